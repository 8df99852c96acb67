#include "motion/sim/motion_recorder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kerf::motion {

MotionRecorder::MotionRecorder(const MachineModel& model)
    : m_model(model), m_recentMoves(static_cast<size_t>(std::max(1, model.filterTaps)) + 1, 0) {}

bool MotionRecorder::writeCsv(const std::string& path) {
    m_csv.open(path);
    if (!m_csv) return false;
    m_csv << "t_s";
    for (size_t i = 0; i < m_model.axes.size(); ++i) {
        if (m_model.axes[i].enabled) m_csv << ',' << axisLetter(static_cast<Axis>(i));
    }
    m_csv << ",spindle_deg,path_velocity,move\n";
    return true;
}

void MotionRecorder::addProgrammedMove(uint32_t index, const PathGeometry& geometry) {
    m_moves.emplace_back(index, geometry);
}

uint32_t MotionRecorder::oldestRecentMove(uint32_t current) const {
    uint32_t oldest = current;
    for (uint32_t index : m_recentMoves) {
        if (index != 0) oldest = std::min(oldest, index);
    }
    return oldest;
}

double MotionRecorder::deviationOf(const Sample& sample, uint32_t from) const {
    Vec3Array p{sample.tip[0], sample.tip[1], sample.tip[2]};
    double best = 1e300;
    for (const auto& [index, geometry] : m_moves) {
        if (index < from) continue;
        if (index > sample.moveIndex + 1) break;
        best = std::min(best, distanceTo(geometry, p, 0.0, geometry.length));
    }
    return best == 1e300 ? 0.0 : best;
}

void MotionRecorder::record(const Sample& sample) {
    const double dt = m_model.periodS;
    for (size_t i = 0; i < m_model.axes.size(); ++i) {
        if (!m_model.axes[i].enabled) continue;
        AxisExtremes& e = m_axes[i];
        double x0 = sample.joints[i];
        if (m_count >= 1) {
            double x1 = m_history[0][i];
            e.maxVelocity = std::max(e.maxVelocity, std::fabs(x0 - x1) / dt);
        }
        if (m_count >= 2) {
            double a = (x0 - 2.0 * m_history[0][i] + m_history[1][i]) / (dt * dt);
            e.maxAccel = std::max(e.maxAccel, std::fabs(a));
        }
        if (m_count >= 3) {
            double j = (x0 - 3.0 * m_history[0][i] + 3.0 * m_history[1][i] - m_history[2][i]) /
                       (dt * dt * dt);
            e.maxJerk = std::max(e.maxJerk, std::fabs(j));
        }
    }
    m_history[2] = m_history[1];
    m_history[1] = m_history[0];
    m_history[0] = sample.joints;
    ++m_count;

    if (sample.onFeedMove) {
        if (m_feedStart < 0.0) m_feedStart = sample.timeS - dt;
        m_feedEnd = sample.timeS;
    }
    m_recentMoves[m_recentNext] =
        sample.firstMoveIndex > 0 ? sample.firstMoveIndex : sample.moveIndex;
    m_recentNext = (m_recentNext + 1) % m_recentMoves.size();
    if (sample.moveIndex > 0 && !m_moves.empty()) {
        // The move before the oldest one too: its end is the corner a blend starts from.
        const uint32_t oldest = oldestRecentMove(sample.moveIndex);
        const uint32_t from = oldest > 1 ? oldest - 1 : 0;
        m_maxDeviation = std::max(m_maxDeviation, deviationOf(sample, from));
        while (!m_moves.empty() && m_moves.front().first < from)
            m_moves.pop_front();
    }
    if (m_csv.is_open()) {
        char buffer[48];
        std::snprintf(buffer, sizeof buffer, "%.6f", sample.timeS);
        m_csv << buffer;
        for (size_t i = 0; i < m_model.axes.size(); ++i) {
            if (!m_model.axes[i].enabled) continue;
            std::snprintf(buffer, sizeof buffer, ",%.9f", sample.tip[i]);
            m_csv << buffer;
        }
        std::snprintf(buffer, sizeof buffer, ",%.6f,%.6f,%u\n", sample.spindleDeg,
                      sample.pathVelocity, sample.moveIndex);
        m_csv << buffer;
    }
}

double MotionRecorder::feedTimeS() const {
    if (m_feedStart < 0.0) return 0.0;
    // The setpoints reach the end of the last feed move one filter length after the
    // interpolator does.
    return m_feedEnd - m_feedStart + m_model.filterTimeS();
}

}  // namespace kerf::motion
