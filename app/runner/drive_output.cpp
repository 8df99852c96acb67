#include "app/runner/drive_output.h"

#include <cmath>

#include "app/runner/can_machine.h"
#include "app/runner/motion_output.h"
#include "app/runner/session.h"
#include "app/runner/soft_limit_gate.h"
#include "drivers/setup/fault_injection.h"
#include "motion/kinematics/machine_model.h"

namespace kerf::app {

namespace {

constexpr const char* kCanSim = "can-sim";
// A fault stops the interpreter within this many blocks once held commands were released (a
// long program releases them before its end; each block's motion is simulated as it arrives).
constexpr uint64_t kBlocksPerSliceWithDrives = 16;

// Rounds to 6 decimals and never writes -0, like the rest of the report.
double clean(double value) {
    double rounded = std::round(value * 1e6) / 1e6;
    return rounded == 0.0 ? 0.0 : rounded;
}

Expected<drivers::CanSimOptions> simOptions(const RunOptions& options) {
    drivers::CanSimOptions sim;
    if (options.canTrace) sim.tracePath = *options.canTrace;
    sim.maxSimulatedS = options.maxDriveTimeS;
    for (const std::string& spec : options.injectFaults) {
        auto fault = drivers::parseFaultInjection(spec);
        if (!fault) return fault.error();
        sim.faults.push_back(*fault);
    }
    return sim;
}

}  // namespace

struct DriveOutput::Result {
    CanRunResult run;
};

// The check before anything moves, with the machine model it plans on.
struct DriveOutput::Checked {
    explicit Checked(const Session& session)
        : model(motion::makeMachineModel(session.machine, workOffsetOf(session))), gate(model) {}
    static motion::MotionOptions workOffsetOf(const Session& session) {
        motion::MotionOptions options;
        options.workOffset = session.workOffset.values;
        return options;
    }
    motion::MachineModel model;
    SoftLimitGate gate;
};

std::optional<std::string> checkDriveOptions(const RunOptions& options) {
    if (!options.drives) {
        if (options.canTrace) return "--can-trace needs --drives can-sim";
        if (!options.injectFaults.empty()) return "--inject-fault needs --drives can-sim";
        return std::nullopt;
    }
    if (*options.drives != kCanSim) return "--drives must be can-sim";
    for (const std::string& spec : options.injectFaults) {
        auto fault = drivers::parseFaultInjection(spec);
        if (!fault) return fault.error().message();
    }
    return std::nullopt;
}

DriveOutput::DriveOutput(const RunOptions& options, const Session& session)
    : m_options(options), m_session(session), m_active(options.drives.has_value()) {
    if (m_active) m_checked = std::make_unique<Checked>(session);
}

DriveOutput::~DriveOutput() = default;

canon::Sink& DriveOutput::sink() {
    return m_checked->gate;
}

std::string DriveOutput::fileOf(uint32_t fileId) const {
    return fileId < m_session.sources().size() ? m_session.sources().path(fileId)
                                               : m_options.program.string();
}

void DriveOutput::setStart(const Pose& start, DiagnosticList& problems) {
    if (!m_active) return;
    auto sim = simOptions(m_options);
    if (!sim) {
        problems.push_back(sim.error());
        m_bootFailed = true;
        return;
    }
    // Where the workpiece lies on the machine, as for --motion.
    auto machine = CanMachine::create(m_session.machine, std::move(sim).value(), start.values,
                                      Checked::workOffsetOf(m_session));
    if (!machine) {
        Diagnostic d = machine.error();
        d.severity = Severity::Error;
        problems.push_back(d);
        m_bootFailed = true;
        return;
    }
    m_machine = std::move(machine).value();
    m_checked->gate.start(start.values, *m_machine);
}

uint64_t DriveOutput::blocksPerSlice(uint64_t withoutDrives) const {
    return m_active ? kBlocksPerSliceWithDrives : withoutDrives;
}

bool DriveOutput::stopped() const {
    return m_bootFailed || (m_checked && m_checked->gate.refused()) ||
           (m_machine && (m_machine->stopped() || m_machine->refused()));
}

interp::WorldSnapshot DriveOutput::drain() {
    interp::WorldSnapshot world;
    if (!m_machine) return world;
    SoftLimitGate& gate = m_checked->gate;
    if (gate.refused()) {
        world.position.values = gate.position();
        return world;
    }
    gate.release();
    world = m_machine->drain();
    gate.resumeAt(world.position.values);
    return world;
}

void DriveOutput::finish(bool programRan, DiagnosticList& problems) {
    if (!m_machine) return;
    SoftLimitGate& gate = m_checked->gate;
    // With --motion as well, motion reports the same refusal.
    if (gate.refused() && !m_options.motion && !m_options.samples) {
        const bool atMachineOrigin = m_session.workOffset.values == Pose{}.values;
        DiagnosticList refusal = gate.refusal(fileOf(gate.refusedAt()->fileId), atMachineOrigin);
        problems.insert(problems.end(), refusal.begin(), refusal.end());
    }
    if (programRan) gate.release();
    m_result = std::make_unique<Result>();
    m_result->run = m_machine->finish();
    const SourceLocation& at = m_result->run.stoppedAt;
    for (Diagnostic d : m_result->run.diagnostics) {
        if (d.file.empty() && d.line > 0) {
            // The planner names the block it refused.
            d.file = m_options.program.string();
        } else if (d.file.empty() && at.line > 0) {
            // Where the program was when the drives stopped.
            d.file = m_session.sources().displayName(at.fileId);
            d.line = at.line;
            d.column = at.column;
        }
        problems.push_back(std::move(d));
    }
    m_machine.reset();
}

namespace {

nlohmann::json tipJson(const motion::AxisVector& tip, const machine::MachineConfig& machine,
                       bool xInDiameter) {
    nlohmann::json position = nlohmann::json::object();
    for (char letter : machine.enabledAxisLetters()) {
        auto axis = axisFromLetter(letter);
        if (!axis) continue;
        double value = tip[static_cast<size_t>(axisIndex(*axis))];
        if (letter == 'X' && xInDiameter) value *= 2.0;
        position[std::string(1, letter)] = clean(value);
    }
    return position;
}

const char* standstillName(drivers::cia402::Standstill standstill) {
    switch (standstill) {
        case drivers::cia402::Standstill::AtRest:
            return "at rest";
        case drivers::cia402::Standstill::Moving:
            return "moving";
        case drivers::cia402::Standstill::Unknown:
            return "unknown";
    }
    return "?";
}

// Where the quick stop went out, where every drive came to rest and how far it went.
nlohmann::json stopJson(const StopOutcome& stop, const motion::AxisVector& rest,
                        const machine::MachineConfig& machine, bool xInDiameter) {
    nlohmann::json json;
    json["at_s"] = clean(stop.stoppedS);
    json["all_at_rest"] = stop.allAtRest();
    json["rest_after_s"] = clean(stop.restS);
    json["limit_s"] = clean(stop.limitS);
    json["position_at_stop"] = tipJson(stop.tipAtStop, machine, xInDiameter);
    double squared = 0.0;
    for (size_t i = 0; i < rest.size(); ++i) {
        double d = rest[i] - stop.tipAtStop[i];
        squared += d * d;
    }
    json["stopping_distance_mm"] = clean(std::sqrt(squared));
    nlohmann::json drives = nlohmann::json::object();
    for (const DriveRest& d : stop.drives) {
        drives[std::string(1, d.letter)] = {{"state", standstillName(d.standstill)},
                                            {"travel", clean(std::fabs(d.atRest - d.atStop))}};
    }
    json["drives"] = drives;
    return json;
}

}  // namespace

void DriveOutput::addToReport(nlohmann::json& report, bool xInDiameter) const {
    if (!m_active) return;
    nlohmann::json drives;
    drives["kind"] = kCanSim;
    drives["booted"] = m_result != nullptr;
    if (m_result) {
        const CanRunResult& run = m_result->run;
        drives["programmed_final_position"] = report["final_position"];
        report["final_position"] = tipJson(run.finalPosition, m_session.machine, xInDiameter);
        drives["stopped"] = run.stopped;
        drives["refused"] = run.refused || m_checked->gate.refused();
        drives["time_limit"] = run.timeLimit;
        if (run.stop)
            drives["stop"] = stopJson(*run.stop, run.finalPosition, m_session.machine, xInDiameter);
        drives["simulated_time_s"] = clean(run.durationS);
        drives["max_following_error_mm"] = clean(run.maxFollowingErrorMm);
        drives["bus_load_percent"] = std::round(run.busLoad * 1000.0) / 10.0;
    }
    if (m_options.canTrace) drives["can_trace"] = m_options.canTrace->string();
    report["drives"] = drives;
}

}  // namespace kerf::app
