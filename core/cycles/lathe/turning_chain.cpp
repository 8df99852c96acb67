#include "core/cycles/lathe/turning_chain.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf::cycles::lathe {

Vec2 Section::at(double t) const {
    if (t <= 0.0) return a;
    if (t >= 1.0) return b;
    if (!arc) return a + t * (b - a);
    const double theta = theta0 + t * sweep;
    return c + r * Vec2(std::cos(theta), std::sin(theta));
}

double Section::atLevel(double v) const {
    if (!arc) {
        const double dy = b.y() - a.y();
        return std::fabs(dy) < kChainTolerance ? 0.0 : std::clamp((v - a.y()) / dy, 0.0, 1.0);
    }
    const double base = std::asin(std::clamp((v - c.y()) / r, -1.0, 1.0));
    double best = 0.0;
    double bestDistance = HUGE_VAL;
    for (const double angle : {base, kPi - base}) {
        for (const double turn : {-kTwoPi, 0.0, kTwoPi}) {
            const double t = (angle + turn - theta0) / sweep;
            const double distance = t < 0.0 ? -t : t > 1.0 ? t - 1.0 : 0.0;
            if (distance < bestDistance) {
                bestDistance = distance;
                best = std::clamp(t, 0.0, 1.0);
            }
        }
    }
    return best;
}

Vec2 Chain::at(double t) const {
    const double i = std::clamp(std::floor(t), 0.0, size() - 1.0);
    return parts[static_cast<size_t>(i)].at(t - i);
}

double Chain::atLevel(double v, double side) const {
    for (size_t i = 0; i < parts.size(); ++i) {
        const Section& p = parts[i];
        if (side * (p.a.y() - v) > kChainTolerance) return static_cast<double>(i);
        if (side * (p.b.y() - v) > kChainTolerance) return static_cast<double>(i) + p.atLevel(v);
    }
    return size();
}

Chain Chain::shifted(const Vec2& d) const {
    Chain moved = *this;
    for (Section& p : moved.parts) {
        p.a += d;
        p.b += d;
        p.c += d;
    }
    return moved;
}

void Chain::addArcByQuadrants(const Section& arc) {
    const double quarter = kPi / 2.0;
    const double first = arc.theta0 / quarter;
    const double last = (arc.theta0 + arc.sweep) / quarter;
    std::vector<double> cuts;  // angles strictly inside the sweep
    for (double q = std::ceil(std::min(first, last) + 1e-9);
         q <= std::floor(std::max(first, last) - 1e-9); q += 1.0) {
        cuts.push_back(q * quarter);
    }
    if (arc.sweep < 0.0) std::reverse(cuts.begin(), cuts.end());
    cuts.push_back(arc.theta0 + arc.sweep);
    Section piece = arc;
    for (const double angle : cuts) {
        piece.sweep = angle - piece.theta0;
        piece.b =
            angle == cuts.back() ? arc.b : arc.c + arc.r * Vec2(std::cos(angle), std::sin(angle));
        parts.push_back(piece);
        piece.a = piece.b;
        piece.theta0 = angle;
    }
}

std::vector<LevelInterval> Chain::intervalsAt(double v, double side) const {
    std::vector<LevelInterval> out;
    auto below = [&](const Vec2& p) { return side * (v - p.y()) > kChainTolerance; };
    bool inside = below(start());
    LevelInterval open;
    for (size_t i = 0; i < parts.size(); ++i) {
        const bool after = below(parts[i].b);
        if (after == inside) continue;
        const double t = static_cast<double>(i) + parts[i].atLevel(v);
        if (after) {
            open.enter = t;
        } else {
            open.exit = t;
            out.push_back(open);
            open = LevelInterval();
        }
        inside = after;
    }
    if (inside) {
        open.exit = size();
        out.push_back(open);
    }
    return out;
}

double Chain::lowest(double side) const {
    double low = side * start().y();
    for (const Section& s : parts)
        low = std::min(low, side * s.b.y());
    return side * low;
}

