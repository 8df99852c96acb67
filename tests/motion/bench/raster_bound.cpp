#include "tests/motion/bench/raster_bound.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geometry/arc_math.h"
#include "motion/profile/jerk_profile.h"

namespace kerf::motion::test {

namespace {

constexpr double kTurnRadius = 0.25;

struct Lengths final : canon::Sink {
    std::vector<double> rows;
    int arcs = 0;
    double current = 0.0;
    Vec3 position = rasterStart().xyz();
    void consume(const canon::Command& c) override {
        if (const auto* l = std::get_if<canon::LinearMove>(&c.body)) {
            current += (l->target.xyz() - position).norm();
            position = l->target.xyz();
        } else if (const auto* a = std::get_if<canon::ArcMove>(&c.body)) {
            rows.push_back(current);
            current = 0.0;
            ++arcs;
            position = a->target.xyz();
        }
    }
};

// Trapezoid: least time over `length` from v0 to v1 with |a| <= accel, v <= vmax.
double trapezoidS(double length, double v0, double v1, double vmax, double accel) {
    double peak = std::sqrt((2.0 * accel * length + v0 * v0 + v1 * v1) / 2.0);
    if (peak <= vmax) return (peak - v0) / accel + (peak - v1) / accel;
    double ramps = (vmax * vmax - v0 * v0 + vmax * vmax - v1 * v1) / (2.0 * accel);
    return (vmax - v0) / accel + (vmax - v1) / accel + (length - ramps) / vmax;
}

// S-curve: least time over `length` from v0 to v1 (a = 0 at both ends), v <= vmax.
double sCurveS(double length, double v0, double v1, double vmax, const Limits& limits) {
    auto legs = [&](double peak, double& time, double& distance) {
        Profile up = velocityChange({0.0, v0, 0.0}, peak, limits);
        Profile down = velocityChange({0.0, peak, 0.0}, v1, limits);
        time = up.duration() + down.duration();
        distance = up.end().s + down.end().s;
    };
    double time = 0.0;
    double distance = 0.0;
    legs(vmax, time, distance);
    if (distance <= length) return time + (length - distance) / vmax;
    double lo = std::max(v0, v1);
    double hi = vmax;
    for (int i = 0; i < 100; ++i) {
        double mid = (lo + hi) / 2.0;
        legs(mid, time, distance);
        if (distance <= length)
            lo = mid;
        else
            hi = mid;
    }
    legs(lo, time, distance);
    return time + (length - distance) / std::max(lo, 1e-9);
}

}  // namespace

double rasterBoundS(const RasterOptions& options, double accel, double jerk) {
    Lengths lengths;
    RasterOptions plain = options;
    plain.leadIn = false;
    emitRaster(plain, lengths);
    if (lengths.current > 0.0) lengths.rows.push_back(lengths.current);
    double vmax = options.feedMmPerMin / 60.0;
    double turn = std::min(vmax, std::sqrt(accel * kTurnRadius));
    if (jerk > 0.0) turn = std::min(turn, std::cbrt(jerk * kTurnRadius * kTurnRadius));
    double total = 0.0;
    size_t rows = lengths.rows.size();
    for (size_t i = 0; i < rows; ++i) {
        double v0 = i == 0 ? 0.0 : turn;
        bool lastRowEndsTheProgram = i + 1 == rows && static_cast<size_t>(lengths.arcs) < rows;
        double v1 = lastRowEndsTheProgram ? 0.0 : turn;
        total += jerk > 0.0 ? sCurveS(lengths.rows[i], v0, v1, vmax, {accel, jerk})
                            : trapezoidS(lengths.rows[i], v0, v1, vmax, accel);
    }
    total += lengths.arcs * kPi * kTurnRadius / turn;
    return total;
}

}  // namespace kerf::motion::test
