#include "tests/motion/sample_checker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/geometry/arc_math.h"

namespace kerf::motion::test {

namespace {

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    Vec3 ab = b - a;
    double len2 = ab.squaredNorm();
    double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + t * ab)).norm();
}

}  // namespace

SampleChecker::SampleChecker(const MachineModel& model, const Pose& start)
    : m_model(model),
      m_position(start),
      m_recentMoves(static_cast<size_t>(std::max(1, model.filterTaps)) + 1, 0) {}

void SampleChecker::addCommand(const canon::Command& command) {
    Move move;
    Pose target;
    if (const auto* rapid = std::get_if<canon::RapidMove>(&command.body)) {
        target = rapid->target;
    } else if (const auto* lin = std::get_if<canon::LinearMove>(&command.body)) {
        target = lin->target;
    } else if (const auto* synced = std::get_if<canon::SpindleSyncedMove>(&command.body)) {
        target = synced->target;
    } else if (const auto* probe = std::get_if<canon::ProbeMove>(&command.body)) {
        target = probe->target;
    } else if (const auto* arc = std::get_if<canon::ArcMove>(&command.body)) {
        target = arc->target;
        PlaneAxes axes = planeAxes(arc->plane);
        move.arc = true;
        move.f = axisIndex(axes.first);
        move.s = axisIndex(axes.second);
        move.n = axisIndex(axes.normal);
        move.center = arc->center;
        const Vec3 from = m_position.xyz();
        move.radius =
            std::hypot(from[move.f] - arc->center[move.f], from[move.s] - arc->center[move.s]);
        move.phi0 =
            std::atan2(from[move.s] - arc->center[move.s], from[move.f] - arc->center[move.f]);
        move.sweep = arc->sweepRad;
    } else {
        return;
    }
    bool moves = false;
    for (size_t i = 0; i < target.values.size(); ++i) {
        if (std::fabs(target.values[i] - m_position.values[i]) > 1e-9) moves = true;
    }
    move.start = m_position.xyz();
    move.end = target.xyz();
    m_position = target;
    if (moves) m_moves.push_back(move);
}

double SampleChecker::distanceTo(const Move& move, const Vec3& p) {
    if (!move.arc) return distanceToSegment(p, move.start, move.end);
    auto pointAt = [&](double u) {
        Vec3 q = move.start;
        const double phi = move.phi0 + u * move.sweep;
        q[move.f] = move.center[move.f] + move.radius * std::cos(phi);
        q[move.s] = move.center[move.s] + move.radius * std::sin(phi);
        q[move.n] = move.start[move.n] + u * (move.end[move.n] - move.start[move.n]);
        return q;
    };
    auto dist = [&](double u) { return (p - pointAt(u)).norm(); };
    const double rise = move.end[move.n] - move.start[move.n];
    const double planar =
        std::hypot(p[move.f] - move.center[move.f], p[move.s] - move.center[move.s]);
    if (rise == 0.0) {
        // A circle: the nearest point is at p's angle in the plane (on any turn) or an end.
        double best = std::min(dist(0.0), dist(1.0));
        if (planar == 0.0) return best;
        const double theta =
            std::atan2(p[move.s] - move.center[move.s], p[move.f] - move.center[move.f]);
        const double direction = move.sweep < 0.0 ? -1.0 : 1.0;
        double along = std::fmod(direction * (theta - move.phi0), kTwoPi);
        if (along < 0.0) along += kTwoPi;
        for (; along <= std::fabs(move.sweep); along += kTwoPi)
            best = std::min(best, dist(along / std::fabs(move.sweep)));
        return best;
    }
    // A helix: scan 32 points per turn, then a golden-section search around the nearest one.
    const int count =
        std::max(32, static_cast<int>(std::ceil(std::fabs(move.sweep) / kTwoPi * 32)));
    int nearest = 0;
    double best = dist(0.0);
    for (int i = 1; i <= count; ++i) {
        const double d = dist(static_cast<double>(i) / count);
        if (d < best) {
            best = d;
            nearest = i;
        }
    }
    double lo = std::max(0.0, (nearest - 1.0) / count);
    double hi = std::min(1.0, (nearest + 1.0) / count);
    for (int i = 0; i < 50; ++i) {
        const double m1 = lo + (hi - lo) * 0.381966;
        const double m2 = hi - (hi - lo) * 0.381966;
        if (dist(m1) < dist(m2))
            hi = m2;
        else
            lo = m1;
    }
    best = std::min(best, dist(0.5 * (lo + hi)));
    return best;
}

