#include "motion/sim/simulated_machine.h"

#include <cmath>

#include "core/base/fixed_format.h"
#include "motion/planner/planner.h"
#include "motion/rt/servo_cycle.h"
#include "motion/sim/probe_workpiece.h"

namespace kerf::motion {

struct SimulatedMachine::Impl {
    Impl(const machine::MachineConfig& config, SimulationOptions opts)
        : options(std::move(opts)),
          model(makeMachineModel(config, options.motion)),
          drives(model, options.drives),
          items(std::make_unique<ItemRing>()),
          servo(model, drives, *items, commands, events),
          planner(model),
          recorder(model) {
        std::array<double, kMaxJoints> joints{};
        for (int j = 0; j < model.jointCount; ++j) {
            int axis = model.jointAxis[static_cast<size_t>(j)];
            if (axis >= 0) {
                joints[static_cast<size_t>(j)] = jointFromAxis(
                    model, axis, options.startPosition[static_cast<size_t>(axis)], 0.0);
            }
        }
        drives.setTruePositions(joints);
        if (!options.probeSurface) {
            options.probeSurface = probeWorkpiece(config, options.motion.workOffset);
        }
        // The surface the current probe move carries, else the machine file's box.
        drives.setProbeSurface([this](const std::array<double, kMaxJoints>& j) {
            const AxisVector tip = tipOf(j);
            if (probeTarget) return probeTarget->touches(Vec3(tip[0], tip[1], tip[2]));
            return options.probeSurface && options.probeSurface(tip);
        });
        if (!options.samplesCsvPath.empty() && !recorder.writeCsv(options.samplesCsvPath)) {
            Diagnostic d;
            d.code = "motion.samples-file";
            d.messageTemplate = KERF_TR_NOOP("Cannot write the samples file {1}.");
            d.args = {options.samplesCsvPath};
            diagnostics.push_back(d);
        }
        planner.setPosition(options.startPosition);
        servo.start();
        // Let the drives enable before the program starts.
        for (int i = 0; i < options.drives.enableCycles + 2; ++i)
            cycle();
        startTimeS = servo.status().timeS;
        if (options.emergencyStopAtS >= 0.0)
            emergencyStopTimeS = startTimeS + options.emergencyStopAtS;
    }

    AxisVector tipOf(const std::array<double, kMaxJoints>& joints) const {
        AxisVector tip{};
        for (int j = 0; j < model.jointCount; ++j) {
            int axis = model.jointAxis[static_cast<size_t>(j)];
            if (axis >= 0) {
                tip[static_cast<size_t>(axis)] = axisFromJoint(
                    model, axis, joints[static_cast<size_t>(j)], planner.toolLength());
            }
        }
        return tip;
    }

    void cycle() {
        if (emergencyStopTimeS >= 0.0 && servo.status().timeS >= emergencyStopTimeS - 1e-9)
            drives.setEmergencyStopPressed(true);
        servo.cycle();
        drives.advance(model.periodS);
        const MotionStatus& status = servo.status();
        Sample sample;
        sample.timeS = status.timeS;
        sample.tip = servo.setpoint();
        for (int j = 0; j < model.jointCount; ++j) {
            int axis = model.jointAxis[static_cast<size_t>(j)];
            if (axis >= 0) {
                sample.joints[static_cast<size_t>(axis)] =
                    servo.jointSetpoints()[static_cast<size_t>(j)].position;
            }
        }
        sample.spindleDeg = servo.spindleSetpointDeg();
        sample.pathVelocity = status.pathVelocity;
        sample.onFeedMove = servo.onFeedMove();
        sample.moveIndex = servo.currentMove();
        sample.firstMoveIndex = servo.currentFirstMove();
        // After an emergency stop or a fault the drives brake on their own ramps: the setpoints
        // follow them and are no longer the planned motion the report measures.
        if (options.measure && !halted()) recorder.record(sample);
        if (options.onSample) options.onSample(sample, status);
        handleEvents();
    }

