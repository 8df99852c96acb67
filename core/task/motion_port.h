#pragma once

#include <optional>
#include <string>

#include "core/canon/commands.h"
#include "core/interp/interpreter.h"
#include "core/task/machine_status.h"

namespace kerf::task {

// What the task needs from motion (implemented over the real-time motion thread, simulated
// time, or nothing at all for a test run). Called from the task thread only.
class MotionPort {
public:
    enum class State : uint8_t { Idle, Running, Held, Stopped, Faulted };

    struct Progress {
        State state = State::Idle;
        SourceLocation block;  // the block being executed
        std::string fault;     // why, when Faulted
    };

    virtual ~MotionPort() = default;

    // Plans a command; false when motion refuses it (fault() then says why).
    virtual bool submit(const canon::Command& command) = 0;
    // Whether more commands may be submitted now (bounded queues).
    virtual bool hasRoom() const = 0;
    // Releases what the look-ahead holds back (sync points, program end).
    virtual void flush() = 0;
    // Moves planned work towards execution; call regularly.
    virtual void pump() = 0;
    // Everything submitted has been executed and the axes stand still.
    virtual bool drained() const = 0;
    virtual interp::WorldSnapshot world() const = 0;
    virtual Progress progress() const = 0;
    // A probe move ends where the machine's probe input latched (world().probePosition), not at
    // its programmed end point: the TNC probing cycles take their touches from it.
    virtual bool latchesProbe() const { return false; }

    virtual void cycleStart() = 0;
    virtual void feedHold() = 0;
    virtual void quickStop() = 0;  // stop on the path and discard what is queued
    // Emergency stop: the drives stop by themselves and are disabled, the program is aborted,
    // the spindle and the coolant go off. machineOn() enables the drives again (after an
    // emergency stop or a drive fault); false when there is nothing to switch on. The defaults
    // suit a port without a machine.
    virtual void emergencyStop() {}
    virtual bool machineOn() { return false; }
    // The simulated machine's emergency-stop button, which latches like the mushroom button on
    // a machine: pressed, its chain opens and the servo cycle stops everything at once and keeps
    // the drives off until it is released and the machine switched on. False where there is no
    // simulated button (real drives: their chain is wired, not simulated).
    virtual bool setEmergencyStopButton(bool /*pressed*/) { return false; }
    virtual void setSingleBlock(bool on) = 0;
    // Whether single block also stops after a block without a move (a dwell, an M, S or T
    // function alone), as the FAGOR 8035 does; otherwise such a block runs with the next one.
    virtual void setSingleBlockEveryBlock(bool /*on*/) {}

    // What the HMI needs beyond a program run. The defaults suit a port without a machine
    // (test run, tests): overrides are ignored, manual motion is refused (false), and the status
    // is derived from world() and progress().

    // Fractions: feed 0..1.5, rapid 0..1, spindle 0..1.5; motion changes speed within its limits.
    virtual void setFeedOverride(double) {}
    virtual void setRapidOverride(double) {}
    virtual void setSpindleOverride(double) {}
    // Manual operation while nothing runs. Velocity as a fraction of the axis' maximum (signed).
    virtual bool jogContinuous(Axis, double /*velocityFraction*/) { return false; }
    virtual bool jogStop(Axis) { return false; }
    virtual bool jogIncrement(Axis, double /*distance*/) { return false; }
    // Every axis in the machine's order (nullopt) or one axis.
    virtual bool home(std::optional<Axis>) { return false; }
    // Spindle and coolant in manual operation: executed as canonical commands.
    virtual bool manualSpindle(const canon::SpindleControl& spindle);
    virtual bool manualCoolant(const canon::CoolantControl& coolant);
    virtual MachineStatus status() const;
};

}  // namespace kerf::task
