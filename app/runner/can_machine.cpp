#include "app/runner/can_machine.h"

#include <cmath>
#include <string>

#include "core/base/translate.h"
#include "motion/planner/planner.h"
#include "motion/rt/servo_cycle.h"

namespace kerf::app {

namespace {

using namespace motion;

// A program that has not finished after a simulated day is stuck.
constexpr double kMaxDrainS = 24.0 * 3600.0;
// Drive feedback is quantised to one count (1e-4 mm on the built-in machines): in position when
// within 1.5 counts.
constexpr double kInPositionMm = 1.5e-4;

}  // namespace

struct CanMachine::Chain {
    Chain(const machine::MachineConfig& config, const MotionOptions& options,
          std::unique_ptr<drivers::CanSimDriveSet> set)
        : model(makeMachineModel(config, options)),
          drives(std::move(set)),
          items(std::make_unique<ItemRing>()),
          servo(model, drives->bus(), *items, commands, events),
          planner(model) {}

    void cycle() {
        servo.cycle();
        drives->advance(model.periodS);
        handleEvents();
        if (!flushed && faulted()) {
            // Safety: what was planned must not start again after the stop.
            planner.reset(servo.status().actualPosition);
            stoppedAt = servo.status().source;
            flushed = true;
        }
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

    void pump() {
        while (auto item = planner.next()) {
            while (items->full() && !faulted())
                cycle();
            if (faulted()) return;
            items->push(*item);
        }
    }

    bool inPosition() const {
        const MotionStatus& s = servo.status();
        for (size_t i = 0; i < s.actualPosition.size(); ++i) {
            if (std::fabs(s.actualPosition[i] - s.commandedPosition[i]) > kInPositionMm)
                return false;
        }
        return true;
    }

    void runToIdle() {
        if (faulted()) return;
        planner.flush();
        pump();
        double end = servo.status().timeS + kMaxDrainS;
        int settle = 0;
        while (servo.status().timeS < end && !faulted()) {
            bool idle = items->empty() && servo.status().mode == MotionMode::Idle;
            // Let the smoothing filter bring the setpoints to the end point and the drives follow.
            if (idle && ++settle > model.filterTaps + 1 && inPosition()) break;
            if (!idle) settle = 0;
            cycle();
        }
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
    SourceLocation stoppedAt;
    double startS = 0.0;
    bool flushed = false;
};

Expected<std::unique_ptr<CanMachine>> CanMachine::create(const machine::MachineConfig& config,
                                                         drivers::CanSimOptions options,
                                                         const AxisVector& startTip,
                                                         const MotionOptions& motion) {
    auto set = drivers::CanSimDriveSet::create(config, std::move(options));
    if (!set) return set.error();
    auto chain = std::make_unique<Chain>(config, motion, std::move(set).value());
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
    if (c.faulted() || c.planner.refused()) return;
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
    double end = c.servo.status().timeS + seconds;
    while (c.servo.status().timeS < end - 1e-12)
        c.cycle();
}

bool CanMachine::stopped() const {
    return m_chain->faulted();
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
    r.maxFollowingErrorMm = s.maxFollowingError;
    r.busLoad = c.drives->measuredBusLoad();
    r.mode = s.mode;
    r.stopped = c.faulted();
    r.stoppedAt = c.stoppedAt;
    r.refused = c.planner.refused();
    c.drives->finish();
    // The drives' own words first: they name the node and the cause.
    r.diagnostics = c.drives->diagnostics();
    r.diagnostics.insert(r.diagnostics.end(), c.planner.diagnostics().begin(),
                         c.planner.diagnostics().end());
    r.diagnostics.insert(r.diagnostics.end(), c.motionErrors.begin(), c.motionErrors.end());
    return r;
}

drivers::CanSimDriveSet& CanMachine::drives() {
    return *m_chain->drives;
}

const MotionStatus& CanMachine::status() const {
    return m_chain->servo.status();
}

}  // namespace kerf::app