    void handleEvents() {
        while (!events.empty()) {
            MotionEvent e = events.front();
            events.pop();
            switch (e.kind) {
                case MotionEventKind::ProbeTriggered:
                    world.probeTriggered = true;
                    world.probePosition.values = e.position;
                    break;
                case MotionEventKind::ProbeMissed:
                    world.probeTriggered = false;
                    break;
                case MotionEventKind::ProgramStopped:
                    if (options.autoCycleStart) commands.push({OperatorCommandKind::CycleStart});
                    break;
                case MotionEventKind::Error:
                case MotionEventKind::Fault: {
                    Diagnostic d;
                    d.code =
                        e.kind == MotionEventKind::Fault ? "motion.drive-fault" : "motion.error";
                    d.messageTemplate = KERF_TR_NOOP("Motion error {1} at line {2}.");
                    d.args = {std::to_string(static_cast<int>(e.value)),
                              std::to_string(e.source.line)};
                    d.line = e.source.line;
                    d.severity = Severity::Error;
                    diagnostics.push_back(d);
                    break;
                }
                case MotionEventKind::Aborted:
                    if (servo.status().emergencyStopOpen) {
                        Diagnostic d;
                        d.code = "motion.emergency-stop";
                        d.messageTemplate = KERF_TR_NOOP(
                            "Emergency stop at {1} s after the start (the button was pressed): "
                            "every axis and the spindle were stopped and the program was aborted.");
                        d.args = {formatFixed(e.timeS - startTimeS, 3)};
                        d.line = e.source.line;
                        d.column = 1;
                        d.severity = Severity::Error;
                        diagnostics.push_back(d);
                    }
                    break;
                default:
                    break;
            }
        }
    }

    bool halted() const {
        const MotionMode mode = servo.status().mode;
        return timeLimitHit || mode == MotionMode::EmergencyStop || mode == MotionMode::Fault;
    }

    void pump() {
        while (auto item = planner.next()) {
            // A halted servo cycle takes nothing from the ring: what is planned is dropped.
            while (items->full() && !halted())
                cycle();
            if (halted()) return;
            items->push(*item);
        }
    }

    bool idle() const {
        const MotionStatus& s = servo.status();
        return items->empty() && (s.mode == MotionMode::Idle || s.mode == MotionMode::Fault ||
                                  s.mode == MotionMode::EmergencyStop);
    }

    bool inPosition() const {
        const MotionStatus& s = servo.status();
        for (size_t i = 0; i < s.actualPosition.size(); ++i) {
            if (std::fabs(s.actualPosition[i] - s.commandedPosition[i]) > 1e-7) return false;
        }
        return true;
    }

    void runToIdle() {
        planner.flush();
        pump();
        const double limit = startTimeS + options.maxSimulatedS;
        int settle = 0;
        for (;;) {
            if (idle()) {
                // Let the smoothing filter bring the setpoints to the end point and the drives
                // follow them there.
                if (++settle > model.filterTaps + 1 && inPosition()) return;
            } else {
                settle = 0;
            }
            if (servo.status().timeS >= limit) break;
            cycle();
        }
        endAtTimeLimit();
    }

    // The motion did not end within the simulated-time limit: the run stops here and says so
    // (the report would otherwise show a program that ended in the middle of its path).
    void endAtTimeLimit() {
        if (timeLimitHit) return;
        timeLimitHit = true;
        Diagnostic d;
        d.code = "motion.time-limit";
        d.messageTemplate = KERF_TR_NOOP(
            "The simulation reached its limit of {1} s of simulated time before the program's "
            "motion ended: the run stops here.");
        d.args = {formatFixed(options.maxSimulatedS, 0)};
        d.line = servo.status().source.line;
        d.column = 1;
        d.severity = Severity::Error;
        diagnostics.push_back(d);
    }

