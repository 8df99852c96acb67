#pragma once

#include <cstddef>

#include "core/cycles/cycle_context.h"

namespace kerf::cycles {

// Emits a cycle's moves while tracking the tool position. A step that would not move the tool
// emits nothing, so hand-derived traces list only real moves. The number of moves is capped: a
// cycle whose parameters would need more stops with an error instead of running for hours.
class CyclePath {
public:
    static constexpr size_t kMoveLimit = 100000;

    CyclePath(CycleEmitter& emitter, const Vec3& start) : m_out(emitter), m_at(start) {}

    const Vec3& position() const { return m_at; }
    double w() const { return m_at.z(); }
    Vec2 uv() const { return {m_at.x(), m_at.y()}; }

    void rapid(const Vec3& target);
    void rapidW(double w) { rapid({m_at.x(), m_at.y(), w}); }
    void rapidUv(const Vec2& p) { rapid({p.x(), p.y(), m_at.z()}); }
    // A straight move at `feed` (rapid when the feed is FMAX).
    void move(const Vec3& target, const Feed& feed);
    void moveW(double w, const Feed& feed) { move({m_at.x(), m_at.y(), w}, feed); }
    void moveUv(const Vec2& p, const Feed& feed) { move({p.x(), p.y(), m_at.z()}, feed); }
    // Arc about `center` ending at `target` (its w makes a helix).
    void arc(const Vec3& target, const Vec2& center, double sweepRad, const Feed& feed);
    // An arc of less than half a turn about `centre` in the plane through it, the tool and
    // `target` (a vertical arc when that plane holds the tool axis).
    void spatialArc(const Vec3& target, const Vec3& centre, const Feed& feed);
    void threadMove(const Vec3& target, double leadMm, double startAngleDeg);
    void dwell(double seconds);
    void spindle(canon::SpindleDirection direction, double rpm);
    void orientSpindle(double angleDeg);
    void miscFunction(int number);

    bool limitReached() const { return m_count >= kMoveLimit; }
    size_t moves() const { return m_count; }

private:
    bool count();

    CycleEmitter& m_out;
    Vec3 m_at;
    size_t m_count = 0;
};

}  // namespace kerf::cycles
