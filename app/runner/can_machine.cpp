#include "app/runner/can_machine.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/geometry/axes.h"
#include "motion/planner/planner.h"
#include "motion/rt/servo_cycle.h"

namespace kerf::app {

namespace {

using namespace motion;
using drivers::cia402::Standstill;

// Drive feedback is quantised to one count: an axis is in position within 1.5 counts of its
// setpoint, at least 1.5e-4 mm (one count of the built-in machines) however fine the scale, at
// most its following-error window however coarse.
constexpr double kInPositionCounts = 1.5;
constexpr double kInPositionMinMm = 1.5e-4;
// Motion is done but an axis is not in position this long after: it will not get there (a
// control's in-position timeout).
constexpr double kInPositionTimeoutS = 1.0;

}  // namespace

bool StopOutcome::allAtRest() const {
    return std::all_of(drives.begin(), drives.end(),
                       [](const DriveRest& d) { return d.standstill == Standstill::AtRest; });
}

struct CanMachine::Chain {
    Chain(const machine::MachineConfig& config, const MotionOptions& options,
          std::unique_ptr<drivers::CanSimDriveSet> set, double simulatedLimitS)
        : model(makeMachineModel(config, options)),
          drives(std::move(set)),
          items(std::make_unique<ItemRing>()),
          servo(model, drives->bus(), *items, commands, events),
          planner(model),
          maxSimulatedS(simulatedLimitS) {
        inPositionMm.fill(kInPositionMinMm);
        double longestRampS = 0.0;
        const auto& joints = drives->config().joints;
        for (size_t j = 0; j < joints.size(); ++j) {
            const drivers::CanJoint& joint = joints[j];
            if (joint.maxAcceleration > 0.0)
                longestRampS = std::max(longestRampS, joint.maxVelocity / joint.maxAcceleration);
            int axis = j < model.jointAxis.size() ? model.jointAxis[j] : -1;
            if (axis >= 0 && joint.countsPerUnit > 0.0) {
                double window = std::max(joint.followingErrorWindow, kInPositionMinMm);
                inPositionMm[static_cast<size_t>(axis)] =
                    std::clamp(kInPositionCounts / joint.countsPerUnit, kInPositionMinMm, window);
            }
        }
        // Every quick stop (0x6085 = the joint's acceleration) is over within its ramp from full
        // speed; twice that and a second for the reports is the most a stop may take.
        stopLimitS = 1.0 + 2.0 * longestRampS;
    }

    double nowS() const { return servo.status().timeS; }

    void cycle() {
        servo.cycle();
        drives->advance(model.periodS);
        handleEvents();
        if (!flushed && faulted()) {
            // Safety: what was planned must not start again after the stop.
            planner.reset(servo.status().actualPosition);
            stoppedAt = servo.status().source;
            flushed = true;
            recordStop();
        }
    }

    void recordStop() {
        StopOutcome s;
        s.stoppedS = nowS() - startS;
        s.limitS = stopLimitS;
        s.tipAtStop = servo.status().actualPosition;
        const drivers::cia402::DriveBusAdapter& adapter = drives->stack().adapter();
        const auto& joints = drives->config().joints;
        for (size_t j = 0; j < joints.size(); ++j) {
            if (joints[j].node == 0) continue;
            DriveRest r;
            r.joint = static_cast<int>(j);
            r.letter = joints[j].axis;
            r.atStop = r.atRest = adapter.position(r.joint);
            s.drives.push_back(r);
        }
        stop = s;
        followingErrorAtStop = servo.status().maxFollowingError;
    }

    // After a stop: the drives ramp down under their quick stop; run until every one that still
    // reports is at rest, at most stopLimitS.
    void settle() {
        if (!stop || settled) return;
        settled = true;
        const drivers::cia402::DriveBusAdapter& adapter = drives->stack().adapter();
        auto resting = [&] {
            return std::none_of(stop->drives.begin(), stop->drives.end(), [&](const DriveRest& d) {
                return adapter.standstill(d.joint) == Standstill::Moving;
            });
        };
        double end = startS + stop->stoppedS + stopLimitS;
        while (!resting() && nowS() < end)
            cycle();
        stop->restS = nowS() - startS - stop->stoppedS;
        for (DriveRest& d : stop->drives) {
            d.atRest = adapter.position(d.joint);
            d.standstill = adapter.standstill(d.joint);
            if (d.standstill != Standstill::AtRest) restProblems.push_back(restProblem(d));
        }
    }

