#include "app/runner/motion_output.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "app/runner/session.h"
#include "app/runner/soft_limit_gate.h"
#include "motion/kinematics/machine_model.h"
#include "motion/sim/simulated_machine.h"

namespace kerf::app {

namespace {

double clean(double value) {
    const double rounded = std::round(value * 1e6) / 1e6;
    return rounded == 0.0 ? 0.0 : rounded;
}

motion::MotionOptions motionOptions(const Session& session) {
    motion::MotionOptions motion;
    motion.workOffset = session.workOffset.values;
    return motion;
}

}  // namespace

std::optional<Pose> parseWorkOffset(const std::string& text) {
    Pose offset;
    size_t at = 0;
    while (at < text.size()) {
        const size_t end = std::min(text.find(',', at), text.size());
        const std::string item = text.substr(at, end - at);
        const auto axis = item.empty() ? std::nullopt : axisFromLetter(item[0]);
        if (!axis || item.size() < 2) return std::nullopt;
        size_t used = 0;
        try {
            offset[*axis] = std::stod(item.substr(1), &used);
        } catch (const std::exception&) {
            return std::nullopt;
        }
        if (used != item.size() - 1 || !std::isfinite(offset[*axis])) return std::nullopt;
        at = end + 1;
    }
    if (text.empty() || text.back() == ',') return std::nullopt;
    return offset;
}

struct MotionOutput::State final : canon::Sink {
    State(const RunOptions& runOptions, const Session& s)
        : options(runOptions),
          session(s),
          model(motion::makeMachineModel(s.machine, motionOptions(s))),
          gate(model) {}

    void consume(const canon::Command& command) override {
        gate.consume(command);
        if (!gate.refused() && std::holds_alternative<canon::ProbeMove>(command.body))
            ++probesSinceDrain;
    }

    std::string fileOf(uint32_t fileId) const {
        return fileId < session.sources.size() ? session.sources.path(fileId)
                                               : options.program.string();
    }

    const RunOptions& options;
    const Session& session;
    motion::MachineModel model;
    SoftLimitGate gate;  // soft limits and the planner's rules, before anything moves
    std::unique_ptr<motion::SimulatedMachine> machine;
    double startS = 0.0;  // simulated time when the program started (the drives enabled)
    std::optional<motion::MotionReport> report;
    // The probe results the program waited for (one per sync after probe moves).
    struct ProbeResult {
        bool triggered = false;
        Pose position;  // latched tool tip, workpiece coordinates
    };
    std::vector<ProbeResult> probes;
    int probesSinceDrain = 0;
};

MotionOutput::MotionOutput(const RunOptions& options, const Session& session) {
    if (options.motion || options.samples) m_state = std::make_unique<State>(options, session);
}

MotionOutput::~MotionOutput() = default;

canon::Sink& MotionOutput::sink() {
    return *m_state;
}

void MotionOutput::setStart(const Pose& start) {
    if (!m_state) return;
    State& s = *m_state;
    motion::SimulationOptions simulation;
    simulation.motion = motionOptions(s.session);
    simulation.startPosition = start.values;
    if (s.options.samples) simulation.samplesCsvPath = s.options.samples->string();
    if (s.options.emergencyStopAtS) simulation.emergencyStopAtS = *s.options.emergencyStopAtS;
    s.machine = std::make_unique<motion::SimulatedMachine>(s.session.machine, simulation);
    s.startS = s.machine->timeS();
    s.gate.start(start.values, *s.machine);
}

bool MotionOutput::refused() const {
    return m_state && m_state->gate.refused();
}

bool MotionOutput::halted() const {
    return m_state && m_state->machine && m_state->machine->halted();
}

interp::WorldSnapshot MotionOutput::drain() {
    interp::WorldSnapshot world;
    if (!m_state || !m_state->machine) return world;
    State& s = *m_state;
    if (s.gate.refused()) {
        world.position.values = s.gate.position();
        return world;
    }
    s.gate.release();
    world = s.machine->drain();
    if (s.probesSinceDrain > 0) {
        s.probes.push_back({world.probeTriggered, world.probePosition});
        s.probesSinceDrain = 0;
    }
    s.gate.resumeAt(world.position.values);
    return world;
}

void MotionOutput::finish(bool programRan, DiagnosticList& problems) {
    if (!m_state || !m_state->machine) return;
    State& s = *m_state;
    if (s.gate.refused()) {
        const bool atMachineOrigin = s.session.workOffset.values == Pose{}.values;
        DiagnosticList refusal =
            s.gate.refusal(s.fileOf(s.gate.refusedAt()->fileId), atMachineOrigin);
        problems.insert(problems.end(), refusal.begin(), refusal.end());
    } else if (programRan) {
        s.gate.release();
        s.machine->drain();
    }
    s.report = s.machine->report();
    for (Diagnostic d : s.report->diagnostics) {
        if (d.file.empty()) d.file = s.options.program.string();
        problems.push_back(std::move(d));
    }
}

double MotionOutput::machiningTimeS() const {
    if (!m_state || !m_state->report) return 0.0;
    return m_state->report->durationS - m_state->startS;
}

void MotionOutput::addToReport(nlohmann::json& report, bool xInDiameter) const {
    if (!m_state || !m_state->report) return;
    const State& s = *m_state;
    const motion::MotionReport& r = *s.report;
    nlohmann::json motion;
    motion["refused"] = s.gate.refused() || r.refused;
    motion["duration_s"] = clean(r.durationS);
    motion["feed_time_s"] = clean(r.feedTimeS);
    motion["max_path_deviation_mm"] = clean(r.maxPathDeviationMm);
    motion["max_following_error_mm"] = clean(r.maxFollowingErrorMm);
    motion["servo_cycles"] = r.cycles;
    motion["moves"] = r.programmedMoves;
    nlohmann::json axes = nlohmann::json::object();
    for (const motion::AxisReport& axis : r.axes) {
        axes[std::string(1, axis.letter)] = {{"max_velocity", clean(axis.maxVelocity)},
                                             {"max_accel", clean(axis.maxAccel)},
                                             {"max_jerk", clean(axis.maxJerk)}};
    }
    motion["axes"] = axes;
    nlohmann::json position = nlohmann::json::object();
    for (char letter : s.session.machine.enabledAxisLetters()) {
        const auto axis = axisFromLetter(letter);
        if (!axis) continue;
        double value = r.finalPosition[static_cast<size_t>(axisIndex(*axis))];
        if (letter == 'X' && xInDiameter) value *= 2.0;
        position[std::string(1, letter)] = clean(value);
    }
    motion["final_position"] = position;
    nlohmann::json probes = nlohmann::json::array();
    for (const State::ProbeResult& probe : s.probes) {
        nlohmann::json entry = {{"triggered", probe.triggered}};
        if (probe.triggered) {
            nlohmann::json latched = nlohmann::json::object();
            for (char letter : s.session.machine.enabledAxisLetters()) {
                const auto axis = axisFromLetter(letter);
                if (!axis) continue;
                double value = probe.position[*axis];
                if (letter == 'X' && xInDiameter) value *= 2.0;
                latched[std::string(1, letter)] = clean(value);
            }
            entry["position"] = latched;
        }
        probes.push_back(entry);
    }
    motion["probes"] = probes;
    if (s.options.samples) motion["samples"] = s.options.samples->string();
    report["motion"] = motion;
}

}  // namespace kerf::app
