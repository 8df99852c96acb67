#pragma once

#include <memory>
#include <vector>

#include "core/task/machining_clock.h"
#include "motion/sim/simulated_machine.h"

// The machining clock of the test run and of `kerf run`'s report: the program runs through the
// planner and the servo cycle on simulated drives in simulated time, exactly as `kerf run
// --motion` runs it, and each command's end is read off the servo cycle's programmed move.
// Stops (M0, M1) continue at once; the work area is not checked (the clock only times the
// program). One thread.
namespace kerf::motion {

class SimulatedClock final : public task::MachiningClock {
public:
    explicit SimulatedClock(const machine::MachineConfig& config);
    ~SimulatedClock() override;

    void setStart(const Pose& start) override;
    void consume(const canon::Command& command) override;
    void sync() override;
    void finish() override;
    std::vector<double> endTimesS() const override;
    double totalS() const override { return m_totalS; }

private:
    // After each servo cycle: the programmed move being interpolated at `timeS`.
    void observe(double timeS, uint32_t move);
    double sinceStart(double timeS) const { return timeS - m_startS; }

    machine::MachineConfig m_config;
    std::unique_ptr<SimulatedMachine> m_machine;
    double m_startS = 0.0;
    double m_totalS = 0.0;
    // Per command: the number of moves the planner had accepted after it, and whether it was
    // a move itself.
    std::vector<uint32_t> m_movesAfter;
    std::vector<bool> m_isMove;
    // Per programmed move (index - 1): when the servo cycle began it and was past it.
    std::vector<double> m_moveStartS;
    std::vector<double> m_moveEndS;
    uint32_t m_currentMove = 0;
    uint32_t m_highestMove = 0;
};

// The factory app injects into the test run and the runner.
std::unique_ptr<task::MachiningClock> makeSimulatedClock(const machine::MachineConfig& config);

}  // namespace kerf::motion
