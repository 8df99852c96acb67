#include "core/task/program_sketch.h"

#include <cctype>
#include <variant>

#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::task {

namespace {

constexpr uint32_t kMainProgram = 0;  // SourceRegistry: id 0 is the main program
constexpr uint64_t kBlocksPerSlice = 2000;

Vec2 planar(const Pose& pose) {
    return {pose[Axis::X], pose[Axis::Y]};
}

// Collects the main program's moves in the XY plane; it follows the tool through every move.
class MoveCollector final : public canon::Sink {
public:
    MoveCollector(Pose start, std::vector<SketchMove>& out) : m_at(start), m_out(out) {}

    void consume(const canon::Command& command) override {
        std::visit([&](const auto& body) { take(command.location, body); }, command.body);
    }
    const Pose& position() const { return m_at; }

private:
    void take(const SourceLocation& at, const canon::RapidMove& move) {
        add(at, PlanarSegment::line(planar(m_at), planar(move.target)), true);
        m_at = move.target;
    }
    void take(const SourceLocation& at, const canon::LinearMove& move) {
        add(at, PlanarSegment::line(planar(m_at), planar(move.target)), false);
        m_at = move.target;
    }
    void take(const SourceLocation& at, const canon::ArcMove& move) {
        const PlanarSegment segment =
            move.plane == Plane::XY
                ? PlanarSegment::arc(planar(m_at), {move.center.x(), move.center.y()},
                                     move.sweepRad)
                : PlanarSegment::line(planar(m_at), planar(move.target));
        add(at, segment, false);
        m_at = move.target;
    }
    void take(const SourceLocation& at, const canon::ProbeMove& move) {
        add(at, PlanarSegment::line(planar(m_at), planar(move.target)), false);
        m_at = move.target;
    }
    template <typename Other>
    void take(const SourceLocation&, const Other&) {}

    void add(const SourceLocation& at, const PlanarSegment& segment, bool rapid) {
        if (at.fileId != kMainProgram || (segment.start - segment.end).norm() < 1e-9) return;
        m_out.push_back({at, segment, rapid});
    }

    Pose m_at;
    std::vector<SketchMove>& m_out;
};

}  // namespace

bool mayUseFk(std::string_view text) {
    size_t at = 0;
    while (at < text.size()) {
        size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(at, end - at);
        at = end + 1;
        size_t i = 0;
        while (i < line.size() && (std::isspace(static_cast<unsigned char>(line[i])) ||
                                   std::isdigit(static_cast<unsigned char>(line[i]))))
            ++i;
        if (i + 2 > line.size() || (line[i] != 'F' && line[i] != 'f')) continue;
        const char next = static_cast<char>(std::toupper(static_cast<unsigned char>(line[i + 1])));
        if (next == 'L' || next == 'C' || next == 'P' || next == 'S') return true;
    }
    return false;
}

ProgramSketch sketchProgram(const machine::MachineConfig& machine, const ProgramRequest& request,
                            const std::atomic<bool>* cancel, uint64_t maxBlocks) {
    ProgramSketch sketch;
    ProgramRequest dry = request;
    dry.writeFiles = false;  // checking never writes (FN 16, the TT cycles' TOOL.T ...)
    dry.remanentFile.clear();
    LoadedProgram program = loadProgram(machine, dry);
    sketch.diagnostics = program.diagnostics();
    auto* interpreter = dynamic_cast<klartext::KlartextInterpreter*>(program.interpreter.get());
    if (!program.ready || interpreter == nullptr || !request.text || !mayUseFk(*request.text))
        return sketch;
    const size_t checked = interpreter->diagnostics().size();
    interpreter->traceFk(&sketch.fk);
    MoveCollector moves(interpreter->nominalPosition(), sketch.moves);
    while (interpreter->blocksExecuted() < maxBlocks) {
        if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) {
            sketch.cancelled = true;
            break;
        }
        const interp::RunStatus status = interpreter->run(moves, kBlocksPerSlice);
        if (status == interp::RunStatus::NeedsSync) {
            interp::WorldSnapshot world;
            world.position = moves.position();
            interpreter->resume(world);
            continue;
        }
        if (status != interp::RunStatus::BudgetUsed) break;
    }
    interpreter->traceFk(nullptr);
    // Only the FK solver's findings: the rest of a run's errors belong to the test run.
    const DiagnosticList& all = interpreter->diagnostics();
    for (size_t i = checked; i < all.size(); ++i)
        if (all[i].code == "fk") sketch.diagnostics.push_back(all[i]);
    return sketch;
}

}  // namespace kerf::task
