#include "core/cycles/contour/train_rest.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/base/translate.h"

namespace kerf::cycles::contour {

namespace {

// The point at `length` along a segment from its start.
Vec2 pointAlong(const PlanarSegment& s, double length) {
    const double l = s.length();
    const double f = l > 0.0 ? std::clamp(length / l, 0.0, 1.0) : 0.0;
    if (s.kind != PlanarSegment::Kind::Arc) return s.start + f * (s.end - s.start);
    const double a = s.sweep * f;
    const Vec2 r = s.start - s.center;
    return s.center + Vec2(std::cos(a) * r.x() - std::sin(a) * r.y(),
                           std::sin(a) * r.x() + std::cos(a) * r.y());
}

// The part of a segment between `from` and `to` along it.
PlanarSegment pieceOf(const PlanarSegment& s, double from, double to) {
    const Vec2 a = pointAlong(s, from);
    if (s.kind != PlanarSegment::Kind::Arc) return PlanarSegment::line(a, pointAlong(s, to));
    const double l = s.length();
    return PlanarSegment::arc(a, s.center, s.sweep * (to - from) / l);
}

double distanceToChain(const Chain& chain, const Vec2& p) {
    double d = std::numeric_limits<double>::infinity();
    for (const PlanarSegment& s : chain)
        d = std::min(d, s.distanceTo(p));
    return d;
}

// The part of `chain` between the path lengths `from` and `to`.
Chain chainBetween(const Chain& chain, double from, double to) {
    Chain out;
    double at = 0.0;
    for (const PlanarSegment& s : chain) {
        const double l = s.length();
        const double a = std::max(from - at, 0.0);
        const double b = std::min(to - at, l);
        if (b - a > 1e-9) out.push_back(a <= 0.0 && b >= l ? s : pieceOf(s, a, b));
        at += l;
    }
    return out;
}

// The part of a closed `chain` (length `total`) between the path lengths `from` and `to`, which
// may reach across its start (from < 0 or to > total).
Chain chainAround(const Chain& chain, double total, double from, double to) {
    if (from < 0.0) {
        from += total;
        to += total;
    }
    Chain out = chainBetween(chain, from, std::min(to, total));
    if (to > total) {
        const Chain beyond = chainBetween(chain, 0.0, to - total);
        out.insert(out.end(), beyond.begin(), beyond.end());
    }
    return out;
}

}  // namespace

std::vector<Chain> restPieces(const Chain& fine, double fineRadius, const Chain& coarse,
                              double coarseRadius, const TrainRest& rest) {
    double total = 0.0;
    for (const PlanarSegment& s : fine)
        total += s.length();
    if (coarse.empty()) return {fine};
    const double limit = coarseRadius - fineRadius + rest.residual;
    auto isRest = [&](const PlanarSegment& s, double t) {
        return distanceToChain(coarse, pointAlong(s, t)) > limit;
    };
    // Where the rest begins and ends along the path: samples every 0.05 mm (at most 2000 per
    // segment), each change located by bisection to 1e-7 mm.
    std::vector<std::pair<double, double>> spans;
    double at = 0.0;
    bool inside = false;
    double begin = 0.0;
    for (const PlanarSegment& s : fine) {
        const double l = s.length();
        const int samples = static_cast<int>(std::clamp(std::ceil(l / 0.05), 8.0, 2000.0));
        double before = 0.0;
        bool wasRest = isRest(s, 0.0);
        if (wasRest != inside) {
            inside = wasRest;
            if (inside) begin = at;
            if (!inside) spans.emplace_back(begin, at);
        }
        for (int i = 1; i <= samples; ++i) {
            const double t = l * i / samples;
            const bool now = isRest(s, t);
            if (now != wasRest) {
                double lo = before;
                double hi = t;
                while (hi - lo > 1e-7) {
                    const double mid = (lo + hi) / 2.0;
                    (isRest(s, mid) == wasRest ? lo : hi) = mid;
                }
                if (now) {
                    begin = at + hi;
                } else {
                    spans.emplace_back(begin, at + lo);
                }
                inside = now;
            }
            wasRest = now;
            before = t;
        }
        at += l;
    }
    if (inside) spans.emplace_back(begin, total);
    // Lengthened by Q448 (an open path not beyond its ends), joined across gaps of at most Q447;
    // on a closed path also across its start, where the last piece runs on into the first.
    const bool closed = (fine.front().start - fine.back().end).norm() <= 1e-9;
    std::vector<std::pair<double, double>> joined;
    for (auto [from, to] : spans) {
        from -= rest.extension;
        to += rest.extension;
        if (!closed) {
            from = std::max(0.0, from);
            to = std::min(total, to);
        }
        if (!joined.empty() && from - joined.back().second <= rest.connection) {
            joined.back().second = std::max(joined.back().second, to);
        } else {
            joined.emplace_back(from, to);
        }
    }
    if (closed && joined.size() > 1 &&
        joined.front().first + total - joined.back().second <= rest.connection) {
        joined.back().second = std::max(joined.back().second, joined.front().second + total);
        joined.erase(joined.begin());
    }
    std::vector<Chain> pieces;
    for (const auto& [from, to] : joined) {
        // A closed path with rest all round is run whole from its start.
        if (closed && to - from >= total - 1e-9) return {fine};
        Chain piece = closed ? chainAround(fine, total, from, to) : chainBetween(fine, from, to);
        if (!piece.empty()) pieces.push_back(std::move(piece));
    }
    return pieces;
}

std::optional<CycleError> coarseTool(int cycle, const CycleValues& values,
                                     const CycleContext& context, ToolInfo& out) {
    const int number = static_cast<int>(values.number(18));
    std::optional<ToolInfo> tool =
        context.toolByNumber ? context.toolByNumber(number) : std::nullopt;
    if (!tool) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1}: tool {2} ({3}) is not in the tool table"),
                          {std::to_string(cycle), std::to_string(number), "Q18"}};
    }
    out = *tool;
    return std::nullopt;
}

}  // namespace kerf::cycles::contour