std::pair<double, double> Chain::lowestBetween(double t0, double t1, double side) const {
    // Parts are monotone: the extremes are at their ends (or at t0, t1).
    std::vector<double> ts{t0};
    for (double i = std::floor(t0) + 1.0; i < t1; i += 1.0)
        ts.push_back(i);
    ts.push_back(t1);
    double low = HUGE_VAL;
    for (const double t : ts)
        low = std::min(low, side * at(t).y());
    double first = t1;
    double last = t0;
    for (const double t : ts) {
        if (side * at(t).y() <= low + kChainTolerance) {
            first = std::min(first, t);
            last = std::max(last, t);
        }
    }
    return {first, last};
}

double Chain::topBefore(double t0, double t1, double cap, double side) const {
    double best = t1;
    double bestLevel = side * at(t1).y();
    const auto first = static_cast<size_t>(std::max(0.0, std::floor(t0)));
    for (size_t i = std::min(parts.size(), static_cast<size_t>(std::ceil(t1))); i-- > first;) {
        const Section& s = parts[i];
        const double from = std::max(t0, static_cast<double>(i));
        const double to = std::min(t1, static_cast<double>(i) + 1.0);
        if (side * (s.at(to - static_cast<double>(i)).y() - cap) >= -kChainTolerance ||
            side * (s.at(from - static_cast<double>(i)).y() - cap) >= -kChainTolerance) {
            // This part reaches the cap: the last point where it is at the cap.
            const double t = static_cast<double>(i) + s.atLevel(cap);
            return std::clamp(t, from, to);
        }
        for (const double t : {from, to}) {
            const double level = side * at(t).y();
            if (level > bestLevel) {
                bestLevel = level;
                best = t;
            }
        }
    }
    return best;
}

void followChain(const Chain& chain, double t0, double t1, double feed, bool facing,
                 LathePath& path) {
    for (size_t i = static_cast<size_t>(std::max(0.0, std::floor(t0)));
         i < chain.parts.size() && static_cast<double>(i) < t1; ++i) {
        const Section& part = chain.parts[i];
        const double local = std::min(1.0, t1 - static_cast<double>(i));
        const Vec2 to = part.at(local);
        if (part.arc) {
            path.arc(swapped(to, facing), swapped(part.c, facing), (part.sweep > 0.0) != facing,
                     feed);
        } else {
            path.feed(swapped(to, facing), feed);
        }
    }
}

void cutAlongLevel(const Chain* raw, double side, double toX, double level, double feed,
                   bool facing, LathePath& path) {
    const double fromX = swapped(path.position(), facing).x();
    auto go = [&](double x, bool cutting) {
        const Vec2 to = swapped(Vec2(x, level), facing);
        if (cutting) {
            path.feed(to, feed);
        } else {
            path.rapid(to);
        }
    };
    if (raw == nullptr || raw->parts.empty()) {
        go(toX, true);
        return;
    }
    // The stretches of the level under the raw stock, in the order of travel.
    const double direction = toX >= fromX ? 1.0 : -1.0;
    std::vector<std::pair<double, double>> stock;
    for (const LevelInterval& i : raw->intervalsAt(level, -side)) {
        const double a = i.fromCallSide() ? raw->start().x() : raw->at(i.enter).x();
        const double b = i.exit >= raw->size() ? raw->end().x() : raw->at(i.exit).x();
        // In travel coordinates (x times the direction) the stretch runs from lo up to hi.
        const double lo = std::max(std::min(a * direction, b * direction), fromX * direction);
        const double hi = std::min(std::max(a * direction, b * direction), toX * direction);
        if (hi > lo + kChainTolerance) stock.emplace_back(lo * direction, hi * direction);
    }
    std::sort(stock.begin(), stock.end(), [&](const auto& p, const auto& q) {
        return p.first * direction < q.first * direction;
    });
    for (const auto& [start, end] : stock) {
        go(start, false);
        go(end, true);
    }
    go(toX, false);
}

}  // namespace kerf::cycles::lathe
