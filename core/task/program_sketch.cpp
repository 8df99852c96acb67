#include "core/task/program_sketch.h"

#include <cctype>
#include <variant>

#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::task {

namespace {

constexpr uint32_t kMainProgram = 0;  // SourceRegistry: id 0 is the main program
constexpr uint64_t kBlocksPerSlice = 2000;

// A move of the main program as it ran, projected once the FK elements' plane is known.
struct RunMove {
    SourceLocation at;
    Pose from;
    Pose to;
    bool rapid = false;
    std::optional<canon::ArcMove> arc;
};

// Collects the main program's moves; it follows the tool through every move.
class MoveCollector final : public canon::Sink {
public:
    explicit MoveCollector(Pose start) : m_at(start) {}

    void consume(const canon::Command& command) override {
        std::visit([&](const auto& body) { take(command.location, body); }, command.body);
    }
    const Pose& position() const { return m_at; }

    // The moves in `plane`'s (first, second) coordinates, as the FK elements are; an arc in
    // another plane is drawn as its chord.
    std::vector<SketchMove> projected(Plane plane) const {
        const PlaneAxes axes = planeAxes(plane);
        auto planar = [&](const Pose& pose) { return Vec2(pose[axes.first], pose[axes.second]); };
        auto planarPoint = [&](const Vec3& p) {
            return Vec2(p[static_cast<int>(axes.first)], p[static_cast<int>(axes.second)]);
        };
        std::vector<SketchMove> out;
        for (const RunMove& m : m_moves) {
            const bool inPlane = m.arc && m.arc->plane == plane;
            const PlanarSegment segment =
                inPlane ? PlanarSegment::arc(planar(m.from), planarPoint(m.arc->center),
                                             m.arc->sweepRad)
                        : PlanarSegment::line(planar(m.from), planar(m.to));
            if ((segment.start - segment.end).norm() < 1e-9 && !inPlane) continue;
            out.push_back({m.at, segment, m.rapid});
        }
        return out;
    }

private:
    void take(const SourceLocation& at, const canon::RapidMove& move) {
        add(at, move.target, true, std::nullopt);
    }
    void take(const SourceLocation& at, const canon::LinearMove& move) {
        add(at, move.target, false, std::nullopt);
    }
    void take(const SourceLocation& at, const canon::ArcMove& move) {
        add(at, move.target, false, move);
    }
    void take(const SourceLocation& at, const canon::ProbeMove& move) {
        add(at, move.target, false, std::nullopt);
    }
    template <typename Other>
    void take(const SourceLocation&, const Other&) {}

    void add(const SourceLocation& at, const Pose& to, bool rapid,
             std::optional<canon::ArcMove> arc) {
        if (at.fileId == kMainProgram) m_moves.push_back({at, m_at, to, rapid, std::move(arc)});
        m_at = to;
    }

    Pose m_at;
    std::vector<RunMove> m_moves;
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
    MoveCollector moves(interpreter->nominalPosition());
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
    sketch.moves = moves.projected(sketch.fk.plane);
    // Only the FK solver's findings: the rest of a run's errors belong to the test run.
    const DiagnosticList& all = interpreter->diagnostics();
    for (size_t i = checked; i < all.size(); ++i)
        if (all[i].code == "fk") sketch.diagnostics.push_back(all[i]);
    return sketch;
}

}  // namespace kerf::task
