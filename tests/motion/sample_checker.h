#pragma once

#include <string>
#include <vector>

#include "core/canon/commands.h"
#include "motion/kinematics/machine_model.h"
#include "motion/port/motion_status.h"
#include "motion/sim/motion_recorder.h"

// Independent checks of the sampled setpoints, for the invariant tests: per-axis velocity,
// acceleration and jerk by finite differences of the joint setpoints, and the distance of the tool
// tip setpoint from the programmed path (lines exact; arcs and helices by a scan and a
// golden-section search), computed here from the canonical
// commands, not by the code under test.
namespace kerf::motion::test {

struct AxisPeaks {
    double velocity = 0.0;
    double accel = 0.0;
    double jerk = 0.0;
};

class SampleChecker {
public:
    SampleChecker(const MachineModel& model, const Pose& start);

    // The programmed moves, in order (zero-length moves are skipped, as the planner does).
    void addCommand(const canon::Command& command);
    void addSample(const Sample& sample);

    const AxisPeaks& axis(int index) const { return m_peaks[static_cast<size_t>(index)]; }
    double maxDeviation() const { return m_maxDeviation; }
    size_t samples() const { return m_count; }
    // "X v 1.003 ..." for failure messages: the worst ratio to the limit per axis and quantity.
    std::string limitSummary() const;
    // Largest ratio measured / limit over all axes and quantities.
    double worstLimitRatio() const;

private:
    // A programmed move: a line from `start` to `end`, or an arc about `center` in the plane
    // of axes f, s (normal n moving linearly with the angle).
    struct Move {
        Vec3 start;
        Vec3 end;
        bool arc = false;
        Vec3 center;
        double radius = 0.0;
        double phi0 = 0.0;
        double sweep = 0.0;
        int f = 0;
        int s = 1;
        int n = 2;
    };
    static double distanceTo(const Move& move, const Vec3& p);
    double deviation(const Sample& sample, size_t firstMove) const;

    const MachineModel& m_model;
    Pose m_position;
    std::vector<Move> m_moves;  // index = move number - 1
    std::array<AxisPeaks, kAxisCount> m_peaks{};
    std::array<AxisVector, 3> m_history{};
    size_t m_count = 0;
    // Move of each of the last filter length of samples: the smoothed setpoint averages
    // interpolator positions on these moves (and the corners between them).
    std::vector<uint32_t> m_recentMoves;
    size_t m_recentNext = 0;
    double m_maxDeviation = 0.0;
};

}  // namespace kerf::motion::test
