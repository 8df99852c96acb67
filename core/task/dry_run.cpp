#include "core/task/dry_run.h"

#include <algorithm>

#include "core/canon/path_statistics.h"

namespace kerf::task {

namespace {

// Small enough that a cancel is seen within milliseconds.
constexpr uint64_t kBlocksPerSlice = 1u << 16;

bool cancelled(const DryRunOptions& options) {
    return options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed);
}

}  // namespace

DryRunEnd runDry(interp::Interpreter& interpreter, const DryRunOptions& options) {
    canon::PathStatistics position;
    position.setStart(interpreter.nominalPosition());
    for (;;) {
        if (cancelled(options)) return DryRunEnd::Cancelled;
        const uint64_t left =
            options.maxBlocks - std::min(options.maxBlocks, interpreter.blocksExecuted());
        const interp::RunStatus status =
            interpreter.run(position, std::min<uint64_t>(kBlocksPerSlice, left));
        if (status == interp::RunStatus::NeedsSync) {
            if (options.atSync && !options.atSync()) return DryRunEnd::Stopped;
            interp::WorldSnapshot world;
            world.position = position.position();
            world.probeTriggered = true;
            world.probePosition = world.position;
            interpreter.resume(world);
            continue;
        }
        if (status != interp::RunStatus::BudgetUsed) return DryRunEnd::Finished;
        if (interpreter.blocksExecuted() >= options.maxBlocks) return DryRunEnd::BlockLimit;
    }
}

Diagnostic blockLimitError(const std::string& file, uint64_t maxBlocks, BlockLimitSource source) {
    const char* text =
        source == BlockLimitSource::CommandLine
            ? KERF_TR_NOOP("stopped after {1} blocks: endless loop? (--max-blocks)")
            : KERF_TR_NOOP("the program check stopped after {1} blocks: endless loop?");
    return Diagnostic::make(Severity::Error, "block-limit", file, 0, 0, text,
                            std::to_string(maxBlocks));
}

RunCheck checkByRunning(const machine::MachineConfig& machine, ProgramRequest request,
                        const DryRunOptions& options) {
    request.writeFiles = false;
    LoadedProgram program = loadProgram(machine, request);
    RunCheck check;
    if (!program.ready || !program.interpreter) {
        check.diagnostics = program.diagnostics();
        return check;
    }
    const DryRunEnd end = runDry(*program.interpreter, options);
    check.cancelled = end == DryRunEnd::Cancelled;
    check.diagnostics = program.diagnostics();
    if (end == DryRunEnd::BlockLimit)
        check.diagnostics.push_back(blockLimitError(request.path.string(), options.maxBlocks));
    return check;
}

}  // namespace kerf::task
