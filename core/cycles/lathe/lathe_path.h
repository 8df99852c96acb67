#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/axes.h"

// FAGOR lathe canned cycles (spec part 2 §2) as pure expansions. They work in the lathe plane:
// a point is (z, x) = (abscissa, ordinate), mm, x as a radius; the interpreter maps the plane to
// axes (G16 remaps, §1.3), applies units, diameter mode and the coordinate transformations.
namespace kerf::cycles::lathe {

struct LatheStep {
    enum class Kind : uint8_t {
        Rapid,
        Feed,            // at `feed` (mm/min or mm/rev as active), 0: the feed active at the call
        FeedArc,         // like Feed, about `centre`, counter-clockwise in (z, x) if `ccw`
        Thread,          // spindle-synchronised: `lead` mm per revolution along the move
        Dwell,           // `seconds`
        SpindleStop,     // M05
        SpindleReverse,  // the opposite of the direction at the call
        SpindleRestore,  // the direction at the call again
        Orient,          // M19 to `angleDeg`
    };
    Kind kind = Kind::Rapid;
    Vec2 to{0.0, 0.0};
    Vec2 centre{0.0, 0.0};
    bool ccw = false;
    double feed = 0.0;
    double lead = 0.0;
    double leadChange = 0.0;  // mm per revolution per revolution (G86/G87 M)
    double angleDeg = 0.0;    // thread start angle, orientation
    double seconds = 0.0;
};

// A problem that stops the cycle, at the column of `letter` (0: the cycle's G).
struct LatheError {
    char letter = 0;
    std::string code;
    std::string messageTemplate;  // English with {1}.. placeholders, marked with KERF_TR_NOOP
    std::vector<std::string> args;
};

// Collects a cycle's steps while tracking the tool; moves that go nowhere are left out, and the
// number of steps is capped so that a tiny step over a long section stops with an error.
class LathePath {
public:
    static constexpr size_t kStepLimit = 200000;

    explicit LathePath(const Vec2& start) : m_at(start) {}

    const Vec2& position() const { return m_at; }
    const std::vector<LatheStep>& steps() const { return m_steps; }
    bool full() const { return m_steps.size() >= kStepLimit; }

    void rapid(const Vec2& to) { move(LatheStep::Kind::Rapid, to, 0.0); }
    void feed(const Vec2& to, double feed = 0.0) { move(LatheStep::Kind::Feed, to, feed); }
    void arc(const Vec2& to, const Vec2& centre, bool ccw, double feed = 0.0);
    void thread(const Vec2& to, double lead, double angleDeg, double leadChange = 0.0);
    void dwell(double seconds);
    void command(LatheStep::Kind kind, double angleDeg = 0.0);

private:
    void move(LatheStep::Kind kind, const Vec2& to, double feed);

    Vec2 m_at;
    std::vector<LatheStep> m_steps;
};

// The error a cycle reports when its steps would exceed LathePath::kStepLimit.
LatheError tooManySteps(char letter);

}  // namespace kerf::cycles::lathe
