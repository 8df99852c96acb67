#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "core/canon/commands.h"
#include "core/machine/machine_config.h"

namespace kerf::task {

// Times a canonical stream as the machine executes it: the machining time of the test run and of
// `kerf run`'s report. Motion implements it with its planner and servo cycle in simulated time
// (docs/motion.md), app injects it; core and ui see only this interface. One thread.
class MachiningClock : public canon::Sink {
public:
    // Where the program starts (workpiece coordinates); before the first command.
    virtual void setStart(const Pose& start) = 0;
    // A sync point: the machine executes everything consumed so far and stands still there.
    virtual void sync() = 0;
    // The program ended: executes the rest.
    virtual void finish() = 0;
    // After finish(): seconds from the program's start at which each consumed command was done,
    // in order (non-decreasing). Commands without motion end with the move before them, but
    // for the last one before a move, which takes the time until that move begins (a dwell).
    virtual std::vector<double> endTimesS() const = 0;
    // After finish(): the whole program's machining time.
    virtual double totalS() const = 0;
};

// Makes a clock for a machine; empty where none is wired (then nothing reports a time).
using MachiningClockFactory =
    std::function<std::unique_ptr<MachiningClock>(const machine::MachineConfig&)>;

}  // namespace kerf::task
