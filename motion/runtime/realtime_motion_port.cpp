#include "motion/runtime/realtime_motion_port.h"

#include <cmath>

namespace kerf::motion {

namespace {

std::optional<AxisVector> moveTarget(const canon::CommandBody& body) {
    if (const auto* rapid = std::get_if<canon::RapidMove>(&body)) return rapid->target.values;
    if (const auto* line = std::get_if<canon::LinearMove>(&body)) return line->target.values;
    if (const auto* arc = std::get_if<canon::ArcMove>(&body)) return arc->target.values;
    if (const auto* synced = std::get_if<canon::SpindleSyncedMove>(&body))
        return synced->target.values;
    if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) return probe->target.values;
    return std::nullopt;
}

double moveFeed(const canon::CommandBody& body) {
    if (const auto* line = std::get_if<canon::LinearMove>(&body)) return line->feed;
    if (const auto* arc = std::get_if<canon::ArcMove>(&body)) return arc->feed;
    if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) return probe->feed;
    return 0.0;
}

task::MachineState machineState(MotionMode mode) {
    switch (mode) {
        case MotionMode::Idle:
            return task::MachineState::Idle;
        case MotionMode::Program:
        case MotionMode::Returning:
            return task::MachineState::Running;
        case MotionMode::Hold:
            return task::MachineState::Held;
        case MotionMode::Stopped:
            return task::MachineState::Stopped;
        case MotionMode::Jog:
            return task::MachineState::Jogging;
        case MotionMode::Homing:
            return task::MachineState::Homing;
        case MotionMode::Stopping:
            return task::MachineState::Stopping;
        case MotionMode::EmergencyStop:
            return task::MachineState::EmergencyStop;
        case MotionMode::Fault:
            return task::MachineState::Fault;
    }
    return task::MachineState::Fault;
}

const char* motionErrorText(MotionError error) {
    switch (error) {
        case MotionError::None:
            return "";
        case MotionError::SoftLimit:
            return "the jog target was limited to the soft limit";
        case MotionError::DriveFault:
            return "drive fault";
        case MotionError::BusError:
            return "drive bus error";
        case MotionError::FollowingError:
            return "following error too large";
        case MotionError::QueueStarved:
            return "the planner fell behind; the axes stopped on the path";
        case MotionError::NotHomed:
            return "the axes are not homed";
    }
    return "";
}

}  // namespace

RealtimeMotionPort::RealtimeMotionPort(const machine::MachineConfig& config,
                                       RealtimeOptions options, DriveBus* bus)
    : m_machine(std::make_unique<RealtimeMachine>(config, options, bus)),
      m_config(config),
      m_workOffset(options.motion.workOffset) {
    m_machine->start();
}

RealtimeMotionPort::~RealtimeMotionPort() {
    m_machine->stop();
}

void RealtimeMotionPort::prepareForCommands() {
    Planner& planner = m_machine->planner();
    if (m_replan && m_machine->drained()) {
        planner.reset(m_machine->status().commandedPosition);
        m_replan = false;
        m_fault.clear();
    }
    if (planner.needsPosition() && m_machine->drained()) {
        // A probe move ended where the probe stopped it: plan on from there.
        planner.setPosition(m_machine->status().actualPosition);
    }
}

bool RealtimeMotionPort::submit(const canon::Command& command) {
    prepareForCommands();
    if (!m_machine->submit(command)) {
        const DiagnosticList& refusals = m_machine->planner().diagnostics();
        m_fault = refusals.empty() ? std::string("motion refused the command")
                                   : refusals.back().message();
        m_replan = true;
        return false;
    }
    Submitted s;
    s.block = command.location;
    s.target = moveTarget(command.body);
    if (const auto* mode = std::get_if<canon::SetFeedMode>(&command.body))
        m_feedPerRevolution = mode->mode == canon::FeedMode::PerRevolution;
    if (const auto* spindle = std::get_if<canon::SpindleControl>(&command.body))
        m_submittedRpm = spindle->speedRpm;
    // A feed per revolution (G95) shows as the path feed it gives at the programmed speed, and so
    // does a thread's lead (it was shown as F 0).
    s.feedMmPerMin = moveFeed(command.body) * (m_feedPerRevolution ? m_submittedRpm : 1.0);
    if (const auto* thread = std::get_if<canon::SpindleSyncedMove>(&command.body))
        s.feedMmPerMin = thread->leadMmPerRev * m_submittedRpm;
    if (const auto* tool = std::get_if<canon::ToolChange>(&command.body)) {
        s.tool = tool->number;
        s.toolLength = tool->geometry.lengthMm;
    }
    if (const auto* update = std::get_if<canon::ToolUpdate>(&command.body))
        s.toolLength = update->geometry.lengthMm;
    if (const auto* spindle = std::get_if<canon::SpindleControl>(&command.body)) {
        const bool turning = spindle->direction != canon::SpindleDirection::Stopped;
        s.spindleRpm = turning ? spindle->speedRpm : 0.0;
        s.surfaceSpeed = turning ? spindle->surfaceSpeedMPerMin : 0.0;
    }
    // Commands without an effect on the display need no memory.
    if (s.target || s.tool || s.toolLength || s.spindleRpm) m_submitted.push_back(s);
    return true;
}

