// Expansion time of the pocket cycles (docs/benchmarks.md): the spec's 251 example (80 x 60, R5,
// allowances, helical plunge, 4 infeeds, side finishing in 4 infeeds, floor finishing) with a
// D10 tool, into an emitter that only counts.
#include <cmath>
#include <numbers>

#include <benchmark/benchmark.h>

#include "core/cycles/contour/sl_machining.h"
#include "core/cycles/cycle_registry.h"

namespace kerf::cycles {
namespace {

struct Counter final : CycleEmitter {
    size_t moves = 0;
    void rapid(const Vec3&) override { ++moves; }
    void line(const Vec3&, const Feed&) override { ++moves; }
    void arc(const Vec3&, const Vec2&, double, const Feed&) override { ++moves; }
    void threadMove(const Vec3&, double, double) override {}
    void dwell(double) override {}
    void spindle(canon::SpindleDirection, double) override {}
    void orientSpindle(double) override {}
    void miscFunction(int) override {}
};

void expandSpecExample251(benchmark::State& state) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {215, 0},   {218, 80}, {219, 60},  {220, 5}, {368, 0.2}, {224, 0},   {367, 0},
        {207, 500}, {351, 1},  {201, -20}, {202, 5}, {369, 0.1}, {206, 150}, {338, 5},
        {200, 2},   {203, 0},  {204, 50},  {370, 1}, {366, 1},   {385, 500}, {439, 0}};
    for (auto [q, value] : values)
        v.set(q, value);
    CycleContext ctx;
    ctx.start = {50.0, 50.0, 100.0};
    ctx.tool.radius = 5.0;
    ctx.tool.plungeAngleDeg = 5.0;
    const CycleDescriptor& cycle = *findCycle(251);
    size_t moves = 0;
    for (auto _ : state) {
        Counter out;
        CyclePath path(out, ctx.start);
        benchmark::DoNotOptimize(cycle.expand(v, ctx, path));
        moves = out.moves;
    }
    state.counters["moves"] = static_cast<double>(moves);
}
BENCHMARK(expandSpecExample251)->Unit(benchmark::kMicrosecond);

// SL cycles 22 + 23 + 24 on one contour set with a D12 tool, Q3 0.5, Q4 0.5, depth 20 in
// infeeds of 5; the expansion includes the booleans and offsets of the contour engine.
void expandSl(benchmark::State& state, std::vector<SubContour> contours, double radius = 6.0) {
    CycleValues data;
    const std::pair<uint16_t, double> dataValues[] = {
        {1, -20}, {2, 1}, {3, 0.5}, {4, 0.5}, {5, 0}, {6, 2}, {7, 100}, {8, 0}, {9, 1}};
    for (auto [q, value] : dataValues)
        data.set(q, value);
    CycleValues rough, floor, side;
    for (auto [q, value] : {std::pair<uint16_t, double>{10, 5}, {11, 100}, {12, 350}})
        rough.set(q, value);
    for (auto [q, value] : {std::pair<uint16_t, double>{11, 100}, {12, 200}})
        floor.set(q, value);
    for (auto [q, value] : {std::pair<uint16_t, double>{9, 1}, {10, 5}, {11, 100}, {12, 400}})
        side.set(q, value);
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = radius;
    ctx.contours = std::move(contours);
    ctx.contourData = &data;
    ctx.roughingRadius = radius;
    size_t moves = 0;
    for (auto _ : state) {
        Counter out;
        // As in the interpreter, one cache for the calls of a program run.
        contour::ClearingCache cache;
        ctx.clearingCache = &cache;
        for (auto [number, values] :
             {std::pair<int, const CycleValues*>{22, &rough}, {23, &floor}, {24, &side}}) {
            CyclePath path(out, ctx.start);
            benchmark::DoNotOptimize(findCycle(number)->expand(*values, ctx, path));
        }
        moves = out.moves;
    }
    state.counters["moves"] = static_cast<double>(moves);
}

std::vector<SubContour> seedExampleC21() {
    auto polygon = [](std::initializer_list<Vec2> points) {
        ClosedContour c;
        const std::vector<Vec2> p(points);
        for (size_t i = 0; i < p.size(); ++i)
            c.segments.push_back(PlanarSegment::line(p[i], p[(i + 1) % p.size()]));
        return c;
    };
    return {{circleContour(25.0).placed({35.0, 50.0}, 0.0), false, 1},
            {circleContour(25.0).placed({65.0, 50.0}, 0.0), false, 2},
            {polygon({{27, 42}, {43, 42}, {43, 58}, {27, 58}}), true, 3},
            {polygon({{57, 42}, {73, 42}, {65, 58}}), true, 4}};
}

// The size: an outer contour of 200 lines (an ellipse 240 x 160 with a wavy edge) and
// 20 round islands of 8 mm diameter on a 5 x 4 grid.
std::vector<SubContour> largePocket() {
    std::vector<SubContour> out;
    ClosedContour outer;
    constexpr int kCorners = 200;
    std::vector<Vec2> p;
    for (int i = 0; i < kCorners; ++i) {
        const double a = 2.0 * std::numbers::pi * i / kCorners;
        const double wave = 1.0 + 0.03 * std::sin(12.0 * a);
        p.emplace_back(120.0 * wave * std::cos(a), 80.0 * wave * std::sin(a));
    }
    for (size_t i = 0; i < p.size(); ++i)
        outer.segments.push_back(PlanarSegment::line(p[i], p[(i + 1) % p.size()]));
    out.push_back({outer, false, 1});
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 4; ++j) {
            const Vec2 centre(-60.0 + 30.0 * i, -36.0 + 24.0 * j);
            out.push_back({circleContour(4.0).placed(centre, 0.0), true, 2 + i * 4 + j});
        }
    }
    return out;
}

void expandSeedExampleC21(benchmark::State& state) {
    expandSl(state, seedExampleC21());
}
BENCHMARK(expandSeedExampleC21)->Unit(benchmark::kMillisecond);

void expandSlPocket200Elements20Islands(benchmark::State& state) {
    expandSl(state, largePocket());
}
BENCHMARK(expandSlPocket200Elements20Islands)->Unit(benchmark::kMillisecond);

// A 300 x 200 rectangle with 20 round islands of 16 mm on a 5 x 4 grid and a small tool (D6):
// some 30 clearing rings.
void expandSlPocket300x200SmallTool(benchmark::State& state) {
    std::vector<SubContour> contours;
    ClosedContour outer;
    const Vec2 p[] = {{-150, -100}, {150, -100}, {150, 100}, {-150, 100}};
    for (size_t i = 0; i < 4; ++i)
        outer.segments.push_back(PlanarSegment::line(p[i], p[(i + 1) % 4]));
    contours.push_back({outer, false, 1});
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 4; ++j) {
            const Vec2 centre(-100.0 + 50.0 * i, -60.0 + 40.0 * j);
            contours.push_back({circleContour(8.0).placed(centre, 0.0), true, 2 + i * 4 + j});
        }
    }
    expandSl(state, std::move(contours), 3.0);
}
BENCHMARK(expandSlPocket300x200SmallTool)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace kerf::cycles

BENCHMARK_MAIN();
