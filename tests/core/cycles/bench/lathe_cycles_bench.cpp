// Expansion time of the biggest FAGOR lathe cycles (docs/benchmarks.md): the pure expansion into
// steps, without the interpreter's output stage.
#include <benchmark/benchmark.h>

#include "core/cycles/lathe/pattern_repeat.h"
#include "core/cycles/lathe/section_turning.h"
#include "core/cycles/lathe/threading.h"

namespace kerf::cycles::lathe {
namespace {

// G84 quarter round r10 -> r20 from r25, C 0.001: 15,000 passes, about 75,000 moves.
void BM_G84ArcTurning15000Passes(benchmark::State& state) {
    TurningSection s;
    s.start = {0.0, 10.0};
    s.elements.push_back({Vec2(-10.0, 20.0), Vec2(-10.0, 10.0), true});
    s.maxStep = 0.001;
    s.finishingFeed = 0.1;
    const Vec2 call(2.0, 25.0);
    for (auto _ : state) {
        LathePath path(call);
        LatheError error;
        benchmark::DoNotOptimize(expandTurningSection(s, call, path, error));
        state.counters["moves"] = static_cast<double>(path.steps().size());
    }
}
BENCHMARK(BM_G84ArcTurning15000Passes)->Unit(benchmark::kMillisecond);

// G86 taper thread, constant infeed 0.002 over 1.5 mm, A30, 4 starts: 3,000 passes.
void BM_G86Thread3000Passes(benchmark::State& state) {
    Thread t;
    t.start = {5.0, 20.0};
    t.end = {-30.0, 22.0};
    t.depth = 1.5;
    t.infeed = -0.002;
    t.pitch = 2.0;
    t.starts = 4;
    t.safety = 1.0;
    for (auto _ : state) {
        LathePath path(Vec2(10.0, 30.0));
        LatheError error;
        benchmark::DoNotOptimize(expandThread(t, Vec2(10.0, 30.0), path, error));
        state.counters["moves"] = static_cast<double>(path.steps().size());
    }
}
BENCHMARK(BM_G86Thread3000Passes)->Unit(benchmark::kMillisecond);

// G68 over a 100-element profile (50 steps of a 1 mm shoulder each followed by a 0.5 mm taper,
// from r0 to r50 over 100 mm), C 0.5 from r55, no D: 110 passes back along the profile.
void BM_G68Profile100Elements(benchmark::State& state) {
    TurningSection s;
    s.start = {0.0, 0.0};
    Vec2 at = s.start;
    for (int i = 0; i < 50; ++i) {
        at += Vec2(0.0, 0.5);
        s.elements.push_back({at, std::nullopt, false});
        at += Vec2(-2.0, 0.5);
        s.elements.push_back({at, std::nullopt, false});
    }
    s.maxStep = 0.5;
    s.allowanceX = 0.2;
    s.allowanceZ = 0.1;
    s.finalRoughingFeed = 0.2;
    s.finishingFeed = 0.1;
    const Vec2 call(2.0, 55.0);
    for (auto _ : state) {
        LathePath path(call);
        LatheError error;
        benchmark::DoNotOptimize(expandTurningSection(s, call, path, error));
        state.counters["moves"] = static_cast<double>(path.steps().size());
    }
}
BENCHMARK(BM_G68Profile100Elements)->Unit(benchmark::kMillisecond);

// G66 over a 100-element profile (50 shoulders of 0.5 mm each followed by a taper, r0 to r50 over
// 100 mm), I 10, C 0.5 from r70: 20 passes, each the exact offset of the profile (2 n^2 pair
// tests for the offset's self-crossings).
void BM_G66Profile100Elements(benchmark::State& state) {
    PatternRepeat c;
    c.start = {0.0, 0.0};
    Vec2 at = c.start;
    for (int i = 0; i < 50; ++i) {
        at += Vec2(0.0, 0.5);
        c.elements.push_back({at, std::nullopt, false});
        at += Vec2(-2.0, 0.5);
        c.elements.push_back({at, std::nullopt, false});
    }
    c.stock = 10.0;
    c.step = 0.5;
    c.allowanceX = 0.2;
    c.finishingFeed = 0.1;
    const Vec2 call(15.0, 70.0);
    for (auto _ : state) {
        LathePath path(call);
        LatheError error;
        benchmark::DoNotOptimize(expandPatternRepeat(c, call, path, error));
        state.counters["moves"] = static_cast<double>(path.steps().size());
    }
}
BENCHMARK(BM_G66Profile100Elements)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace kerf::cycles::lathe

BENCHMARK_MAIN();