bool RealtimeMotionPort::hasRoom() const {
    // Bounds the memory of what is planned but not executed. Well above the ring: the planner
    // holds back a braking distance of path, which for 1 µm segments is many thousand moves.
    constexpr size_t kMaxWaitingBlocks = size_t{1} << 16;
    return m_submitted.size() < kMaxWaitingBlocks;
}

void RealtimeMotionPort::flush() {
    m_machine->flush();
}

void RealtimeMotionPort::handle(const MotionEvent& event) {
    switch (event.kind) {
        case MotionEventKind::ProbeTriggered:
            m_probe.probeTriggered = true;
            m_probe.probePosition.values = event.position;
            break;
        case MotionEventKind::ProbeMissed:
            m_probe.probeTriggered = false;
            break;
        case MotionEventKind::Aborted:
            m_submitted.clear();
            m_replan = true;
            stopProgrammedSpindle();  // the abort stopped the spindle
            break;
        case MotionEventKind::Fault:
            m_fault = "drive fault " + std::to_string(static_cast<long>(event.value)) +
                      " on joint " + std::to_string(event.joint);
            m_submitted.clear();
            m_replan = true;
            break;
        case MotionEventKind::Error:
        case MotionEventKind::ItemRejected:
            m_fault = motionErrorText(static_cast<MotionError>(static_cast<int>(event.value)));
            break;
        case MotionEventKind::SyncReached:
        case MotionEventKind::ProgramStopped:
        case MotionEventKind::ProgramEnd:
        case MotionEventKind::HomingDone:
            break;
    }
}

void RealtimeMotionPort::stopProgrammedSpindle() {
    m_programmedRpm = 0.0;
    m_programmedSurfaceSpeed = 0.0;
}

void RealtimeMotionPort::retire(const Submitted& done) {
    if (done.tool) m_tool = *done.tool;
    if (done.toolLength) m_toolLength = *done.toolLength;
    if (done.spindleRpm) {
        m_programmedRpm = *done.spindleRpm;
        m_programmedSurfaceSpeed = done.surfaceSpeed;
    }
    m_executing = done;
}

void RealtimeMotionPort::followExecution(const MotionStatus& now) {
    if (m_machine->drained()) {
        while (!m_submitted.empty()) {
            retire(m_submitted.front());
            m_submitted.pop_front();
        }
        return;
    }
    if (now.mode != MotionMode::Program && now.mode != MotionMode::Hold &&
        now.mode != MotionMode::Stopped && now.mode != MotionMode::Stopping)
        return;
    // Everything before the executing block is done. A block of several moves (a cycle) moves on
    // to its next move once the axes reached the end of the current one.
    for (size_t i = 0; i < m_submitted.size(); ++i) {
        if (!(m_submitted[i].block == now.source)) continue;
        for (size_t k = 0; k < i; ++k) {
            retire(m_submitted.front());
            m_submitted.pop_front();
        }
        while (m_submitted.size() > 1 && m_submitted[0].target &&
               m_submitted[1].block == now.source) {
            double gap = 0.0;
            for (size_t a = 0; a < kAxisCount; ++a)
                gap = std::max(gap,
                               std::fabs((*m_submitted[0].target)[a] - now.commandedPosition[a]));
            if (gap > 1e-6) break;
            retire(m_submitted.front());
            m_submitted.pop_front();
        }
        if (m_submitted.front().tool || m_submitted.front().toolLength ||
            m_submitted.front().spindleRpm) {
            retire(m_submitted.front());  // the action is running now
        } else {
            m_executing = m_submitted.front();
        }
        return;
    }
}

void RealtimeMotionPort::pump() {
    m_machine->pump();
    while (auto event = m_machine->nextEvent())
        handle(*event);
    followExecution(m_machine->status());
}

bool RealtimeMotionPort::drained() const {
    return m_machine->drained();
}

interp::WorldSnapshot RealtimeMotionPort::world() const {
    interp::WorldSnapshot world = m_probe;
    world.position.values = m_machine->status().actualPosition;
    return world;
}

