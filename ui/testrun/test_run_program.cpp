#include "ui/testrun/test_run_program.h"

#include <algorithm>
#include <limits>

#include "core/canon/path_statistics.h"
#include "core/tables/tool_table.h"
#include "core/task/preset_store.h"
#include "core/task/program_loader.h"
#include "graphics/stock/machine_stock_options.h"

namespace kerf::ui {

namespace {

constexpr uint64_t kBlocksPerSlice = 2000;
// Status snapshots block by block up to this many, then one per slice.
constexpr size_t kMaxStatusSnapshots = 100'000;
// How many blocks back the status of a command's own block is looked for.
constexpr long kStatusLookBack = 16;

// Feeds every consumer of the test run from one canonical stream and keeps the stream.
class Recorder final : public canon::Sink {
public:
    Recorder(TestRunProgram& out, task::MachiningClock* clock, graphics::ToolpathOptions toolpath)
        : m_out(out), m_clock(clock), m_toolpath(std::move(toolpath)) {}

    void setStart(const Pose& start) {
        m_statistics.setStart(start);
        m_toolpath.setStart(start);
        if (m_clock != nullptr) m_clock->setStart(start);
    }
    // Commands the check refuses (and every one after) are not recorded.
    void setCheck(task::MoveCheck* check) { m_check = check; }
    void consume(const canon::Command& command) override {
        if (m_check != nullptr && !m_check->accept(command)) {
            if (!m_out.refusedAt) m_out.refusedAt = command.location;
            return;
        }
        m_statistics.consume(command);
        m_out.movesBefore.push_back(static_cast<uint32_t>(m_toolpath.data().moveCount()));
        m_toolpath.consume(command);
        m_out.commands.push_back(command);
        if (m_clock != nullptr) m_clock->consume(command);
    }
    // A sync point: the machine stops there before the program goes on.
    void sync() {
        if (m_clock != nullptr) m_clock->sync();
    }
    // Each command's end in machining time.
    std::vector<double> finish() {
        if (m_clock == nullptr) return std::vector<double>(m_out.commands.size(), 0.0);
        m_clock->finish();
        return m_clock->endTimesS();
    }
    const Pose& position() const { return m_statistics.position(); }
    graphics::ToolpathData takeToolpath() { return m_toolpath.take(); }

private:
    TestRunProgram& m_out;
    task::MachiningClock* m_clock;
    task::MoveCheck* m_check = nullptr;
    canon::PathStatistics m_statistics;
    graphics::ToolpathCollector m_toolpath;
};

Diagnostic testRunError(const std::string& file, const char* text, std::string arg = {}) {
    return Diagnostic::make(Severity::Error, "test-run", file, 0, 0, text, std::move(arg));
}

}  // namespace

size_t TestRunProgram::commandAt(double timeS) const {
    return static_cast<size_t>(std::upper_bound(endTimeS.begin(), endTimeS.end(), timeS) -
                               endTimeS.begin());
}

Vec3 TestRunProgram::toolPositionAt(double timeS) const {
    return placeAt(runPointAt(timeS)).tip;
}

Vec3 TestRunProgram::toolAxisAt(double timeS) const {
    if (!toolpath || toolpath->pointCount() == 0) return Vec3::UnitZ();
    const size_t reached = placeAt(runPointAt(timeS)).pointsDone;
    return toolpath->toolAxisAt(std::min(reached, toolpath->pointCount() - 1));
}

RunPoint TestRunProgram::runPointAt(double timeS) const {
    const size_t index = commandAt(timeS);
    if (index >= commands.size()) return {commands.size(), 0.0};
    const double startS = index > 0 ? endTimeS[index - 1] : 0.0;
    const double durationS = endTimeS[index] - startS;
    return {index, durationS > 0.0 ? std::clamp((timeS - startS) / durationS, 0.0, 1.0) : 1.0};
}

double TestRunProgram::timeAt(const RunPoint& point) const {
    if (point.command >= endTimeS.size()) return machiningTimeS();
    const double startS = point.command > 0 ? endTimeS[point.command - 1] : 0.0;
    return startS + point.fraction * (endTimeS[point.command] - startS);
}

void TestRunProgram::setOverrideTimes() {
    rapidEndTimeS.assign(commands.size(), 0.0);
    feedEndTimeS.assign(commands.size(), 0.0);
    double rapidS = 0.0, feedS = 0.0, startS = 0.0;
    for (size_t i = 0; i < commands.size() && i < endTimeS.size(); ++i) {
        const double durationS = endTimeS[i] - startS;
        startS = endTimeS[i];
        const auto& body = commands[i].body;
        if (std::holds_alternative<canon::RapidMove>(body)) {
            rapidS += durationS;
        } else if (std::holds_alternative<canon::LinearMove>(body) ||
                   std::holds_alternative<canon::ArcMove>(body) ||
                   std::holds_alternative<canon::ProbeMove>(body)) {
            feedS += durationS;
        }
        rapidEndTimeS[i] = rapidS;
        feedEndTimeS[i] = feedS;
    }
}

double TestRunProgram::remainingTimeS(const RunPoint& point, double feedOverride,
                                      double rapidOverride) const {
    if (rapidEndTimeS.size() != endTimeS.size() || endTimeS.empty())
        return std::max(0.0, machiningTimeS() - timeAt(point));
    // A share of the time up to `point`, interpolated inside its command as timeAt() does.
    auto partAt = [&](const std::vector<double>& endS) {
        if (point.command >= endS.size()) return endS.back();
        const double startS = point.command > 0 ? endS[point.command - 1] : 0.0;
        return startS + point.fraction * (endS[point.command] - startS);
    };
    const double rapidLeftS = rapidEndTimeS.back() - partAt(rapidEndTimeS);
    const double feedLeftS = feedEndTimeS.back() - partAt(feedEndTimeS);
    const double otherLeftS =
        std::max(0.0, machiningTimeS() - timeAt(point) - rapidLeftS - feedLeftS);
    auto scaled = [](double seconds, double fraction) {
        if (seconds <= 0.0) return 0.0;
        return fraction > 0.0 ? seconds / fraction : std::numeric_limits<double>::infinity();
    };
    return otherLeftS + scaled(rapidLeftS, rapidOverride) + scaled(feedLeftS, feedOverride);
}

bool TestRunProgram::isMove(size_t command) const {
    if (command >= movesBefore.size() || !toolpath) return false;
    const uint32_t move = movesBefore[command];
    return command + 1 < movesBefore.size() ? movesBefore[command + 1] > move
                                            : toolpath->moveCount() > move;
}

PathPlace TestRunProgram::placeAt(const RunPoint& point) const {
    if (!toolpath || toolpath->pointCount() == 0) return {0, start.xyz()};
    const graphics::ToolpathData& path = *toolpath;
    const PathPlace end{path.pointCount(), path.point(path.pointCount() - 1)};
    if (point.command >= commands.size()) return end;
    const uint32_t move = movesBefore[point.command];
    if (move >= path.moveCount()) return end;
    const auto [begin, stop] = path.pointsOfMove(move);
    const size_t from = begin > 0 ? begin - 1 : 0;
    if (!isMove(point.command) || stop <= begin) return {from + 1, path.point(from)};
    // Points of a move are evenly spaced (lines: one segment; arcs: equal chords).
    const double position =
        std::clamp(point.fraction, 0.0, 1.0) * static_cast<double>(stop - 1 - from);
    const size_t i = from + std::min(static_cast<size_t>(position), stop - 1 - from);
    if (i + 1 >= stop) return {stop, path.point(stop - 1)};
    const double t = position - static_cast<double>(i - from);
    return {i + 1, path.point(i) + (path.point(i + 1) - path.point(i)) * t};
}

const canon::ToolChange* TestRunProgram::toolAt(double timeS) const {
    const canon::ToolChange* tool = nullptr;
    const size_t index = std::min(commandAt(timeS), commands.size());
    for (size_t i = 0; i < index; ++i) {
        if (const auto* change = std::get_if<canon::ToolChange>(&commands[i].body)) tool = change;
    }
    return tool;
}

const TestRunProgram::StatusSnapshot* TestRunProgram::statusAt(double timeS) const {
    return statusOfCommand(commandAt(timeS));
}

const TestRunProgram::StatusSnapshot* TestRunProgram::statusOfCommand(size_t index) const {
    if (statuses.empty()) return nullptr;
    const auto it = std::upper_bound(
        statuses.begin(), statuses.end(), index,
        [](size_t i, const StatusSnapshot& snapshot) { return i < snapshot.commandsEnd; });
    auto found = it != statuses.end() ? it : statuses.end() - 1;
    // Moves may be emitted a few blocks late (the contour look-ahead of radius compensation):
    // the status that belongs to a command is that of the block written on its line.
    if (index < commands.size()) {
        const uint32_t line = commands[index].location.line;
        for (auto back = found; back >= statuses.begin() && found - back < kStatusLookBack;
             --back) {
            if (back->status.line == line) return &*back;
            if (back == statuses.begin()) break;
        }
    }
    return &*found;
}

TestRunProgram interpretForTestRun(const TestRunInput& input, const std::atomic<bool>* cancel) {
    TestRunProgram out;
    // The same loading as a program run on the machine: dialect by file and machine, TOOL.T of
    // the NC root.
    task::ProgramRequest request;
    request.text = input.text;
    request.path = input.path;
    request.ncRoot = input.ncRoot;
    request.dialect = input.dialect;
    request.presetInMachine = input.presetInMachine;
    if (input.machine.kind == machine::MachineKind::Mill && !input.ncRoot.empty()) {
        // As Program run starts: with the basic rotation of row 0 of PRESET.PR.
        request.basicRotationDeg = task::PresetStore(input.ncRoot).basicRotationDeg();
    }
    request.startPosition = input.startPosition;
    task::LoadedProgram program = task::loadProgram(input.machine, request);
    // A machine with rotary tables: the path and the stock on the part the tables turn.
    const std::optional<machine::WorkpieceFrame> frame = machine::WorkpieceFrame::of(
        input.machine, program.streamOrigin.value_or(input.presetInMachine));
    out.stockOptions = graphics::stockOptionsFor(input.machine, program.tools.get(), frame);
    out.diagnostics = program.diagnostics();
    const size_t checkDiagnostics =
        program.interpreter ? program.interpreter->diagnostics().size() : 0;
    std::unique_ptr<interp::Interpreter> interpreter =
        program.ready ? std::move(program.interpreter) : nullptr;
    std::unique_ptr<task::MachiningClock> clock =
        input.clock ? input.clock(input.machine) : nullptr;
    graphics::ToolpathOptions toolpathOptions;
    toolpathOptions.workpieceFrame = frame;
    Recorder recorder(out, clock.get(), std::move(toolpathOptions));
    std::unique_ptr<task::MoveCheck> check;
    if (interpreter && input.checkMoves) {
        check = input.checkMoves(program.streamOrigin.value_or(input.presetInMachine));
        recorder.setCheck(check.get());
    }
    if (interpreter) {
        out.start = interpreter->nominalPosition();
        recorder.setStart(out.start);
        if (check) check->start(out.start);
        for (;;) {
            if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
                out.cancelled = true;
                break;
            }
            const uint64_t slice = out.statuses.size() < kMaxStatusSnapshots ? 1 : kBlocksPerSlice;
            const interp::RunStatus status = interpreter->run(recorder, slice);
            out.statuses.push_back({out.commands.size(), interpreter->programStatus()});
            if (out.refusedAt) break;  // Program run would not go past this block either
            if (status == interp::RunStatus::NeedsSync) {
                interp::WorldSnapshot world;
                world.position = recorder.position();
                if (check) check->resumeAt(world.position);
                recorder.sync();
                interpreter->resume(world);
                continue;
            }
            if (status == interp::RunStatus::Finished) out.ran = true;
            if (status != interp::RunStatus::BudgetUsed) break;
            if (interpreter->blocksExecuted() >= input.maxBlocks) {
                out.diagnostics.push_back(testRunError(
                    input.path.string(),
                    KERF_TR_NOOP("the test run stopped after {1} blocks: endless loop?"),
                    std::to_string(input.maxBlocks)));
                break;
            }
        }
        out.blocks = interpreter->blocksExecuted();
    }
    out.endTimeS =
        out.cancelled ? std::vector<double>(out.commands.size(), 0.0) : recorder.finish();
    out.setOverrideTimes();
    if (interpreter && interpreter->diagnostics().size() > checkDiagnostics) {
        // Run-time diagnostics follow the check's, which were taken at the load already.
        out.diagnostics.insert(
            out.diagnostics.end(),
            interpreter->diagnostics().begin() + static_cast<long>(checkDiagnostics),
            interpreter->diagnostics().end());
    }
    if (out.refusedAt) {
        const uint32_t fileId = out.refusedAt->fileId;
        const std::string file =
            fileId < program.sources->size() ? program.sources->path(fileId) : input.path.string();
        for (Diagnostic d : check->refusal()) {
            d.file = file;
            out.diagnostics.push_back(std::move(d));
        }
    }
    if (hasErrors(out.diagnostics)) out.ran = false;
    auto toolpath = std::make_shared<graphics::ToolpathData>(recorder.takeToolpath());
    out.geometry =
        std::make_shared<graphics::ToolpathGeometry>(graphics::buildToolpathGeometry(*toolpath));
    out.toolpath = std::move(toolpath);
    return out;
}

}  // namespace kerf::ui