    Diagnostic restProblem(const DriveRest& d) const {
        const drivers::CanBusConfig& bus = drives->config();
        Diagnostic diagnostic;
        std::string node = std::to_string(bus.joints[static_cast<size_t>(d.joint)].node);
        std::string name = drivers::jointName(bus, d.joint);
        if (d.standstill == Standstill::Unknown) {
            diagnostic.severity = Severity::Warning;
            diagnostic.code = "drives.rest-unknown";
            diagnostic.messageTemplate = KERF_TR_NOOP(
                "CAN node {1} ({2}) sends no feedback since the stop: where it came to rest is "
                "unknown (last seen at {3})");
            diagnostic.args = {node, name, formatFixed(d.atRest, 3)};
        } else {
            diagnostic.severity = Severity::Error;
            diagnostic.code = "drives.not-at-rest";
            diagnostic.messageTemplate =
                KERF_TR_NOOP("CAN node {1} ({2}) was still moving {3} s after the quick stop");
            diagnostic.args = {node, name, formatFixed(stopLimitS, 3)};
        }
        return diagnostic;
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
                    commands.push({OperatorCommandKind::CycleStart});
                    break;
                case MotionEventKind::Error:
                case MotionEventKind::Fault:
                    // A drive fault is reported by the drive set, naming node and cause.
                    if (!drives->stopped()) motionErrors.push_back(motionError(e));
                    break;
                default:
                    break;
            }
        }
    }

    static Diagnostic motionError(const MotionEvent& e) {
        Diagnostic d;
        d.code = e.kind == MotionEventKind::Fault ? "motion.drive-fault" : "motion.error";
        d.messageTemplate = KERF_TR_NOOP("Motion error {1} at line {2}.");
        d.args = {std::to_string(static_cast<int>(e.value)), std::to_string(e.source.line)};
        d.line = e.source.line;
        d.severity = Severity::Error;
        return d;
    }

    bool faulted() const {
        MotionMode m = servo.status().mode;
        return drives->stopped() || m == MotionMode::Fault || m == MotionMode::EmergencyStop;
    }

    // Nothing more runs: a stop, the time limit or an axis that does not arrive.
    bool halted() const { return faulted() || timeLimitHit || notInPosition; }

    bool overTime() const { return nowS() - startS >= maxSimulatedS; }

    // The simulated-time limit: the axes stop along the path and the program is aborted.
    void endAtTimeLimit() {
        timeLimitHit = true;
        planner.reset(servo.status().actualPosition);
        commands.push({OperatorCommandKind::QuickStop});
        double end = nowS() + stopLimitS;
        int settleCycles = 0;
        double distance = 0.0;
        while (nowS() < end && !faulted()) {
            settleCycles = items->empty() && idle() ? settleCycles + 1 : 0;
            if (settleCycles > model.filterTaps + 1 && axisOutOfPosition(distance) < 0) break;
            cycle();
        }
        Diagnostic d;
        d.severity = Severity::Error;
        d.code = "drives.time-limit";
        d.messageTemplate = KERF_TR_NOOP(
            "the drive simulation reached its limit of {1} s of simulated time; the axes were "
            "stopped");
        d.args = {formatFixed(maxSimulatedS, 0)};
        limitProblems.push_back(d);
    }

    bool idle() const { return servo.status().mode == MotionMode::Idle; }

    void pump() {
        while (auto item = planner.next()) {
            while (items->full() && !halted()) {
                if (overTime()) return endAtTimeLimit();
                cycle();
            }
            if (halted()) return;
            items->push(*item);
        }
    }

    // The first axis beyond its in-position window (and how far it is); -1 if none.
    int axisOutOfPosition(double& distance) const {
        const MotionStatus& s = servo.status();
        for (size_t i = 0; i < s.actualPosition.size(); ++i) {
            distance = std::fabs(s.actualPosition[i] - s.commandedPosition[i]);
            if (distance > inPositionMm[i]) return static_cast<int>(i);
        }
        return -1;
    }

    void reportNotInPosition(int axis, double distance) {
        notInPosition = true;
        planner.reset(servo.status().actualPosition);
        Diagnostic d;
        d.severity = Severity::Error;
        d.code = "drives.in-position";
        d.messageTemplate =
            KERF_TR_NOOP("axis {1} did not reach its end point: {2} away {3} s after motion ended");
        std::string letter(1, axisLetter(static_cast<Axis>(axis)));
        d.args = {letter, formatFixed(distance, 4), formatFixed(kInPositionTimeoutS, 1)};
        limitProblems.push_back(d);
    }

    void runToIdle() {
        if (!halted()) {
            planner.flush();
            pump();
        }
        int settleCycles = 0;
        double idleSince = 0.0;
        while (!halted()) {
            if (overTime()) {
                endAtTimeLimit();
                break;
            }
            bool done = items->empty() && idle();
            if (done) {
                if (settleCycles == 0) idleSince = nowS();
                // Let the smoothing filter bring the setpoints to the end point and the drives
                // follow.
                double distance = 0.0;
                int axis = axisOutOfPosition(distance);
                if (++settleCycles > model.filterTaps + 1 && axis < 0) break;
                if (axis >= 0 && nowS() - idleSince > kInPositionTimeoutS) {
                    reportNotInPosition(axis, distance);
                    break;
                }
            } else {
                settleCycles = 0;
            }
            cycle();
        }
        settle();
    }

    MachineModel model;
    std::unique_ptr<drivers::CanSimDriveSet> drives;
    std::unique_ptr<ItemRing> items;
    CommandRing commands;
    EventRing events;
    ServoCycle servo;
    Planner planner;
    interp::WorldSnapshot world;
    DiagnosticList motionErrors;
    DiagnosticList restProblems;
    DiagnosticList limitProblems;
    SourceLocation stoppedAt;
    std::optional<StopOutcome> stop;
    AxisVector inPositionMm{};
    double followingErrorAtStop = 0.0;
    double stopLimitS = 1.0;
    double maxSimulatedS;
    double startS = 0.0;
    bool flushed = false;
    bool settled = false;
    bool timeLimitHit = false;
    bool notInPosition = false;
};