task::MotionPort::Progress RealtimeMotionPort::progress() const {
    const MotionStatus now = m_machine->status();
    Progress p;
    p.block = now.source;
    p.fault = m_fault;
    switch (now.mode) {
        case MotionMode::Idle:
            p.state = State::Idle;
            break;
        case MotionMode::Hold:
            p.state = State::Held;
            break;
        case MotionMode::Stopped:
            p.state = State::Stopped;
            break;
        case MotionMode::EmergencyStop:
        case MotionMode::Fault:
            p.state = State::Faulted;
            break;
        case MotionMode::Program:
        case MotionMode::Jog:
        case MotionMode::Returning:
        case MotionMode::Homing:
        case MotionMode::Stopping:
            p.state = State::Running;
            break;
    }
    return p;
}

void RealtimeMotionPort::cycleStart() {
    m_machine->command({OperatorCommandKind::CycleStart});
}

void RealtimeMotionPort::feedHold() {
    m_machine->command({OperatorCommandKind::FeedHold});
}

void RealtimeMotionPort::quickStop() {
    m_machine->command({OperatorCommandKind::QuickStop});
    m_replan = true;
    // Without a program the stop turns the spindle off at once (no Aborted event follows).
    const MotionMode mode = m_machine->status().mode;
    if (mode == MotionMode::Idle || mode == MotionMode::Jog || mode == MotionMode::Homing)
        stopProgrammedSpindle();
}

void RealtimeMotionPort::emergencyStop() {
    m_machine->command({OperatorCommandKind::EmergencyStop});
    m_replan = true;
    stopProgrammedSpindle();
    m_fault = "emergency stop";
}

bool RealtimeMotionPort::setEmergencyStopButton(bool pressed) {
    if (!m_machine->setEmergencyStopButton(pressed)) return false;
    if (pressed) {
        m_replan = true;
        stopProgrammedSpindle();
        m_fault = "emergency stop button pressed";
    }
    return true;
}

bool RealtimeMotionPort::machineOn() {
    const MotionStatus now = m_machine->status();
    if (now.mode != MotionMode::EmergencyStop && now.mode != MotionMode::Fault) return false;
    if (now.emergencyStopOpen) return false;
    m_fault.clear();
    return m_machine->command({OperatorCommandKind::Reset});
}

void RealtimeMotionPort::setSingleBlock(bool on) {
    m_singleBlock = on;
    // Single block stops at the programmed end of each block: no corner blend or fitted curve
    // may cut it short (moves planned before the switch keep theirs).
    m_machine->planner().setSingleBlock(on);
    OperatorCommand c{OperatorCommandKind::SingleBlock};
    c.flag = on;
    m_machine->command(c);
}

void RealtimeMotionPort::setSingleBlockEveryBlock(bool on) {
    OperatorCommand c{OperatorCommandKind::SingleBlockEveryBlock};
    c.flag = on;
    m_machine->command(c);
}

void RealtimeMotionPort::setFeedOverride(double fraction) {
    m_feedOverride = fraction;
    m_machine->command({OperatorCommandKind::FeedOverride, -1, fraction});
}

void RealtimeMotionPort::setRapidOverride(double fraction) {
    m_rapidOverride = fraction;
    m_machine->command({OperatorCommandKind::RapidOverride, -1, fraction});
}

void RealtimeMotionPort::setSpindleOverride(double fraction) {
    m_machine->command({OperatorCommandKind::SpindleOverride, -1, fraction});
}

int RealtimeMotionPort::jointOf(Axis axis) const {
    const MachineModel& model = m_machine->model();
    for (int j = 0; j < model.jointCount; ++j)
        if (model.jointAxis[static_cast<size_t>(j)] == axisIndex(axis)) return j;
    return -1;
}

bool RealtimeMotionPort::manualAllowed() const {
    const MotionMode mode = m_machine->status().mode;
    // Held or stopped, the operator may jog away from the program (the servo cycle returns to
    // the contour on cycle start); otherwise only without a program.
    return mode == MotionMode::Hold || mode == MotionMode::Stopped || mode == MotionMode::Jog ||
           (mode == MotionMode::Idle && m_submitted.empty());
}

bool RealtimeMotionPort::programInterrupted() const {
    const MotionStatus now = m_machine->status();
    return now.mode == MotionMode::Hold || now.mode == MotionMode::Stopped ||
           (now.mode == MotionMode::Jog && (now.queued > 0 || !m_submitted.empty()));
}

