#include "tests/motion/random_program.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/geometry/arc_math.h"

namespace kerf::motion::test {

std::vector<canon::Command> randomProgram(const RandomProgramOptions& options) {
    std::mt19937 rng(options.seed);
    auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    auto chance = [&](double p) { return uniform(0.0, 1.0) < p; };
    std::vector<canon::Command> out;
    uint32_t line = 1;
    auto push = [&](canon::CommandBody body) {
        canon::Command c;
        c.location.line = line++;
        c.location.blockNumber = static_cast<int64_t>(line);
        c.body = std::move(body);
        out.push_back(std::move(c));
    };
    Pose position;
    Vec3 direction(1.0, 0.0, 0.0);
    double feed = 1000.0;
    // The built-in mill's Z travel ends at +50 mm.
    auto keepInside = [](Vec3 p) {
        for (int i = 0; i < 2; ++i)
            p[i] = std::clamp(p[i], -100.0, 100.0);
        p[2] = std::clamp(p[2], -60.0, 40.0);
        return p;
    };
    for (int n = 0; n < options.moves; ++n) {
        if (chance(0.3)) feed = std::exp(uniform(std::log(100.0), std::log(15000.0)));
        if (options.tolerances && chance(0.05))
            push(canon::PathTolerance{chance(0.3) ? 0.0 : uniform(0.002, 0.1)});
        double kind = uniform(0.0, 1.0);
        if (options.rapids && kind < 0.08) {
            Pose target = position;
            target.setXyz(keepInside(position.xyz() +
                                     Vec3(uniform(-30, 30), uniform(-30, 30), uniform(-10, 10))));
            push(canon::RapidMove{target});
            direction = (target.xyz() - position.xyz()).normalized();
            position = target;
        } else if (kind < 0.6) {
            // Lines: mostly short, some long; tangent continuations or any direction.
            double length =
                chance(0.5) ? std::exp(uniform(std::log(0.01), std::log(1.0))) : uniform(1.0, 25.0);
            Vec3 d = chance(0.4)
                         ? direction
                         : Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-0.5, 0.5)).normalized();
            Pose target = position;
            target.setXyz(keepInside(position.xyz() + d * length));
            if ((target.xyz() - position.xyz()).norm() < 1e-6) continue;
            push(canon::LinearMove{target, feed});
            direction = (target.xyz() - position.xyz()).normalized();
            position = target;
        } else {
            canon::ArcMove arc;
            arc.plane = static_cast<Plane>(std::uniform_int_distribution<int>(0, 2)(rng));
            PlaneAxes axes = planeAxes(arc.plane);
            int f = axisIndex(axes.first);
            int s = axisIndex(axes.second);
            int nrm = axisIndex(axes.normal);
            double radius = std::exp(uniform(std::log(0.2), std::log(20.0)));
            double angle = uniform(0.0, kTwoPi);
            Vec3 center = position.xyz();
            center[f] -= radius * std::cos(angle);
            center[s] -= radius * std::sin(angle);
            arc.center = center;
            arc.sweepRad = (chance(0.5) ? 1.0 : -1.0) * uniform(0.1, kTwoPi);
            double end = angle + arc.sweepRad;
            Pose target = position;
            target.values[static_cast<size_t>(f)] = center[f] + radius * std::cos(end);
            target.values[static_cast<size_t>(s)] = center[s] + radius * std::sin(end);
            if (chance(0.3)) target.values[static_cast<size_t>(nrm)] += uniform(-5.0, 5.0);
            Vec3 t = target.xyz();
            if (t != keepInside(t)) continue;
            arc.target = target;
            arc.feed = feed;
            push(arc);
            Vec3 tangent(0.0, 0.0, 0.0);
            double turn = arc.sweepRad > 0.0 ? 1.0 : -1.0;
            tangent[f] = -turn * std::sin(end);
            tangent[s] = turn * std::cos(end);
            direction = tangent;
            position = target;
        }
    }
    return out;
}

}  // namespace kerf::motion::test
