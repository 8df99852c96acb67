#include "app/runner/drive_output.h"

#include <chrono>
#include <cmath>

#include "app/runner/can_machine.h"
#include "app/runner/motion_output.h"
#include "app/runner/session.h"
#include "drivers/setup/fault_injection.h"

namespace kerf::app {

namespace {

constexpr const char* kCanSim = "can-sim";
// A fault stops the interpreter within this many blocks (each block's motion is simulated as it
// is interpreted, so the slice bounds the blocks read after the stop).
constexpr uint64_t kBlocksPerSliceWithDrives = 16;

// Rounds to 6 decimals and never writes -0, like the rest of the report.
double clean(double value) {
    double rounded = std::round(value * 1e6) / 1e6;
    return rounded == 0.0 ? 0.0 : rounded;
}

Expected<drivers::CanSimOptions> simOptions(const RunOptions& options) {
    drivers::CanSimOptions sim;
    if (options.canTrace) sim.tracePath = *options.canTrace;
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
    nlohmann::json programmedFinal;
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
    : m_options(options), m_session(session), m_active(options.drives.has_value()) {}

DriveOutput::~DriveOutput() = default;

void DriveOutput::Forward::consume(const canon::Command& command) {
    if (machine) machine->consume(command);
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
    motion::MotionOptions motionOptions;
    motionOptions.workOffset = m_session.workOffset.values;
    auto machine =
        CanMachine::create(m_session.machine, std::move(sim).value(), start.values, motionOptions);
    if (!machine) {
        Diagnostic d = machine.error();
        d.severity = Severity::Error;
        problems.push_back(d);
        m_bootFailed = true;
        return;
    }
    m_machine = std::move(machine).value();
    m_forward.machine = m_machine.get();
}

uint64_t DriveOutput::blocksPerSlice(uint64_t withoutDrives) const {
    return m_active ? kBlocksPerSliceWithDrives : withoutDrives;
}

bool DriveOutput::stopped() const {
    return m_bootFailed || (m_machine && (m_machine->stopped() || m_machine->refused()));
}

interp::WorldSnapshot DriveOutput::drain() {
    return m_machine ? m_machine->drain() : interp::WorldSnapshot{};
}

void DriveOutput::finish(DiagnosticList& problems) {
    if (!m_machine) return;
    m_result = std::make_unique<Result>();
    m_result->run = m_machine->finish();
    const SourceLocation& at = m_result->run.stoppedAt;
    for (Diagnostic d : m_result->run.diagnostics) {
        if (d.file.empty() && d.line > 0) {
            // The planner names the block it refused.
            d.file = m_options.program.string();
        } else if (d.file.empty() && at.line > 0) {
            // Where the program was when the drives stopped.
            d.file = m_session.sources.displayName(at.fileId);
            d.line = at.line;
            d.column = at.column;
        }
        problems.push_back(std::move(d));
    }
    m_forward.machine = nullptr;
    m_machine.reset();
}

void DriveOutput::addToReport(nlohmann::json& report, bool xInDiameter) const {
    if (!m_active) return;
    nlohmann::json drives;
    drives["kind"] = kCanSim;
    drives["booted"] = m_result != nullptr;
    if (m_result) {
        const CanRunResult& run = m_result->run;
        drives["programmed_final_position"] = report["final_position"];
        nlohmann::json position = nlohmann::json::object();
        for (char letter : m_session.machine.enabledAxisLetters()) {
            auto axis = axisFromLetter(letter);
            if (!axis) continue;
            double value = run.finalPosition[static_cast<size_t>(axisIndex(*axis))];
            if (letter == 'X' && xInDiameter) value *= 2.0;
            position[std::string(1, letter)] = clean(value);
        }
        report["final_position"] = position;
        drives["stopped"] = run.stopped;
        drives["refused"] = run.refused;
        drives["simulated_time_s"] = clean(run.durationS);
        drives["max_following_error_mm"] = clean(run.maxFollowingErrorMm);
        drives["bus_load_percent"] = std::round(run.busLoad * 1000.0) / 10.0;
    }
    if (m_options.canTrace) drives["can_trace"] = m_options.canTrace->string();
    report["drives"] = drives;
}

}  // namespace kerf::app
