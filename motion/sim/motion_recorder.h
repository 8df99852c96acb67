#pragma once

#include <cstdint>
#include <deque>
#include <fstream>
#include <string>
#include <vector>

#include "motion/kinematics/machine_model.h"
#include "motion/path/path_geometry.h"

// Measures the executed motion on the sampled setpoints, as a drive would receive them: per-axis
// velocity, acceleration and jerk by finite differences of the joint setpoints, the distance of
// the tool tip setpoint from the programmed path, and the feed time. Optionally writes every
// sample to a CSV file. Runs in the simulation thread, after each servo cycle.
namespace kerf::motion {

struct AxisExtremes {
    double maxVelocity = 0.0;
    double maxAccel = 0.0;
    double maxJerk = 0.0;
};

struct Sample {
    double timeS = 0.0;
    AxisVector joints{};  // joint setpoints by axis index (machine coordinates)
    AxisVector tip{};     // tool tip setpoint, workpiece coordinates
    double spindleDeg = 0.0;
    double pathVelocity = 0.0;
    uint32_t moveIndex = 0;       // programmed move being interpolated (0: none)
    uint32_t firstMoveIndex = 0;  // the first one the element being interpolated stands for
    bool onFeedMove = false;
};

class MotionRecorder {
public:
    explicit MotionRecorder(const MachineModel& model);

    // Samples to a CSV file from now on; false if the file cannot be opened.
    bool writeCsv(const std::string& path);
    // A programmed move, in order: index and geometry (workpiece coordinates).
    void addProgrammedMove(uint32_t index, const PathGeometry& geometry);
    void record(const Sample& sample);

    const AxisExtremes& axis(int index) const { return m_axes[static_cast<size_t>(index)]; }
    double maxPathDeviation() const { return m_maxDeviation; }
    double feedTimeS() const;
    uint64_t samples() const { return m_count; }

private:
    double deviationOf(const Sample& sample, uint32_t from) const;
    uint32_t oldestRecentMove(uint32_t current) const;

    const MachineModel& m_model;
    std::array<AxisExtremes, kAxisCount> m_axes{};
    std::array<AxisVector, 3> m_history{};  // previous joint setpoints, newest first
    uint64_t m_count = 0;
    double m_maxDeviation = 0.0;
    double m_feedStart = -1.0;
    double m_feedEnd = -1.0;
    std::deque<std::pair<uint32_t, PathGeometry>> m_moves;
    // The interpolator's move of the last filter length of samples (ring): the smoothed setpoint
    // is an average of the interpolator positions on these moves.
    std::vector<uint32_t> m_recentMoves;
    size_t m_recentNext = 0;
    std::ofstream m_csv;
};

}  // namespace kerf::motion
