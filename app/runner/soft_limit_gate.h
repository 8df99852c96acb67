#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/canon/commands.h"
#include "motion/kinematics/machine_model.h"
#include "motion/runtime/work_area_check.h"

// The check before anything moves, for every machine a run drives (motion's simulated drives,
// the CAN drive chain): each command is checked against the soft limits and the planner's rules
// by motion::WorkAreaCheck (the check the HMI's test run makes too), and held back until the
// program ends or needs the machine (a sync point). A program that would leave the work area is
// refused before anything moves, with the block named (unless a sync point or a very long program
// released part of it before). One thread (the interpreter's).
namespace kerf::app {

class SoftLimitGate final : public canon::Sink {
public:
    // Commands held back at most; a longer program starts moving after this many (memory stays
    // bounded; the rest is still checked before it moves).
    static constexpr size_t kMaxHeldCommands = 200'000;

    explicit SoftLimitGate(const motion::MachineModel& model);

    // Where the program starts (workpiece coordinates), and where released commands go.
    void start(const motion::AxisVector& tip, canon::Sink& machine);
    void consume(const canon::Command& command) override;
    // The held commands go to the machine: they move (nothing once the program was refused).
    void release();
    // After the machine ran to a sync point: plan on from where it stands (after a probe move:
    // where the probe stopped).
    void resumeAt(const motion::AxisVector& tip);

    bool refused() const { return m_refusedAt.has_value(); }
    // Why the program was refused (nothing if it was not), in `file`; with a hint to give the
    // work offset when a soft limit refused it and the workpiece origin is the machine's.
    DiagnosticList refusal(const std::string& file, bool originAtMachineOrigin) const;
    const std::optional<SourceLocation>& refusedAt() const { return m_refusedAt; }
    motion::AxisVector position() const { return m_checker.position().values; }

private:
    motion::WorkAreaCheck m_checker;
    canon::Sink* m_machine = nullptr;
    std::vector<canon::Command> m_held;
    std::optional<SourceLocation> m_refusedAt;
};

// A refusal of the work-area check with a hint after each soft-limit error to give the work
// offset when the workpiece origin is the machine's (`kerf run --motion` and `kerf check`).
DiagnosticList withWorkOffsetHint(DiagnosticList refusal, bool originAtMachineOrigin);

}  // namespace kerf::app
