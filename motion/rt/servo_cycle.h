#pragma once

#include <array>

#include "motion/kinematics/machine_model.h"
#include "motion/port/drive_bus.h"
#include "motion/port/motion_item.h"
#include "motion/port/motion_status.h"
#include "motion/port/operator_command.h"
#include "motion/port/spsc_ring.h"
#include "motion/rt/contour_return.h"
#include "motion/rt/joint_mover.h"
#include "motion/rt/moving_average.h"
#include "motion/rt/path_generator.h"
#include "motion/rt/spindle_channel.h"

// The servo cycle: one call per period runs the pipeline read feedback -> check faults ->
// operator commands -> interpolate (program, jog, homing) -> spindle -> smoothing filter ->
// joints -> write setpoints -> status. Constructed and start()ed in a normal thread before the
// RT thread runs; cycle() and the accessors are for the RT thread only (or the simulation
// thread, which plays that role). No allocation, no locks, no I/O, no clock reads in cycle().
namespace kerf::motion {

inline constexpr size_t kItemRingCapacity = 4096;
using ItemRing = SpscRing<MotionItem, kItemRingCapacity>;
using CommandRing = SpscRing<OperatorCommand, 64>;
using EventRing = SpscRing<MotionEvent, 1024>;

class ServoCycle {
public:
    ServoCycle(const MachineModel& model, DriveBus& bus, ItemRing& items, CommandRing& commands,
               EventRing& events);

    // Takes the drives' positions as the start and enables them (normal thread, before cycling).
    void start() noexcept;
    void cycle() noexcept;

    const MotionStatus& status() const noexcept { return m_status; }
    // Setpoint (after the filter) and interpolated point (before it), tool tip coordinates.
    const AxisVector& setpoint() const noexcept { return m_setpoint; }
    const AxisVector& interpolated() const noexcept { return m_interpolated; }
    // The interpolator is on a feed move (not rapid) of the program.
    bool onFeedMove() const noexcept { return m_onFeedMove; }
    // Spindle angle setpoint after the filter (in step with setpoint()).
    double spindleSetpointDeg() const noexcept { return m_spindleOutput; }
    // Joint setpoints written this cycle (index = joint).
    const std::array<JointSetpoint, kMaxJoints>& jointSetpoints() const noexcept {
        return m_setpoints;
    }
    // Programmed move the interpolator is on (PathElement::moveIndex; 0 outside a program move).
    uint32_t currentMove() const noexcept { return m_currentMove; }
    // The first programmed move the current element stands for (PathElement::firstMoveIndex).
    uint32_t currentFirstMove() const noexcept { return m_currentFirstMove; }
    double pathS() const noexcept { return m_gen.state().s; }
    // Timing measured by the thread that calls cycle().
    void noteTiming(bool late, double cpuS) noexcept;

private:
    // The axes and the spindle go through the same moving average (a synchronised spindle stays
    // locked to the axes); separate instances, so the axes can settle while the spindle turns.
    using Filter = MovingAverage<256, kAxisCount>;
    using SpindleFilter = MovingAverage<256, 1>;

    void readFeedback() noexcept;
    void processCommands() noexcept;
    void handle(const OperatorCommand& command) noexcept;
    void runProgram() noexcept;
    bool runAction(const MotionItem& item) noexcept;
    void stepPath() noexcept;
    void chooseSingleBlockStop() noexcept;
    // Whether single block stops at the end of queued element `index`: where its programmed
    // block ends and the next move queued (if any) belongs to another.
    bool endsSingleBlockStep(size_t index) const noexcept;
    // After the last move or action of a single-block step: whether `item` still belongs to the
    // step (an action of the same block that acts at the end of the block, M5, M9, M30 ...; the
    // move of a block whose actions act before it).
    bool continuesStep(const MotionItem& item) const noexcept;
    // Whether a block whose last item is `action` ends a single-block step there when every
    // block is a step (FAGOR): a dwell, a tool, spindle, coolant or M function block.
    static bool endsStepAlone(const Action& action) noexcept;
    // The single-block stop once the step's moves and actions are done.
    void stopAfterStep() noexcept;
    size_t collectConstraints(size_t first, std::span<Constraint> out) const noexcept;
    void enterElement(const PathElement& element) noexcept;
    void runManual() noexcept;
    bool moveManualAxis() noexcept;
    void runReturn() noexcept;
    void runHoming() noexcept;
    void nextHomingJoint() noexcept;
    void followFeedback() noexcept;
    void writeOutputs() noexcept;
    void abortProgram() noexcept;
    void enterEmergencyStop() noexcept;  // quick stop, program aborted, drives off until Reset
    void stopSpindleAndCoolant() noexcept;
    bool manualFunctionsAllowed() const noexcept;  // no program queued, running or waiting
    double liveFeed(FeedKind kind, double feed) const noexcept;
    // What the interpolator moves towards on element e: its cap and live feed, 0 when stopping.
    double targetVelocity(const PathElement& e) const noexcept;
    void emit(MotionEventKind kind, int joint, double value, const AxisVector& position) noexcept;
    AxisVector actualTip() const noexcept;
    bool filterSettled() const noexcept { return m_filter.settled(); }
    Limits axisLimits(int axis) const noexcept;

    const MachineModel& m_model;
    DriveBus& m_bus;
    ItemRing& m_items;
    CommandRing& m_commands;
    EventRing& m_events;
    double m_dt;

    std::array<JointFeedback, kMaxJoints> m_feedback{};
    std::array<JointSetpoint, kMaxJoints> m_setpoints{};
    MotionStatus m_status;
    MotionMode m_mode = MotionMode::Idle;
    Filter m_filter;
    SpindleFilter m_spindleFilter;
    PathGenerator m_gen;
    SpindleChannel m_spindle;
    JointMover m_mover;
    ContourReturn m_return;  // where the operator left an interrupted program

    AxisVector m_interpolated{};
    AxisVector m_setpoint{};
    double m_spindleSetpoint = 0.0;  // before the filter
    double m_spindleOutput = 0.0;
    double m_toolLength = 0.0;
    double m_feedOverride = 1.0;
    double m_rapidOverride = 1.0;
    bool m_singleBlock = false;
    bool m_everyBlockSteps = false;  // single block stops after blocks without a move too
    bool m_optionalStop = false;
    bool m_hold = false;
    bool m_stopping = false;
    bool m_waitingStart = false;
    bool m_onFeedMove = false;
    uint32_t m_currentMove = 0;
    uint32_t m_currentFirstMove = 0;
    bool m_elementEntered = false;
    bool m_actionStarted = false;
    double m_actionTimer = 0.0;
    double m_syncAngleStart = 0.0;
    bool m_probeArmed = false;
    bool m_probeTriggered = false;
    double m_singleBlockS = -1.0;  // path position of the single-block stop ahead
    // The last move of a single-block step has ended: the block's remaining actions run, then
    // the stop (stopAfterStep). m_stepEnd is the step's place.
    bool m_stepEndPending = false;
    SourceLocation m_stepEnd;

    // Homing: joints in the model's homing order, one at a time.
    enum class HomingPhase : uint8_t { Off, LeaveSwitch, Search, Brake, Return };
    HomingPhase m_homingPhase = HomingPhase::Off;
    int m_homingJoint = -1;
    int m_homingStep = 0;  // index in MachineModel::homingOrder
    int m_homingOnly = -1;
    double m_homingLatch = 0.0;
};

}  // namespace kerf::motion