bool RealtimeMotionPort::jogContinuous(Axis axis, double velocityFraction) {
    const int joint = jointOf(axis);
    if (joint < 0 || !manualAllowed()) return false;
    const double velocity =
        velocityFraction * m_machine->model().axes[static_cast<size_t>(axisIndex(axis))].velocity;
    // The planner plans on from the jog's end, unless a program waits to continue its path.
    if (!programInterrupted()) m_replan = true;
    return m_machine->command({OperatorCommandKind::JogContinuous, joint, velocity});
}

bool RealtimeMotionPort::jogStop(Axis axis) {
    const int joint = jointOf(axis);
    if (joint < 0) return false;
    return m_machine->command({OperatorCommandKind::JogStop, joint});
}

bool RealtimeMotionPort::jogIncrement(Axis axis, double distance) {
    const int joint = jointOf(axis);
    if (joint < 0 || !manualAllowed()) return false;
    if (!programInterrupted()) m_replan = true;
    return m_machine->command({OperatorCommandKind::JogIncrement, joint, distance});
}

bool RealtimeMotionPort::home(std::optional<Axis> axis) {
    const int joint = axis ? jointOf(*axis) : -1;
    if ((axis && joint < 0) || m_machine->status().mode != MotionMode::Idle || !m_submitted.empty())
        return false;
    m_replan = true;
    return m_machine->command({OperatorCommandKind::Home, joint});
}

bool RealtimeMotionPort::withoutProgram() const {
    return m_submitted.empty() && m_machine->drained();
}

bool RealtimeMotionPort::manualSpindle(const canon::SpindleControl& spindle) {
    if (!withoutProgram()) return false;
    const int direction = spindle.direction == canon::SpindleDirection::Clockwise          ? 1
                          : spindle.direction == canon::SpindleDirection::CounterClockwise ? -1
                                                                                           : 0;
    const double rpm = direction != 0 ? spindle.speedRpm : 0.0;
    if (!m_machine->command({OperatorCommandKind::ManualSpindle, direction, rpm})) return false;
    // The next program plans with the spindle the operator left (feed per revolution).
    m_machine->planner().setSpindle(spindle.direction, rpm);
    m_programmedRpm = m_submittedRpm = rpm;
    m_programmedSurfaceSpeed = 0.0;
    return true;
}

bool RealtimeMotionPort::manualCoolant(const canon::CoolantControl& coolant) {
    if (!withoutProgram()) return false;
    const int bits = (coolant.flood ? 1 : 0) | (coolant.mist ? 2 : 0);
    return m_machine->command({OperatorCommandKind::ManualCoolant, bits});
}

task::MachineStatus RealtimeMotionPort::status() const {
    const MotionStatus now = m_machine->status();
    const MachineModel& model = m_machine->model();
    task::MachineStatus s;
    s.state = machineState(now.mode);
    s.block = now.source;
    s.feedOverride = now.feedOverride;
    s.rapidOverride = now.rapidOverride;
    s.spindleOverride = now.spindleOverride;
    s.actualSpindleRpm = now.spindleRpm;
    s.programmedSpindleRpm = m_programmedRpm;
    s.programmedSurfaceSpeedMPerMin = m_programmedSurfaceSpeed;
    s.coolant = now.coolant != 0;
    s.actualFeedMmPerMin = std::fabs(now.pathVelocity) * 60.0;
    const bool moving = s.state == task::MachineState::Running ||
                        s.state == task::MachineState::Held ||
                        s.state == task::MachineState::Stopped;
    s.programmedFeedMmPerMin = moving ? m_executing.feedMmPerMin : 0.0;
    s.toolNumber = m_tool;
    s.singleBlock = m_singleBlock;
    s.emergencyStopOpen = now.emergencyStopOpen;
    s.servoTimeS = now.timeS;
    for (int j = 0; j < model.jointCount; ++j) {
        const int axis = model.jointAxis[static_cast<size_t>(j)];
        if (axis < 0) continue;
        const auto i = static_cast<size_t>(axis);
        task::AxisStatus& a = s.axes[i];
        a.enabled = true;
        a.homed = ((now.homedMask >> j) & 1u) != 0;
        a.nominal = now.commandedPosition[i];
        a.actual = now.actualPosition[i];
        const double toMachine = m_workOffset[i] + (axis == model.toolAxis ? m_toolLength : 0.0);
        a.machineNominal = a.nominal + toMachine;
        a.machineActual = a.actual + toMachine;
        a.followingError = a.nominal - a.actual;
        a.distanceToGo = moving && m_executing.target ? (*m_executing.target)[i] - a.nominal : 0.0;
    }
    return s;
}

}  // namespace kerf::motion
