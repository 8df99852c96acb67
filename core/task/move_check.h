#pragma once

#include <functional>
#include <memory>

#include "core/base/diagnostic.h"
#include "core/canon/commands.h"

namespace kerf::task {

// Whether the machine would take a program's commands, judged before they move: the soft limits
// of the work area (with the workpiece origin and the tool length) and the motion planner's
// rules, exactly as Program run judges them. motion/ implements it over its planner (executing
// nothing); the test run and `kerf run` use it, the ui through the factory app/ hands it.
// One thread.
class MoveCheck {
public:
    virtual ~MoveCheck() = default;

    // Where the tool tip stands before the first command (workpiece coordinates).
    virtual void start(const Pose& tip) = 0;
    // False when the machine would refuse this command; refusal() then says why, naming the
    // block. After a refusal every further command is refused.
    virtual bool accept(const canon::Command& command) = 0;
    // After a sync point: where the tool tip stands now.
    virtual void resumeAt(const Pose& tip) = 0;
    // Where the tool tip is after the commands accepted so far.
    virtual Pose position() const = 0;
    virtual bool refused() const = 0;
    // Why the machine refused (the diagnostics carry line and column, not the file).
    virtual DiagnosticList refusal() const = 0;
};

// A check for programs whose workpiece origin lies at `originInMachine` (machine coordinates).
using MoveCheckFactory = std::function<std::unique_ptr<MoveCheck>(const Pose& originInMachine)>;

}  // namespace kerf::task
