#pragma once

#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "app/runner/run_options.h"
#include "core/base/diagnostic.h"
#include "core/canon/commands.h"
#include "core/interp/interpreter.h"

namespace kerf::app {

struct Session;

// Parses --work-offset: axis letters with values, comma-separated ("X10,Y-5,Z-300"); nothing if
// malformed.
std::optional<Pose> parseWorkOffset(const std::string& text);

// `kerf run --motion` / `--samples FILE.csv`: the canonical stream the run consumes is executed by
// motion's planner and servo cycle on simulated drives in simulated time (docs/motion.md), and the
// report gets a "motion" object measured on the interpolated setpoints.
//
// The commands pass the SoftLimitGate: checked as they arrive and held back until the program
// ends or needs the machine (a sync point), so a program that would leave the work area is
// refused before anything moves.
class MotionOutput {
public:
    MotionOutput(const RunOptions& options, const Session& session);
    ~MotionOutput();
    MotionOutput(const MotionOutput&) = delete;
    MotionOutput& operator=(const MotionOutput&) = delete;

    bool active() const { return m_state != nullptr; }
    canon::Sink& sink();
    // Where the program starts (workpiece coordinates): the simulated machine is put there.
    void setStart(const Pose& start);
    // A soft limit or another planner rule refused the program: interpret no further.
    bool refused() const;
    // An emergency stop or a drive fault ended the program on the simulated machine.
    bool halted() const;
    // Executes everything so far: the world at a sync point (probe result, position).
    interp::WorldSnapshot drain();
    // After the run: executes the rest when the program ran (nothing when it was rejected) and
    // appends the refusal or motion errors to `problems`.
    void finish(bool programRan, DiagnosticList& problems);
    // After finish(): simulated time from the program's start until everything was executed.
    double machiningTimeS() const;
    // Adds "motion" to the report; positions like the report's (lathe X in diameter if so).
    void addToReport(nlohmann::json& report, bool xInDiameter) const;

private:
    struct State;
    std::unique_ptr<State> m_state;
};

}  // namespace kerf::app