double SampleChecker::deviation(const Sample& sample, size_t firstMove) const {
    if (sample.moveIndex == 0 || m_moves.empty()) return 0.0;
    Vec3 p(sample.tip[0], sample.tip[1], sample.tip[2]);
    double best = 1e300;
    size_t last = std::min<size_t>(sample.moveIndex + 1, m_moves.size());
    size_t first = std::clamp<size_t>(firstMove, 1, last);
    for (size_t m = first; m <= last; ++m)
        best = std::min(best, distanceTo(m_moves[m - 1], p));
    return best;
}

void SampleChecker::addSample(const Sample& sample) {
    const double dt = m_model.periodS;
    for (size_t i = 0; i < m_model.axes.size(); ++i) {
        if (!m_model.axes[i].enabled) continue;
        AxisPeaks& peaks = m_peaks[i];
        const double x0 = sample.joints[i];
        if (m_count >= 1)
            peaks.velocity = std::max(peaks.velocity, std::fabs(x0 - m_history[0][i]) / dt);
        if (m_count >= 2) {
            peaks.accel = std::max(
                peaks.accel, std::fabs(x0 - 2 * m_history[0][i] + m_history[1][i]) / (dt * dt));
        }
        if (m_count >= 3) {
            double third = x0 - 3 * m_history[0][i] + 3 * m_history[1][i] - m_history[2][i];
            peaks.jerk = std::max(peaks.jerk, std::fabs(third) / (dt * dt * dt));
        }
    }
    m_history[2] = m_history[1];
    m_history[1] = m_history[0];
    m_history[0] = sample.joints;
    ++m_count;
    // An element fitted to several programmed moves stands for all of them.
    m_recentMoves[m_recentNext] =
        sample.firstMoveIndex > 0 ? sample.firstMoveIndex : sample.moveIndex;
    m_recentNext = (m_recentNext + 1) % m_recentMoves.size();
    uint32_t oldest = sample.moveIndex;
    for (uint32_t index : m_recentMoves) {
        if (index != 0) oldest = std::min(oldest, index);
    }
    // From the move before the oldest: a blend starts at its end.
    m_maxDeviation = std::max(m_maxDeviation, deviation(sample, oldest > 1 ? oldest - 1 : 1));
}

double SampleChecker::worstLimitRatio() const {
    double worst = 0.0;
    for (size_t i = 0; i < m_model.axes.size(); ++i) {
        const AxisModel& a = m_model.axes[i];
        if (!a.enabled) continue;
        worst = std::max({worst, m_peaks[i].velocity / a.velocity, m_peaks[i].accel / a.accel,
                          m_peaks[i].jerk / a.jerk});
    }
    return worst;
}

std::string SampleChecker::limitSummary() const {
    std::string out;
    for (size_t i = 0; i < m_model.axes.size(); ++i) {
        const AxisModel& a = m_model.axes[i];
        if (!a.enabled) continue;
        char buffer[128];
        std::snprintf(buffer, sizeof buffer, "%c v %.4f a %.4f j %.4f; ",
                      axisLetter(static_cast<Axis>(i)), m_peaks[i].velocity / a.velocity,
                      m_peaks[i].accel / a.accel, m_peaks[i].jerk / a.jerk);
        out += buffer;
    }
    return out;
}

}  // namespace kerf::motion::test