Expected<std::unique_ptr<CanMachine>> CanMachine::create(const machine::MachineConfig& config,
                                                         drivers::CanSimOptions options,
                                                         const AxisVector& startTip,
                                                         const MotionOptions& motion) {
    double maxSimulatedS = options.maxSimulatedS;
    auto set = drivers::CanSimDriveSet::create(config, std::move(options));
    if (!set) return set.error();
    auto chain = std::make_unique<Chain>(config, motion, std::move(set).value(), maxSimulatedS);
    const MachineModel& model = chain->model;
    std::vector<double> joints(static_cast<size_t>(model.jointCount), 0.0);
    for (int j = 0; j < model.jointCount; ++j) {
        int axis = model.jointAxis[static_cast<size_t>(j)];
        if (axis >= 0) {
            joints[static_cast<size_t>(j)] =
                jointFromAxis(model, axis, startTip[static_cast<size_t>(axis)], 0.0);
        }
    }
    chain->drives->setInitialPositions(joints);
    if (MaybeError error = chain->drives->boot()) {
        chain->drives->finish();
        return *error;
    }
    chain->planner.setPosition(startTip);
    chain->servo.start();
    chain->startS = chain->servo.status().timeS;
    return std::unique_ptr<CanMachine>(new CanMachine(std::move(chain)));
}

CanMachine::CanMachine(std::unique_ptr<Chain> chain) : m_chain(std::move(chain)) {}

CanMachine::~CanMachine() = default;

void CanMachine::consume(const canon::Command& command) {
    Chain& c = *m_chain;
    if (c.halted() || c.planner.refused()) return;
    if (c.planner.needsPosition()) {
        // A probe move ended where the probe stopped it: plan on from there.
        c.runToIdle();
        c.planner.setPosition(c.servo.status().actualPosition);
    }
    c.planner.add(command);
    c.pump();
}

interp::WorldSnapshot CanMachine::drain() {
    Chain& c = *m_chain;
    c.runToIdle();
    if (c.planner.needsPosition()) c.planner.setPosition(c.servo.status().actualPosition);
    c.world.position.values = c.servo.status().actualPosition;
    return c.world;
}

void CanMachine::runFor(double seconds) {
    Chain& c = *m_chain;
    double end = c.nowS() + seconds;
    while (c.nowS() < end - 1e-12)
        c.cycle();
}

bool CanMachine::stopped() const {
    return m_chain->halted();
}

bool CanMachine::refused() const {
    return m_chain->planner.refused();
}

CanRunResult CanMachine::finish() {
    Chain& c = *m_chain;
    c.runToIdle();
    CanRunResult r;
    const MotionStatus& s = c.servo.status();
    r.finalPosition = s.actualPosition;
    r.commandedPosition = s.commandedPosition;
    r.durationS = s.timeS - c.startS;
    // After a stop the frozen setpoints say nothing about following.
    r.maxFollowingErrorMm = c.stop ? c.followingErrorAtStop : s.maxFollowingError;
    r.busLoad = c.drives->measuredBusLoad();
    r.mode = s.mode;
    r.stopped = c.faulted();
    r.stoppedAt = c.stoppedAt;
    r.stop = c.stop;
    r.refused = c.planner.refused();
    r.timeLimit = c.timeLimitHit;
    c.drives->finish();
    // The drives' own words first: they name the node and the cause.
    r.diagnostics = c.drives->diagnostics();
    const DiagnosticList* lists[] = {&c.restProblems, &c.limitProblems, &c.planner.diagnostics(),
                                     &c.motionErrors};
    for (const DiagnosticList* list : lists) {
        r.diagnostics.insert(r.diagnostics.end(), list->begin(), list->end());
    }
    return r;
}

drivers::CanSimDriveSet& CanMachine::drives() {
    return *m_chain->drives;
}

const MotionStatus& CanMachine::status() const {
    return m_chain->servo.status();
}

}  // namespace kerf::app
