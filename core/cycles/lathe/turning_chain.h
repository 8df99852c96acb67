#pragma once

#include <utility>
#include <vector>

#include "core/cycles/lathe/lathe_path.h"
#include "core/geometry/axes.h"

// The profile of the turning cycles in their (cut, step) frame: x() along the passes, y() the
// level they step through (turning: (z, x radius); facing: swapped). Internal to
// core/cycles/lathe.
namespace kerf::cycles::lathe {

inline constexpr double kChainTolerance = 1e-9;

// One element, a line or an arc, as a function of t in [0, 1].
struct Section {
    Vec2 a{0.0, 0.0};
    Vec2 b{0.0, 0.0};
    bool arc = false;
    Vec2 c{0.0, 0.0};
    double r = 0.0;
    double theta0 = 0.0;
    double sweep = 0.0;

    Vec2 at(double t) const;
    // The parameter where the element reaches level v (it is monotone in it: a line, or an arc
    // within a quarter circle); a flat element is reached at its start.
    double atLevel(double v) const;
};

// A stretch of a pass at one level below which the profile lies: from the chain parameter
// `enter` where it goes down through the level (-1: from the call point's side, the profile
// starts below it) to `exit` where it comes back up (the chain's size: up to its end's wall).
struct LevelInterval {
    double enter = -1.0;
    double exit = 0.0;
    bool fromCallSide() const { return enter < 0.0; }
};

// The profile as a chain of elements, parameter t in [0, n].
struct Chain {
    std::vector<Section> parts;

    double size() const { return static_cast<double>(parts.size()); }
    Vec2 start() const { return parts.front().a; }
    Vec2 end() const { return parts.back().b; }
    Vec2 at(double t) const;
    // The first parameter where the chain rises above level v (a stretch at v is passed along).
    double atLevel(double v, double side) const;
    Chain shifted(const Vec2& d) const;
    // An arc split at the quadrant points it passes, so every part is monotone in both axes.
    void addArcByQuadrants(const Section& arc);
    // Where the profile lies below level v (`side`: +1 when the material is above it), in order.
    std::vector<LevelInterval> intervalsAt(double v, double side) const;
    // The lowest level the chain reaches.
    double lowest(double side) const;
    // The stretch where the chain is lowest between t0 and t1: its first and last parameter.
    std::pair<double, double> lowestBetween(double t0, double t1, double side) const;
    // Between t0 < t1, over a stretch that lies above the level `cap`: the last parameter where
    // the chain is at `cap`, else the parameter of its highest point.
    double topBefore(double t0, double t1, double cap, double side) const;
};

// Turning cuts along Z and steps in X, facing the other way: swapping the axes maps the frame to
// (z, x) and back. It mirrors the plane, so arcs turn the other way.
inline Vec2 swapped(const Vec2& p, bool swap) {
    return swap ? Vec2(p.y(), p.x()) : p;
}

// Feed moves along `chain` from parameter t0 to t1 (t0 <= t1), element by element, written in
// (z, x) (`facing`: the frame is swapped).
void followChain(const Chain& chain, double t0, double t1, double feed, bool facing,
                 LathePath& path);

// From the tool's place on `level` along it to `toX`: at `feed` where the raw stock `raw` lies
// beyond the level (`side`: +1 when the material lies above it), at rapid where it does not;
// all at the feed without a raw stock.
void cutAlongLevel(const Chain* raw, double side, double toX, double level, double feed,
                   bool facing, LathePath& path);

}  // namespace kerf::cycles::lathe
