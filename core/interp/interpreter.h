#pragma once

#include <cstdint>

#include "core/base/diagnostic.h"
#include "core/canon/commands.h"
#include "core/interp/program_status.h"

namespace kerf::interp {

// Live machine data the interpreter asked for with a canonical SyncPoint.
struct WorldSnapshot {
    Pose position;  // actual tool-tip position, workpiece coordinates
    bool probeTriggered = false;
    Pose probePosition;
};

enum class RunStatus : uint8_t {
    BudgetUsed,  // more blocks to run; call run() again
    NeedsSync,   // drain motion, then resume() with fresh machine data
    Finished,
    Failed,  // diagnostics() says why
};

// A dialect front end: interprets a loaded program into canonical commands. The interpreter never
// talks to the machine; where a value depends on it, it emits a SyncPoint and waits for resume().
// Called from one thread (the task or a test).
class Interpreter {
public:
    virtual ~Interpreter() = default;

    virtual RunStatus run(canon::Sink& sink, uint64_t blockBudget) = 0;
    virtual void resume(const WorldSnapshot& world) = 0;
    // Check diagnostics of the loaded programs followed by run-time diagnostics.
    virtual const DiagnosticList& diagnostics() const = 0;
    virtual uint64_t blocksExecuted() const = 0;
    // The tool position the interpreter assumes (workpiece coordinates).
    virtual Pose nominalPosition() const = 0;
    // True when the program check (which may run alongside execution) found errors: then the
    // program must be treated as never started and everything it emitted discarded.
    virtual bool checkFailed() const = 0;
    // A copy of the state the HMI status tabs show (program, tool, transformations, parameters,
    // probe). Front ends without one report an empty status.
    virtual ProgramStatus programStatus() const { return {}; }
};

}  // namespace kerf::interp
