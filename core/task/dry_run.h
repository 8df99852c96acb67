#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

#include "core/base/diagnostic.h"
#include "core/interp/interpreter.h"
#include "core/machine/machine_config.h"
#include "core/task/move_check.h"
#include "core/task/program_loader.h"

// The check that runs the program: after the static check, the program runs to its end as
// `kerf run` runs it without motion (the machine stands where the program put it; a probe touches
// at the end of its move), writing no file. What stops the run on the same data and tables — a
// division by zero, a tool the table lacks, a cycle the tool cannot machine, a called program
// that is missing — is then the check's error at its block. `kerf check` and the HMI's "Check
// program" run this same code (docs/headless.md, "What the check runs"). Given a MoveCheck, the
// run also judges every command as the machine would before it moves (soft limits, an axis the
// machine lacks, the planner's rules), as `kerf run --motion` does. Qt-free; any thread, one
// interpreter per call.
namespace kerf::task {

// About two seconds of a tight loop; `kerf check --max-blocks` changes it (the HMI keeps it).
inline constexpr uint64_t kDefaultMaxBlocks = 10'000'000;

enum class DryRunEnd { Finished, BlockLimit, Stopped, Cancelled, Refused };

struct DryRunOptions {
    uint64_t maxBlocks = kDefaultMaxBlocks;
    const std::atomic<bool>* cancel = nullptr;  // polled between slices of blocks
    // Called at each sync point before the machine's answer; false ends the run (a FAGOR user
    // screen's operator who has no more input). Unset: every sync point is answered.
    std::function<bool()> atSync;
    // Judges every command before it would move; the run ends at the first one it refuses.
    // Unset: what the machine would do is not judged.
    MoveCheck* moves = nullptr;
};

struct DryRunResult {
    DryRunEnd end = DryRunEnd::Finished;
    SourceLocation refusedAt;  // Refused: the command `moves` refused
};

// Runs the loaded, checked interpreter to its end (Finished also when it failed: its
// diagnostics() say why).
DryRunResult runDry(interp::Interpreter& interpreter, const DryRunOptions& options);

// Why `moves` refused the command at `at` (the refusal of a Refused run), in the file of `at`.
DiagnosticList moveRefusal(const MoveCheck& moves, const SourceLocation& at,
                           const program::SourceRegistry& sources);

// Who meets the block limit decides what the message says about raising it: `kerf check` and
// `kerf run` name their option; the HMI's Check program has no such setting, so its message only
// says how many blocks ran.
enum class BlockLimitSource { Hmi, CommandLine };

// "the program check stopped after N blocks: endless loop?" about `file` (the command line's:
// "stopped after N blocks: endless loop? (--max-blocks)").
Diagnostic blockLimitError(const std::string& file, uint64_t maxBlocks,
                           BlockLimitSource source = BlockLimitSource::Hmi);

struct RunCheck {
    DiagnosticList diagnostics;  // the static check's, then the run's
    bool cancelled = false;
};

// Loads the program without writing any file and, when it loaded without errors, runs it dry.
RunCheck checkByRunning(const machine::MachineConfig& machine, ProgramRequest request,
                        const DryRunOptions& options = {});

}  // namespace kerf::task
