#include "motion/rt/servo_cycle.h"

#include <algorithm>
#include <cmath>

namespace kerf::motion {

namespace {

constexpr double kFarVelocity = 1e11;
constexpr size_t kSingleBlockScan = 8;
constexpr size_t kLookItems = 8;

// One single-block step: a programmed block (a called cycle's moves carry the calling block's
// place), or one point of a pattern the block machines.
bool sameStep(const SourceLocation& a, const SourceLocation& b) noexcept {
    return a.fileId == b.fileId && a.line == b.line && a.step == b.step;
}

}  // namespace

ServoCycle::ServoCycle(const MachineModel& model, DriveBus& bus, ItemRing& items,
                       CommandRing& commands, EventRing& events)
    : m_model(model),
      m_bus(bus),
      m_items(items),
      m_commands(commands),
      m_events(events),
      m_dt(model.periodS) {
    m_spindle.configure(model);
}

void ServoCycle::start() noexcept {
    readFeedback();
    AxisVector tip = actualTip();
    m_interpolated = tip;
    m_setpoint = tip;
    m_spindleSetpoint = m_model.spindleJoint >= 0
                            ? m_feedback[static_cast<size_t>(m_model.spindleJoint)].position
                            : 0.0;
    m_filter.reset(m_model.filterTaps, tip);
    m_spindleFilter.reset(m_model.filterTaps, {m_spindleSetpoint});
    m_spindle.reset(m_spindleSetpoint);
    if (m_model.options.startHomed) {
        m_status.homedMask = static_cast<uint16_t>((1u << m_model.jointCount) - 1u);
    }
    m_bus.request(DriveRequest::Enable);
    m_mode = MotionMode::Idle;
}

void ServoCycle::noteTiming(bool late, double cpuS) noexcept {
    if (late) ++m_status.lateCycles;
    m_status.maxCycleCpuS = std::max(m_status.maxCycleCpuS, cpuS);
}

AxisVector ServoCycle::actualTip() const noexcept {
    AxisVector tip = m_setpoint;
    for (int j = 0; j < m_model.jointCount; ++j) {
        int axis = m_model.jointAxis[static_cast<size_t>(j)];
        if (axis < 0) continue;
        tip[static_cast<size_t>(axis)] =
            axisFromJoint(m_model, axis, m_feedback[static_cast<size_t>(j)].position, m_toolLength);
    }
    return tip;
}

Limits ServoCycle::axisLimits(int axis) const noexcept {
    const AxisModel& a = m_model.axes[static_cast<size_t>(axis)];
    return {a.accel, a.jerk};
}

void ServoCycle::emit(MotionEventKind kind, int joint, double value,
                      const AxisVector& position) noexcept {
    MotionEvent event;
    event.kind = kind;
    event.joint = joint;
    event.value = value;
    event.timeS = m_status.timeS;
    event.position = position;
    event.sequence = m_status.itemSequence;
    event.source = m_status.source;
    m_events.push(event);
}

void ServoCycle::enterEmergencyStop() noexcept {
    m_bus.request(DriveRequest::QuickStop);
    abortProgram();
    m_mover = JointMover{};
    m_homingPhase = HomingPhase::Off;
    m_mode = MotionMode::EmergencyStop;
    emit(MotionEventKind::Aborted, -1, 0.0, m_setpoint);
}

void ServoCycle::readFeedback() noexcept {
    std::span<JointFeedback> feedback(m_feedback.data(), static_cast<size_t>(m_model.jointCount));
    BusResult result = m_bus.read(feedback);
    if (result == BusResult::Error && m_mode != MotionMode::Fault) {
        emit(MotionEventKind::Error, -1, static_cast<double>(MotionError::BusError), m_setpoint);
        abortProgram();
        m_mode = MotionMode::Fault;
    }
}

double ServoCycle::liveFeed(FeedKind kind, double feed) const noexcept {
    switch (kind) {
        case FeedKind::Rapid:
            return feed * m_rapidOverride;
        case FeedKind::PerMinute:
            return feed * m_feedOverride;
        case FeedKind::PerRevolution:
            return feed * std::fabs(m_spindle.rpm()) / 60.0 * m_feedOverride;
        case FeedKind::SpindleSynced:
            return feed * m_spindle.commandedRpm() / 60.0;
    }
    return 0.0;
}

void ServoCycle::stopSpindleAndCoolant() noexcept {
    m_spindle.unlock();
    m_spindle.command(0, 0.0, 0.0, 0.0);
    m_status.coolant = 0;
}

void ServoCycle::abortProgram() noexcept {
    // As after a TNC's internal stop: the program's spindle and coolant go off with it.
    stopSpindleAndCoolant();
    m_items.clear();
    m_hold = m_stopping = m_waitingStart = false;
    m_stepEndPending = false;
    m_elementEntered = m_actionStarted = false;
    m_onFeedMove = false;
    if (m_probeArmed) m_bus.armProbe(false);
    m_probeArmed = false;
    m_gen.reset(0.0);
    m_return.clear();
}

void ServoCycle::handle(const OperatorCommand& command) noexcept {
    switch (command.kind) {
        case OperatorCommandKind::CycleStart:
            if (m_return.away()) {
                // Back to the interruption point first; runReturn() then resumes the program.
                if (m_mode == MotionMode::Hold || m_mode == MotionMode::Stopped)
                    m_mode = MotionMode::Returning;
                break;
            }
            m_hold = false;
            m_waitingStart = false;
            if (m_mode == MotionMode::Hold || m_mode == MotionMode::Stopped)
                m_mode = MotionMode::Program;
            break;
        case OperatorCommandKind::FeedHold:
            if (m_mode == MotionMode::Program) m_hold = true;
            if (m_mode == MotionMode::Returning) {
                // Brake the return; at rest the program is interrupted again.
                m_mover.stop();
                m_mode = MotionMode::Jog;
            }
            break;
        case OperatorCommandKind::QuickStop:
            if (m_return.away()) {
                // Off the path: brake the axis that moves and abort the program where it stands.
                if (m_mover.active()) m_mover.stop();
                abortProgram();
                emit(MotionEventKind::Aborted, -1, 0.0, actualTip());
                m_mode = m_mover.active() ? MotionMode::Jog : MotionMode::Idle;
            } else if (m_mode == MotionMode::Program || m_mode == MotionMode::Hold ||
                       m_mode == MotionMode::Stopped) {
                // A program waiting for cycle start (single block, M0) stops from where it
                // stands: nothing else would ever step its path to rest.
                m_waitingStart = false;
                m_stopping = true;
                m_mode = MotionMode::Stopping;
            } else if (m_mode == MotionMode::Jog || m_mode == MotionMode::Homing) {
                // A stopped reference run leaves the axis unreferenced; the jog brakes to Idle.
                if (m_mover.active()) m_mover.stop();
                m_homingPhase = HomingPhase::Off;
                m_mode = m_mover.active() ? MotionMode::Jog : MotionMode::Idle;
                stopSpindleAndCoolant();
            } else if (m_mode == MotionMode::Idle) {
                stopSpindleAndCoolant();
            }
            break;
        case OperatorCommandKind::EmergencyStop:
            enterEmergencyStop();
            break;
        case OperatorCommandKind::Reset:
            // While the E-stop chain is open the drives must stay off, whatever the panel says.
            if ((m_mode == MotionMode::EmergencyStop || m_mode == MotionMode::Fault) &&
                !m_status.emergencyStopOpen) {
                m_bus.request(DriveRequest::FaultReset);
                m_bus.request(DriveRequest::Enable);
                m_mode = MotionMode::Idle;
            }
            break;
        case OperatorCommandKind::FeedOverride:
            m_feedOverride = std::clamp(command.value, 0.0, m_model.options.maxFeedOverride);
            break;
        case OperatorCommandKind::RapidOverride:
            m_rapidOverride = std::clamp(command.value, 0.0, 1.0);
            break;
        case OperatorCommandKind::SpindleOverride:
            m_spindle.setOverride(std::clamp(command.value, 0.0, 1.5));
            m_status.spindleOverride = std::clamp(command.value, 0.0, 1.5);
            break;
        case OperatorCommandKind::SingleBlock:
            m_singleBlock = command.flag;
            break;
        case OperatorCommandKind::SingleBlockEveryBlock:
            m_everyBlockSteps = command.flag;
            break;
        case OperatorCommandKind::OptionalStop:
            m_optionalStop = command.flag;
            break;
        case OperatorCommandKind::JogContinuous:
        case OperatorCommandKind::JogIncrement:
        case OperatorCommandKind::Handwheel: {
            // An interrupted program may be left once the path stands still.
            const bool interrupted =
                (m_mode == MotionMode::Hold || m_mode == MotionMode::Stopped) && m_gen.atRest();
            if (m_mode != MotionMode::Idle && m_mode != MotionMode::Jog && !interrupted) break;
            int joint = command.joint;
            if (joint < 0 || joint >= m_model.jointCount) break;
            int axis = m_model.jointAxis[static_cast<size_t>(joint)];
            if (axis < 0) break;
            const AxisModel& a = m_model.axes[static_cast<size_t>(axis)];
            bool homed = (m_status.homedMask >> joint) & 1u;
            double lo = homed ? axisFromJoint(m_model, axis, a.minLimit, m_toolLength) : -1e9;
            double hi = homed ? axisFromJoint(m_model, axis, a.maxLimit, m_toolLength) : 1e9;
            double position = m_interpolated[static_cast<size_t>(axis)];
            if (m_mover.active() && m_mover.axis() != axis) break;
            // An axis beyond a limit (limits changed, the machine moved while off) may only go
            // back: further on is refused where it stands, never clamped back to the limit (a
            // jump of the setpoint, or a move against the operator's direction).
            const double outward = command.value;
            if ((outward > 0.0 && position >= hi) || (outward < 0.0 && position <= lo)) {
                emit(MotionEventKind::Error, joint, static_cast<double>(MotionError::SoftLimit),
                     m_setpoint);
                break;
            }
            if (command.kind == OperatorCommandKind::JogContinuous) {
                double velocity = std::clamp(command.value, -a.velocity, a.velocity);
                m_mover.jog(axis, position, velocity, lo, hi);
            } else {
                double base = command.kind == OperatorCommandKind::Handwheel && m_mover.active()
                                  ? m_mover.target()
                                  : position;
                double target = base + command.value;
                // Clamped to the limit ahead; a target still beyond the limit behind (the way
                // back from outside) is where the operator asked to go.
                const double upper = std::max(hi, position);
                const double lower = std::min(lo, position);
                if (target < lower || target > upper) {
                    emit(MotionEventKind::Error, joint, static_cast<double>(MotionError::SoftLimit),
                         m_setpoint);
                    target = std::clamp(target, lower, upper);
                }
                double velocity =
                    command.kind == OperatorCommandKind::JogIncrement && command.value2 > 0.0
                        ? std::min(command.value2, a.velocity)
                        : a.velocity * m_model.options.jogVelocityFraction;
                if (command.kind == OperatorCommandKind::Handwheel && m_mover.active()) {
                    m_mover.moveTarget(target);
                } else {
                    m_mover.moveTo(axis, position, target, velocity);
                }
            }
            if (interrupted) m_return.leave(m_interpolated, m_mode);
            m_mode = MotionMode::Jog;
            break;
        }
        case OperatorCommandKind::JogStop:
            if (m_mover.active()) m_mover.stop();
            break;
        case OperatorCommandKind::Home:
            if (m_mode != MotionMode::Idle) break;
            m_homingOnly = command.joint;
            m_homingStep = 0;
            m_homingJoint = command.joint >= 0        ? command.joint
                            : m_model.homingCount > 0 ? m_model.homingOrder[0]
                                                      : -1;
            m_homingPhase = HomingPhase::LeaveSwitch;
            m_mode = MotionMode::Homing;
            break;
        case OperatorCommandKind::ManualSpindle:
            // A new speed or a stop takes over from where the spindle is, mid-ramp too; the
            // machine stays ready meanwhile (a program's spindle is the program's).
            if (!manualFunctionsAllowed()) break;
            m_spindle.command(command.joint, command.value, 0.0, 0.0);
            break;
        case OperatorCommandKind::ManualCoolant:
            if (!manualFunctionsAllowed()) break;
            m_status.coolant = static_cast<uint8_t>(command.joint);
            break;
    }
}

bool ServoCycle::manualFunctionsAllowed() const noexcept {
    return (m_mode == MotionMode::Idle || m_mode == MotionMode::Jog) && m_items.empty();
}

void ServoCycle::processCommands() noexcept {
    while (!m_commands.empty()) {
        handle(m_commands.front());
        m_commands.pop();
    }
}

void ServoCycle::followFeedback() noexcept {
    m_interpolated = actualTip();
    if (m_model.spindleJoint >= 0) {
        m_spindleSetpoint = m_feedback[static_cast<size_t>(m_model.spindleJoint)].position;
    }
    m_filter.reset(m_model.filterTaps, m_interpolated);
    m_spindleFilter.reset(m_model.filterTaps, {m_spindleSetpoint});
    m_spindle.reset(m_spindleSetpoint);
    m_setpoint = m_interpolated;
}

void ServoCycle::enterElement(const PathElement& e) noexcept {
    m_elementEntered = true;
    // After a probe stop or an abort the path continues from where the machine stands.
    if (m_gen.atRest() && std::fabs(m_gen.state().s - e.sStart) > 1e-9) m_gen.reset(e.sStart);
    m_onFeedMove = e.feedMove;
    if (e.feedKind == FeedKind::SpindleSynced) m_syncAngleStart = m_spindle.angle();
    if (e.probe && !m_probeArmed) {
        m_bus.armProbe(true);
        m_probeArmed = true;
        m_probeTriggered = false;
    }
}

size_t ServoCycle::collectConstraints(size_t first, std::span<Constraint> out) const noexcept {
    const MotionItem& current = m_items.peek(first);
    const PathElement& e = current.element;
    size_t count = 0;
    // The binding point of this element, and of the next ones this period may reach.
    const MotionState& x = m_gen.state();
    double reach = x.s + (std::fabs(x.v) + e.limits.accel * m_dt) * m_dt * 2.0 + 1e-9;
    double lastBind = -1.0;
    size_t end = std::min(m_items.size(), first + kLookItems);
    for (size_t i = first; i < end; ++i) {
        const MotionItem& item = m_items.peek(i);
        if (item.kind != MotionItem::Kind::Element) break;
        const PathElement& p = item.element;
        if (i > first && p.sStart > reach) break;
        if (p.bindVelocity < kFarVelocity && p.bindS != lastBind && p.bindS >= x.s) {
            out[count++] = {p.bindS,
                            std::min(p.bindVelocity, liveFeed(p.bindFeedKind, p.bindFeed))};
            lastBind = p.bindS;
        }
    }
    // The end of what is queued, unless the planner's binding points already stop there (then
    // they meet it with the limits of each element on the way, not this one's).
    const MotionItem& last = m_items.peek(m_items.size() - 1);
    if (last.kind == MotionItem::Kind::Element &&
        !(last.element.bindS == last.element.sEnd() && last.element.bindVelocity == 0.0))
        out[count++] = {last.element.sEnd(), 0.0};
    if (m_singleBlock && m_singleBlockS >= 0.0) out[count++] = {m_singleBlockS, 0.0};
    return count;
}

void ServoCycle::chooseSingleBlockStop() noexcept {
    if (!m_singleBlock) {
        m_singleBlockS = -1.0;
        return;
    }
    if (m_singleBlockS >= 0.0) return;  // keep braking for the one chosen
    size_t scan = std::min(m_items.size(), kSingleBlockScan);
    for (size_t i = 0; i < scan; ++i) {
        const MotionItem& item = m_items.peek(i);
        if (item.kind != MotionItem::Kind::Element) return;
        if (!endsSingleBlockStep(i)) continue;
        // The first block end the motion can still stop at.
        if (canMeet(m_gen.state(), {item.element.sEnd(), 0.0}, item.element.limits)) {
            m_singleBlockS = item.element.sEnd();
            return;
        }
    }
}

bool ServoCycle::endsSingleBlockStep(size_t index) const noexcept {
    const MotionItem& item = m_items.peek(index);
    if (!item.element.blockEnd) return false;
    // A called cycle (TNC CYCL CALL, a Fagor canned cycle) is one block: its moves and dwells
    // carry the calling block's place and run without a stop between them (docs/hmi.md). Blocks
    // a program joined (Fagor ESBLK) are one block too. The next move decides; the actions
    // before it (a dwell, the spindle) are passed over.
    const size_t end = std::min(m_items.size(), index + 1 + kSingleBlockScan);
    for (size_t i = index + 1; i < end; ++i) {
        const MotionItem& next = m_items.peek(i);
        if (next.kind != MotionItem::Kind::Element) continue;
        const uint32_t group = item.element.joinedGroup;
        if (group != 0 && next.element.joinedGroup == group) return false;
        return !sameStep(next.source, item.source);
    }
    return true;  // no move queued after it yet: the motion comes to rest here anyway
}

bool ServoCycle::continuesStep(const MotionItem& item) const noexcept {
    return sameStep(item.source, m_stepEnd);
}

bool ServoCycle::endsStepAlone(const Action& action) noexcept {
    if (action.joinedGroup != 0) return false;  // ESBLK: the blocks run as one
    switch (action.kind) {
        case ActionKind::Dwell:
        case ActionKind::ToolChange:
        case ActionKind::Spindle:
        case ActionKind::SpindleOrient:
        case ActionKind::Coolant:
        case ActionKind::MachineFunction:
            return true;
        case ActionKind::ProgramStop:  // stops (M0, M1) or ends the program itself
        case ActionKind::SyncStart:    // part of a threading move
        case ActionKind::SyncEnd:
        case ActionKind::SyncPoint:  // the task waits for the machine, then goes on
            return false;
    }
    return false;
}

void ServoCycle::stopAfterStep() noexcept {
    m_stepEndPending = false;
    m_waitingStart = true;
    m_mode = MotionMode::Stopped;
    emit(MotionEventKind::ProgramStopped, -1, 0.0, actualTip());
}

double ServoCycle::targetVelocity(const PathElement& e) const noexcept {
    if (m_hold || m_stopping || m_probeTriggered) return 0.0;
    return std::min(e.capVelocity, liveFeed(e.feedKind, e.feed));
}

void ServoCycle::stepPath() noexcept {
    chooseSingleBlockStop();
    // Within one period the interpolator may pass any number of elements, and it never drops
    // time on the way (a stall inside a period becomes an acceleration spike after the filter):
    // where it passes the end of an element whose successor changes the target, the limits or
    // the constraints (a binding point), it re-plans the rest of the period from there; across
    // the other ends the plan goes on. O(1) per element passed; at most the queue.
    double remaining = m_dt;
    size_t index = 0;
    std::array<Constraint, kLookItems + 2> constraints{};
    Profile plan;
    bool planned = false;
    for (;;) {
        const PathElement& e = m_items.peek(index).element;
        double target = targetVelocity(e);
        if (!planned) {
            size_t count = collectConstraints(index, constraints);
            plan = m_gen.plan(remaining, target, e.limits, {constraints.data(), count});
            planned = true;
        }
        MotionState end = plan.at(remaining);
        bool nextElement =
            index + 1 < m_items.size() && m_items.peek(index + 1).kind == MotionItem::Kind::Element;
        if (end.s >= e.sEnd() - 1e-9 && std::fabs(end.v) < 1e-6) {
            // Came to rest at the end (a stop): the next period decides how to go on.
            m_gen.setState({e.sEnd(), 0.0, 0.0});
            break;
        }
        if (end.s <= e.sEnd() || !nextElement) {
            m_gen.setState(end);
            break;
        }
        const PathElement& next = m_items.peek(index + 1).element;
        bool samePlan = e.bindS > e.sEnd() + 1e-12 && next.limits.accel == e.limits.accel &&
                        next.limits.jerk == e.limits.jerk && targetVelocity(next) == target;
        ++index;
        if (samePlan) continue;
        double lo = 0.0;
        double hi = remaining;
        for (int k = 0; k < 48; ++k) {
            double mid = (lo + hi) / 2.0;
            if (plan.at(mid).s < e.sEnd())
                lo = mid;
            else
                hi = mid;
        }
        MotionState at = plan.at(hi);
        at.s = e.sEnd();
        m_gen.setState(at);
        remaining -= hi;
        planned = false;
    }
    if (m_gen.state().v < 0.0 && m_gen.state().v > -1e-9)
        m_gen.setState({m_gen.state().s, 0.0, m_gen.state().a});
}

bool ServoCycle::runAction(const MotionItem& item) noexcept {
    const Action& a = item.action;
    bool first = !m_actionStarted;
    m_actionStarted = true;
    m_status.itemSequence = item.sequence;
    m_status.source = item.source;
    switch (a.kind) {
        case ActionKind::Dwell:
            if (first) m_actionTimer = 0.0;
            m_actionTimer += m_dt;
            return m_actionTimer >= a.value - 1e-12;
        case ActionKind::ProgramStop:
            if (a.number == 2) {
                if (!filterSettled()) return false;
                m_stepEndPending = false;  // the end needs no single-block stop after it
                emit(MotionEventKind::ProgramEnd, -1, 0.0, actualTip());
                return true;
            }
            if (a.number == 1 && !m_optionalStop) return true;
            if (first) {
                m_stepEndPending = false;  // this stop is the step's
                m_waitingStart = true;
                m_mode = MotionMode::Stopped;
                emit(MotionEventKind::ProgramStopped, -1, 0.0, actualTip());
            }
            return !m_waitingStart;
        case ActionKind::ToolChange: {
            if (!filterSettled()) return false;
            double delta = m_toolLength - a.value;
            m_toolLength = a.value;
            // The joints stay: the tip moves by the change of length.
            auto axis = static_cast<size_t>(m_model.toolAxis);
            m_filter.shift(axis, delta);
            m_interpolated[axis] += delta;
            m_setpoint[axis] += delta;
            return true;
        }
        case ActionKind::Spindle:
            if (first) m_spindle.command(a.number, a.value, a.aux, a.value2);
            return m_spindle.settled();
        case ActionKind::SpindleOrient:
            if (first) m_spindle.orient(a.value);
            return m_spindle.settled();
        case ActionKind::SyncStart:
            // Axes and spindle stand still, their setpoints too: the lock starts exactly.
            if (first) m_spindle.orient(a.value);
            if (!m_spindle.settled() || !filterSettled() || !m_spindleFilter.settled())
                return false;
            m_spindle.lock();
            return true;
        case ActionKind::SyncEnd:
            m_spindle.unlock();
            return true;
        case ActionKind::SyncPoint:
            if (!filterSettled()) return false;
            emit(MotionEventKind::SyncReached, -1, static_cast<double>(a.number), actualTip());
            return true;
        case ActionKind::Coolant:
            m_status.coolant = static_cast<uint8_t>(a.number);
            return true;
        case ActionKind::MachineFunction:
            return true;
    }
    return true;
}

void ServoCycle::runProgram() noexcept {
    bool stepped = false;
    m_currentMove = 0;
    m_currentFirstMove = 0;
    if (!m_singleBlock) m_stepEndPending = false;
    // Every pass but the last pops an item: at most the queue, whatever the path passed.
    for (size_t guard = 0; guard <= kItemRingCapacity; ++guard) {
        if (m_items.empty()) {
            m_onFeedMove = false;
            if (m_stepEndPending && !m_stopping) {
                // The step's moves and actions are done and nothing else is queued yet: wait
                // here, as the machine would stop before the next block anyway.
                if (filterSettled()) stopAfterStep();
                return;
            }
            m_stepEndPending = false;
            if (m_gen.atRest() && !m_hold) m_mode = MotionMode::Idle;
            if (m_stopping) {
                m_stopping = false;
                m_mode = MotionMode::Idle;
            }
            return;
        }
        const MotionItem& item = m_items.front();
        if (m_stepEndPending && !m_stopping) {
            if (!continuesStep(item)) {
                // Stopped where the axes stand still, setpoints too (the position shown is
                // final).
                if (filterSettled()) stopAfterStep();
                return;
            }
            // The move of a block whose actions came first: the step ends where it ends.
            if (item.kind == MotionItem::Kind::Element) m_stepEndPending = false;
        }
        // At a single-block stop nothing of the next step starts before NC start.
        if (m_waitingStart && !m_actionStarted) return;
        if (item.kind == MotionItem::Kind::Action) {
            if (m_stopping) {
                abortProgram();
                emit(MotionEventKind::Aborted, -1, 0.0, actualTip());
                m_mode = MotionMode::Idle;
                return;
            }
            if (!runAction(item)) return;
            const bool stepEnds = m_singleBlock && m_everyBlockSteps && endsStepAlone(item.action);
            if (stepEnds) {
                // A block without a move is a step too: the stop comes before the next item of
                // another block (as after a move).
                m_stepEnd = item.source;
                m_stepEndPending = true;
            }
            m_items.pop();
            m_actionStarted = false;
            // The block ran in this cycle; whether it stops is seen in the next, so the status
            // shows it running for a cycle at least (an NC start is always answered).
            if (stepEnds) return;
            continue;
        }
        const PathElement& e = item.element;
        if (!m_elementEntered) enterElement(e);
        m_currentMove = e.moveIndex;
        m_currentFirstMove = e.firstMoveIndex > 0 ? e.firstMoveIndex : e.moveIndex;
        m_status.itemSequence = item.sequence;
        m_status.source = item.source;
        if (!stepped) {
            stepPath();
            stepped = true;
        }
        if (m_probeArmed && !m_probeTriggered) {
            for (int j = 0; j < m_model.jointCount; ++j) {
                if (!m_feedback[static_cast<size_t>(j)].probeLatched) continue;
                AxisVector latched = actualTip();
                for (int k = 0; k < m_model.jointCount; ++k) {
                    int axis = m_model.jointAxis[static_cast<size_t>(k)];
                    if (axis < 0) continue;
                    latched[static_cast<size_t>(axis)] = axisFromJoint(
                        m_model, axis, m_feedback[static_cast<size_t>(k)].probePosition,
                        m_toolLength);
                }
                m_probeTriggered = true;
                emit(MotionEventKind::ProbeTriggered, -1, 0.0, latched);
                break;
            }
        }
        double s = m_gen.state().s;
        double local = std::clamp(s - e.sStart, 0.0, e.geometry.length);
        m_interpolated = positionAt(e.geometry, local);
        if (e.feedKind == FeedKind::SpindleSynced) {
            m_spindle.setLockedAngle(m_syncAngleStart + e.spindleDegPerUnit * local,
                                     e.spindleDegPerUnit * m_gen.state().v);
        }
        bool stopped = m_gen.atRest() && (m_hold || m_stopping || m_probeTriggered);
        if (stopped && m_probeTriggered) {
            // The probe move ends where the machine stopped.
            m_bus.armProbe(false);
            m_probeArmed = m_probeTriggered = false;
            m_items.pop();
            m_elementEntered = false;
            m_gen.reset(0.0);
            continue;
        }
        if (stopped && m_stopping) {
            abortProgram();
            emit(MotionEventKind::Aborted, -1, 0.0, actualTip());
            m_mode = MotionMode::Idle;
            return;
        }
        if (stopped && m_hold) {
            m_mode = MotionMode::Hold;
            return;
        }
        bool nextIsElement =
            m_items.size() > 1 && m_items.peek(1).kind == MotionItem::Kind::Element;
        // Into the next element once past this one; before a stop, once at rest at its end.
        const MotionState& x = m_gen.state();
        bool landed = s >= e.sEnd() - 1e-9 && std::fabs(x.v) < 1e-4 && std::fabs(x.a) < 1.0;
        // An exact stop between two elements: the motion must come to rest at the end of this
        // one, and the smoothed setpoints with it, before the next starts (else the filter
        // would round the corner).
        bool exactStop = e.bindVelocity == 0.0 && e.bindS <= e.sEnd() + 1e-12;
        if (s < e.sEnd() && !landed) return;
        if (exactStop && !filterSettled()) {
            m_gen.setState({e.sEnd(), 0.0, 0.0});
            return;
        }
        if (!nextIsElement) {
            if (!landed) {
                // Planned items ran out while moving (the planner fell behind).
                emit(MotionEventKind::Error, -1, static_cast<double>(MotionError::QueueStarved),
                     m_interpolated);
            }
            m_gen.setState({e.sEnd(), 0.0, 0.0});
        }
        if (e.probe && m_probeArmed) {
            m_bus.armProbe(false);
            m_probeArmed = false;
            emit(MotionEventKind::ProbeMissed, -1, 0.0, actualTip());
        }
        if (m_singleBlock && m_gen.atRest() && endsSingleBlockStep(0)) {
            // The move is done; the block's own actions after it run before the stop.
            m_stepEnd = item.source;
            m_stepEndPending = true;
            m_singleBlockS = -1.0;
            m_items.pop();
            m_elementEntered = false;
            m_onFeedMove = false;
            continue;
        }
        // A stop chosen here before the rest of its block was queued is not one.
        if (m_singleBlockS >= 0.0 && m_singleBlockS <= e.sEnd() + 1e-9) m_singleBlockS = -1.0;
        m_items.pop();
        m_elementEntered = false;
        if (!nextIsElement) m_onFeedMove = false;
    }
}

bool ServoCycle::moveManualAxis() noexcept {
    int axis = m_mover.axis();
    if (axis < 0 || !m_mover.active()) return false;
    double position = m_interpolated[static_cast<size_t>(axis)];
    bool moving = m_mover.update(m_dt, axisLimits(axis), position);
    m_interpolated[static_cast<size_t>(axis)] = position;
    return moving;
}

void ServoCycle::runManual() noexcept {
    // A jog away from an interrupted program ends in that interruption, not in Idle.
    if (!moveManualAxis()) m_mode = m_return.away() ? m_return.interruptedMode() : MotionMode::Idle;
}

void ServoCycle::runReturn() noexcept {
    // One axis at a time at the jog velocity, each to rest (setpoints too) before the next.
    if (m_mover.active()) {
        if (!moveManualAxis()) {
            auto axis = static_cast<size_t>(m_mover.axis());
            m_interpolated[axis] = m_return.point()[axis];  // exactly, without rounding
        }
        return;
    }
    if (!filterSettled()) return;
    int axis = m_return.nextAxis(m_interpolated, m_model.toolAxis);
    if (axis < 0) {
        // On the path again: resume as a cycle start would have.
        m_return.clear();
        m_hold = false;
        m_waitingStart = false;
        m_mode = MotionMode::Program;
        return;
    }
    const AxisModel& a = m_model.axes[static_cast<size_t>(axis)];
    m_mover.moveTo(axis, m_interpolated[static_cast<size_t>(axis)],
                   m_return.point()[static_cast<size_t>(axis)],
                   a.velocity * m_model.options.jogVelocityFraction);
    moveManualAxis();
}

void ServoCycle::runHoming() noexcept {
    if (m_homingJoint < 0 || m_homingJoint >= m_model.jointCount) {
        m_homingPhase = HomingPhase::Off;
        m_mode = MotionMode::Idle;
        return;
    }
    int axis = m_model.jointAxis[static_cast<size_t>(m_homingJoint)];
    if (axis < 0) {  // the spindle needs no homing
        nextHomingJoint();
        return;
    }
    const AxisModel& a = m_model.axes[static_cast<size_t>(axis)];
    const JointFeedback& fb = m_feedback[static_cast<size_t>(m_homingJoint)];
    auto index = static_cast<size_t>(axis);
    double position = m_interpolated[index];
    double search = a.velocity * 0.05;
    switch (m_homingPhase) {
        case HomingPhase::Off:
            return;
        case HomingPhase::LeaveSwitch:
            if (!fb.homeSwitch) {
                m_mover.jog(axis, position, -search, -1e9, 1e9);
                m_homingPhase = HomingPhase::Search;
            } else if (!m_mover.active()) {
                m_mover.jog(axis, position, search, -1e9, 1e9);
            }
            if (fb.homeSwitch) break;
            return;
        case HomingPhase::Search:
            if (fb.homeSwitch) {
                m_homingLatch = fb.position;
                m_mover.stop();
                m_homingPhase = HomingPhase::Brake;
            }
            break;
        case HomingPhase::Brake:
            if (m_mover.active()) break;
            if (filterSettled()) {
                // The switch position becomes the home position.
                double joint = fb.position - m_homingLatch + a.home;
                m_bus.setPosition(m_homingJoint, joint);
                double shift = joint - fb.position;
                m_filter.shift(index, shift);
                m_interpolated[index] += shift;
                m_setpoint[index] += shift;
                double home = axisFromJoint(m_model, axis, a.home, m_toolLength);
                m_mover.moveTo(axis, m_interpolated[index], home, search * 4.0);
                m_homingPhase = HomingPhase::Return;
            }
            return;
        case HomingPhase::Return:
            if (!m_mover.active() && filterSettled()) {
                m_status.homedMask =
                    static_cast<uint16_t>(m_status.homedMask | (1u << m_homingJoint));
                emit(MotionEventKind::HomingDone, m_homingJoint, 0.0, m_setpoint);
                nextHomingJoint();
                m_homingPhase = HomingPhase::LeaveSwitch;
                return;
            }
            break;
    }
    position = m_interpolated[index];
    m_mover.update(m_dt, axisLimits(axis), position);
    m_interpolated[index] = position;
}

void ServoCycle::nextHomingJoint() noexcept {
    if (m_homingOnly >= 0 || ++m_homingStep >= m_model.homingCount) {
        m_homingJoint = -1;
    } else {
        m_homingJoint = m_model.homingOrder[static_cast<size_t>(m_homingStep)];
    }
}

void ServoCycle::writeOutputs() noexcept {
    m_spindleSetpoint = m_spindle.angle();
    m_setpoint = m_filter.push(m_interpolated);
    m_spindleOutput = m_spindleFilter.push({m_spindleSetpoint})[0];
    for (int j = 0; j < m_model.jointCount; ++j) {
        int axis = m_model.jointAxis[static_cast<size_t>(j)];
        double value =
            axis < 0
                ? m_spindleOutput
                : jointFromAxis(m_model, axis, m_setpoint[static_cast<size_t>(axis)], m_toolLength);
        m_setpoints[static_cast<size_t>(j)].position = value;
    }
    m_bus.write({m_setpoints.data(), static_cast<size_t>(m_model.jointCount)});
}

void ServoCycle::cycle() noexcept {
    ++m_status.cycle;
    m_status.timeS += m_dt;
    readFeedback();
    m_status.emergencyStopOpen = m_bus.emergencyStopOpen();
    if (m_status.emergencyStopOpen && m_mode != MotionMode::EmergencyStop) enterEmergencyStop();
    for (int j = 0; j < m_model.jointCount; ++j) {
        const JointFeedback& fb = m_feedback[static_cast<size_t>(j)];
        if (fb.state == DriveState::Fault && m_mode != MotionMode::Fault &&
            m_mode != MotionMode::EmergencyStop) {
            emit(MotionEventKind::Fault, j, fb.faultCode, m_setpoint);
            abortProgram();
            m_mover = JointMover{};
            m_homingPhase = HomingPhase::Off;
            m_mode = MotionMode::Fault;
        }
    }
    processCommands();
    if (m_mode == MotionMode::Idle && !m_items.empty()) m_mode = MotionMode::Program;
    if (m_mode != MotionMode::Program && m_mode != MotionMode::Hold)
        m_currentMove = m_currentFirstMove = 0;
    switch (m_mode) {
        case MotionMode::Hold:
        case MotionMode::Stopped:
            // Away from the interruption the path must not pull the axes back.
            if (!m_return.away()) runProgram();
            break;
        case MotionMode::Program:
        case MotionMode::Stopping:
            runProgram();
            break;
        case MotionMode::Jog:
            runManual();
            break;
        case MotionMode::Returning:
            runReturn();
            break;
        case MotionMode::Homing:
            runHoming();
            break;
        case MotionMode::EmergencyStop:
        case MotionMode::Fault:
            followFeedback();
            break;
        case MotionMode::Idle:
            break;
    }
    if (m_mode != MotionMode::EmergencyStop && m_mode != MotionMode::Fault) {
        m_spindle.update(m_dt, std::fabs(m_interpolated[0]));
        writeOutputs();
    }
    m_status.mode = m_mode;
    m_status.commandedPosition = m_setpoint;
    m_status.actualPosition = actualTip();
    m_status.pathPosition = m_gen.state().s;
    m_status.pathVelocity = m_gen.state().v;
    m_status.feedOverride = m_feedOverride;
    m_status.rapidOverride = m_rapidOverride;
    m_status.spindleRpm = m_spindle.rpm();
    m_status.spindleAngleDeg = m_spindleSetpoint;
    m_status.queued = static_cast<uint32_t>(m_items.size());
    m_status.singleBlock = m_singleBlock;
    for (int j = 0; j < m_model.jointCount; ++j) {
        double error = std::fabs(m_setpoints[static_cast<size_t>(j)].position -
                                 m_feedback[static_cast<size_t>(j)].position);
        if (m_model.jointAxis[static_cast<size_t>(j)] >= 0) {
            m_status.maxFollowingError = std::max(m_status.maxFollowingError, error);
        }
    }
}

}  // namespace kerf::motion
