#include "core/task/dry_run.h"

#include <algorithm>
#include <optional>

#include "core/canon/path_statistics.h"
#include "core/canon/tee_sink.h"

namespace kerf::task {

namespace {

// Small enough that a cancel is seen within milliseconds.
constexpr uint64_t kBlocksPerSlice = 1u << 16;

bool cancelled(const DryRunOptions& options) {
    return options.cancel != nullptr && options.cancel->load(std::memory_order_relaxed);
}

// Hands every command to the move check until it refuses one, and remembers which.
class JudgedMoves final : public canon::Sink {
public:
    explicit JudgedMoves(MoveCheck& moves) : m_moves(moves) {}
    void consume(const canon::Command& command) override {
        if (m_refusedAt) return;
        if (!m_moves.accept(command)) m_refusedAt = command.location;
    }
    const std::optional<SourceLocation>& refusedAt() const { return m_refusedAt; }

private:
    MoveCheck& m_moves;
    std::optional<SourceLocation> m_refusedAt;
};

}  // namespace

DryRunResult runDry(interp::Interpreter& interpreter, const DryRunOptions& options) {
    canon::PathStatistics position;
    position.setStart(interpreter.nominalPosition());
    canon::TeeSink sinks;
    sinks.add(position);
    std::optional<JudgedMoves> judged;
    if (options.moves != nullptr) {
        options.moves->start(interpreter.nominalPosition());
        sinks.add(judged.emplace(*options.moves));
    }
    auto refused = [&] { return judged && judged->refusedAt(); };
    for (;;) {
        if (cancelled(options)) return {DryRunEnd::Cancelled, {}};
        const uint64_t left =
            options.maxBlocks - std::min(options.maxBlocks, interpreter.blocksExecuted());
        const interp::RunStatus status =
            interpreter.run(sinks, std::min<uint64_t>(kBlocksPerSlice, left));
        // Nothing after a refused command would move: the run ends there, as on the machine.
        if (refused()) return {DryRunEnd::Refused, *judged->refusedAt()};
        if (status == interp::RunStatus::NeedsSync) {
            if (options.atSync && !options.atSync()) return {DryRunEnd::Stopped, {}};
            interp::WorldSnapshot world;
            world.position = position.position();
            world.probeTriggered = true;
            world.probePosition = world.position;
            if (options.moves != nullptr) options.moves->resumeAt(world.position);
            interpreter.resume(world);
            continue;
        }
        if (status != interp::RunStatus::BudgetUsed) return {DryRunEnd::Finished, {}};
        if (interpreter.blocksExecuted() >= options.maxBlocks) return {DryRunEnd::BlockLimit, {}};
    }
}

DiagnosticList moveRefusal(const MoveCheck& moves, const SourceLocation& at,
                           const program::SourceRegistry& sources) {
    DiagnosticList list = moves.refusal();
    const std::string file = at.fileId < sources.size() ? sources.path(at.fileId) : std::string();
    for (Diagnostic& d : list)
        d.file = file;
    return list;
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
    const DryRunResult end = runDry(*program.interpreter, options);
    check.cancelled = end.end == DryRunEnd::Cancelled;
    check.diagnostics = program.diagnostics();
    if (end.end == DryRunEnd::Refused) {
        appendDiagnostics(check.diagnostics,
                          moveRefusal(*options.moves, end.refusedAt, *program.sources));
    }
    if (end.end == DryRunEnd::BlockLimit)
        check.diagnostics.push_back(blockLimitError(request.path.string(), options.maxBlocks));
    return check;
}

}  // namespace kerf::task
