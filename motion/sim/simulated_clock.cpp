#include "motion/sim/simulated_clock.h"

#include <algorithm>

namespace kerf::motion {

namespace {

// Far beyond any machine: the clock times programs that leave the work area too.
constexpr double kOpenLimit = 1e9;

machine::MachineConfig withoutSoftLimits(machine::MachineConfig config) {
    for (machine::AxisConfig& axis : config.axes) {
        axis.minLimit = -kOpenLimit;
        axis.maxLimit = kOpenLimit;
    }
    return config;
}

}  // namespace

SimulatedClock::SimulatedClock(const machine::MachineConfig& config)
    : m_config(withoutSoftLimits(config)) {}

SimulatedClock::~SimulatedClock() = default;

void SimulatedClock::setStart(const Pose& start) {
    SimulationOptions options;
    options.startPosition = start.values;
    options.measure = false;
    options.onSample = [this](const Sample& sample, const MotionStatus&) {
        observe(sample.timeS, sample.moveIndex);
    };
    m_machine = std::make_unique<SimulatedMachine>(m_config, std::move(options));
    m_startS = m_machine->timeS();
}

void SimulatedClock::consume(const canon::Command& command) {
    if (!m_machine) setStart(Pose{});
    const uint32_t before = m_machine->acceptedMoves();
    m_machine->consume(command);
    m_movesAfter.push_back(m_machine->acceptedMoves());
    m_isMove.push_back(m_machine->acceptedMoves() != before);
}

void SimulatedClock::observe(double timeS, uint32_t move) {
    if (move == m_currentMove) return;
    // The change happened within the cycle that ends at `timeS`.
    const double t = std::max(0.0, sinceStart(timeS) - m_machine->model().periodS);
    // Moves run in order: on a move, every one before it is done; between moves (an action, the
    // end), every one begun is.
    const uint32_t done = move > 0 ? move - 1 : m_highestMove;
    while (m_moveEndS.size() < done)
        m_moveEndS.push_back(t);
    while (m_moveStartS.size() < move)
        m_moveStartS.push_back(t);
    m_highestMove = std::max(m_highestMove, move);
    m_currentMove = move;
}

void SimulatedClock::sync() {
    if (m_machine) m_machine->drain();
}

void SimulatedClock::finish() {
    if (!m_machine) return;
    m_machine->drain();
    m_totalS = sinceStart(m_machine->timeS());
    const size_t moves = m_machine->acceptedMoves();
    m_moveStartS.resize(std::max(m_moveStartS.size(), moves), m_totalS);
    m_moveEndS.resize(std::max(m_moveEndS.size(), moves), m_totalS);
}

std::vector<double> SimulatedClock::endTimesS() const {
    std::vector<double> times;
    times.reserve(m_movesAfter.size());
    double last = 0.0;
    for (size_t i = 0; i < m_movesAfter.size(); ++i) {
        const size_t moves = m_movesAfter[i];
        double t = m_totalS;
        if (m_isMove[i]) {
            t = m_moveEndS[moves - 1];
        } else if (i + 1 < m_movesAfter.size() && !m_isMove[i + 1]) {
            // Settings (BLK FORM, feed mode...) take no time: done with the move before.
            t = moves > 0 ? m_moveEndS[moves - 1] : 0.0;
        } else if (moves < m_moveStartS.size()) {
            // The last command before a move takes the time until the move begins (a dwell,
            // the spindle coming up to speed).
            t = m_moveStartS[moves];
        }
        last = std::clamp(t, last, m_totalS);
        times.push_back(last);
    }
    return times;
}

std::unique_ptr<task::MachiningClock> makeSimulatedClock(const machine::MachineConfig& config) {
    return std::make_unique<SimulatedClock>(config);
}

}  // namespace kerf::motion
