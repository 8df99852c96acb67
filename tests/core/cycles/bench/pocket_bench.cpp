// Expansion time of the pocket cycles (docs/benchmarks.md): the spec's 251 example (80 x 60, R5,
// allowances, helical plunge, 4 infeeds, side finishing in 4 infeeds, floor finishing) with a
// D10 tool, into an emitter that only counts.
#include <benchmark/benchmark.h>

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

}  // namespace
}  // namespace kerf::cycles

BENCHMARK_MAIN();
