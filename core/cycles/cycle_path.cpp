#include "core/cycles/cycle_path.h"

#include "core/geometry/spatial_arc.h"

namespace kerf::cycles {

namespace {
constexpr double kSamePosition = 1e-9;
}

bool CyclePath::count() {
    if (m_count >= kMoveLimit) return false;
    ++m_count;
    return true;
}

void CyclePath::rapid(const Vec3& target) {
    if ((target - m_at).norm() <= kSamePosition || !count()) return;
    m_out.rapid(target);
    m_at = target;
}

void CyclePath::move(const Vec3& target, const Feed& feed) {
    if (feed.isRapid()) {
        rapid(target);
        return;
    }
    if ((target - m_at).norm() <= kSamePosition || !count()) return;
    m_out.line(target, feed);
    m_at = target;
}

void CyclePath::arc(const Vec3& target, const Vec2& center, double sweepRad, const Feed& feed) {
    if (sweepRad == 0.0 || !count()) return;
    m_out.arc(target, center, sweepRad, feed);
    m_at = target;
}

void CyclePath::spatialArc(const Vec3& target, const Vec3& centre, const Feed& feed) {
    if ((target - m_at).norm() <= kSamePosition || !count()) return;
    m_out.spatialArc(m_at, target, centre, feed);
    m_at = target;
}

void CycleEmitter::spatialArc(const Vec3& from, const Vec3& target, const Vec3& centre,
                              const Feed& feed) {
    for (const Vec3& p : arcChordPoints(from, target, centre, kSpatialArcTolerance))
        line(p, feed);
}

void CyclePath::threadMove(const Vec3& target, double leadMm, double startAngleDeg) {
    if ((target - m_at).norm() <= kSamePosition || !count()) return;
    m_out.threadMove(target, leadMm, startAngleDeg);
    m_at = target;
}

void CyclePath::dwell(double seconds) {
    if (seconds > 0.0 && count()) m_out.dwell(seconds);
}

void CyclePath::spindle(canon::SpindleDirection direction, double rpm) {
    if (count()) m_out.spindle(direction, rpm);
}

void CyclePath::orientSpindle(double angleDeg) {
    if (count()) m_out.orientSpindle(angleDeg);
}

void CyclePath::miscFunction(int number) {
    if (count()) m_out.miscFunction(number);
}

}  // namespace kerf::cycles