    SimulationOptions options;
    MachineModel model;
    SimDriveSet drives;
    std::unique_ptr<ItemRing> items;
    CommandRing commands;
    EventRing events;
    ServoCycle servo;
    Planner planner;
    MotionRecorder recorder;
    interp::WorldSnapshot world;
    // What the probe touches on the current probe move (canon::ProbeMove::surface).
    std::shared_ptr<const canon::ProbeSurface> probeTarget;
    DiagnosticList diagnostics;
    double startTimeS = 0.0;           // the drives enabled: the program may start
    double emergencyStopTimeS = -1.0;  // simulated time of the button press; negative: never
    bool timeLimitHit = false;         // maxSimulatedS ran out before the motion ended
};

SimulatedMachine::SimulatedMachine(const machine::MachineConfig& config, SimulationOptions options)
    : m_impl(std::make_unique<Impl>(config, std::move(options))) {}

SimulatedMachine::~SimulatedMachine() = default;

void SimulatedMachine::consume(const canon::Command& command) {
    Impl& m = *m_impl;
    if (m.planner.refused() || m.halted()) return;
    if (const auto* probe = std::get_if<canon::ProbeMove>(&command.body)) {
        const auto event =
            probe->untilRelease ? SimDriveSet::ProbeEvent::Release : SimDriveSet::ProbeEvent::Touch;
        if (event != m.drives.probeEvent() || probe->surface != m.probeTarget) {
            // The drives arm for the event when the move starts, and test the surface while it
            // runs: finish what is queued first.
            m.runToIdle();
            m.drives.setProbeEvent(event);
            m.probeTarget = probe->surface;
        }
    }
    if (m.planner.needsPosition()) {
        // A probe move ended where the probe stopped it: plan on from there.
        m.runToIdle();
        m.planner.setPosition(m.servo.status().actualPosition);
    }
    uint32_t before = m.planner.acceptedMoves();
    m.planner.add(command);
    if (m.planner.acceptedMoves() != before) {
        m.recorder.addProgrammedMove(m.planner.acceptedMoves(), m.planner.lastMoveGeometry());
    }
    m.pump();
}

interp::WorldSnapshot SimulatedMachine::drain() {
    Impl& m = *m_impl;
    m.runToIdle();
    if (m.planner.needsPosition()) m.planner.setPosition(m.servo.status().actualPosition);
    m.world.position.values = m.servo.status().actualPosition;
    return m.world;
}

MotionReport SimulatedMachine::report() const {
    const Impl& m = *m_impl;
    MotionReport r;
    r.durationS = m.servo.status().timeS;
    r.feedTimeS = m.recorder.feedTimeS();
    r.maxPathDeviationMm = m.recorder.maxPathDeviation();
    r.maxFollowingErrorMm = m.servo.status().maxFollowingError;
    for (size_t i = 0; i < m.model.axes.size(); ++i) {
        if (!m.model.axes[i].enabled) continue;
        const AxisExtremes& e = m.recorder.axis(static_cast<int>(i));
        r.axes.push_back({axisLetter(static_cast<Axis>(i)), e.maxVelocity, e.maxAccel, e.maxJerk});
    }
    r.finalPosition = m.servo.status().actualPosition;
    r.cycles = m.servo.status().cycle;
    r.programmedMoves = m.planner.acceptedMoves();
    r.refused = m.planner.refused();
    r.diagnostics = m.planner.diagnostics();
    r.diagnostics.insert(r.diagnostics.end(), m.diagnostics.begin(), m.diagnostics.end());
    return r;
}

void SimulatedMachine::command(const OperatorCommand& command) {
    m_impl->commands.push(command);
}

void SimulatedMachine::runFor(double seconds) {
    Impl& m = *m_impl;
    double end = m.servo.status().timeS + seconds;
    while (m.servo.status().timeS < end - 1e-12)
        m.cycle();
}

bool SimulatedMachine::runUntil(const std::function<bool(const MotionStatus&)>& done,
                                double timeoutS) {
    Impl& m = *m_impl;
    double end = m.servo.status().timeS + timeoutS;
    while (m.servo.status().timeS < end) {
        if (done(m.servo.status())) return true;
        m.cycle();
    }
    return done(m.servo.status());
}

const MotionStatus& SimulatedMachine::status() const {
    return m_impl->servo.status();
}
const MachineModel& SimulatedMachine::model() const {
    return m_impl->model;
}
SimDriveSet& SimulatedMachine::drives() {
    return m_impl->drives;
}
double SimulatedMachine::timeS() const {
    return m_impl->servo.status().timeS;
}

uint32_t SimulatedMachine::acceptedMoves() const {
    return m_impl->planner.acceptedMoves();
}

bool SimulatedMachine::halted() const {
    return m_impl->halted();
}

}  // namespace kerf::motion
