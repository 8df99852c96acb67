// Builds and tears down complete scenes (toolpath with levels of detail, VTK poly data, stock
// mesh, tool glyphs, highlight) without a window, and fails when the heap in use grows from one
// round to the next (ctest graphics_scene_no_leaks). Valgrind takes minutes over VTK's libraries;
// glibc's own counters take nothing. Freed blocks parked in glibc's per-thread cache count as in
// use, so the check runs with that cache off (it re-executes itself with GLIBC_TUNABLES). Under
// AddressSanitizer (asan preset) the counters stay at zero and LeakSanitizer checks at exit.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <malloc.h>
#include <unistd.h>

#include "graphics/scene/scene.h"
#include "graphics/stock/stock_simulation.h"
#include "graphics/toolpath/toolpath_data.h"
#include "graphics/toolpath/toolpath_lod.h"

using namespace kerf;
using namespace kerf::graphics;

namespace {

canon::Command command(canon::CommandBody body, uint32_t line) {
    canon::Command c;
    c.location.line = line;
    c.body = std::move(body);
    return c;
}

Pose pose(double x, double y, double z) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

// Builds, uses and destroys the scenes of one round (mill, mill, lathe).
void buildAndDestroyScenes() {
    for (int round = 0; round < 3; ++round) {
        ToolpathCollector collector;
        StockSimulation stock;
        uint32_t line = 0;
        auto feed = [&](canon::CommandBody body) {
            const canon::Command c = command(std::move(body), ++line);
            collector.consume(c);
            stock.consume(c);
        };
        feed(canon::StockDefinition{canon::StockBox{Vec3(0, 0, -10), Vec3(50, 50, 0)}});
        canon::ToolChange tool;
        tool.number = 1;
        tool.geometry.radiusMm = 3;
        tool.geometry.radius2Mm = 3;
        feed(tool);
        feed(canon::RapidMove{pose(0, 0, 5)});
        for (int i = 0; i < 2000; ++i) {
            const double x = (i % 100) * 0.5;
            feed(canon::LinearMove{pose(x, (i / 100) * 2.5, -1 + 0.5 * std::sin(x)), 500});
        }
        canon::ArcMove arc;
        arc.target = pose(20, 25, -2);
        arc.center = Vec3(25, 25, 0);
        arc.sweepRad = 6.0;
        feed(arc);
        stock.finish();
        auto data = std::make_shared<ToolpathData>(collector.take());
        auto geometry = std::make_shared<ToolpathGeometry>(buildToolpathGeometry(*data));
        SceneOptions options;
        Bounds3 limits;
        limits.add(Vec3(-100, -100, -100));
        limits.add(Vec3(100, 100, 100));
        options.limits = limits;
        options.lathe = round == 2;
        Scene scene(options);
        ToolGlyph glyph;
        if (round == 2) {
            LatheInsert insert;
            insert.includedAngleDeg = 55;
            insert.edgeLengthMm = 6;
            glyph.shape = insert;
        } else {
            glyph.shape = MillCutter::fromGeometry(3, 3);
        }
        scene.setTool(glyph);
        scene.setToolpath(data, geometry);
        scene.setStockMesh(std::make_shared<Mesh>(stock.mesh(128)));
        scene.highlightBlock(0, 50);
        scene.setView(View::Top);
        scene.zoom(3.0);
        scene.rotate(10, 5);
        (void)scene.pick(100, 100);
        scene.setToolpath(data, geometry);  // replace: the old actors go
        scene.clearHighlight();
    }
}

size_t heapInUse() {
    return mallinfo2().uordblks;
}

}  // namespace

int main(int, char** argv) {
    if (std::getenv("GLIBC_TUNABLES") == nullptr) {
        ::setenv("GLIBC_TUNABLES", "glibc.malloc.tcache_count=0", 1);
        ::execv("/proc/self/exe", argv);
        std::perror("graphics_leak_check: re-executing without the thread cache");
        return 2;
    }
    // stdout's buffer comes with the first output: before the measurement.
    std::printf("building and destroying scenes\n");
    // The first rounds set up VTK's object factories, class registries and caches for good.
    buildAndDestroyScenes();
    buildAndDestroyScenes();
    // Two batches: a leak grows the heap in both; a one-off (a worker thread's bookkeeping
    // from the level-of-detail build, reused or not) shows in one at most.
    constexpr int kRounds = 5;
    long long growth[2] = {0, 0};
    for (long long& batch : growth) {
        const size_t before = heapInUse();
        for (int r = 0; r < kRounds; ++r)
            buildAndDestroyScenes();
        batch = static_cast<long long>(heapInUse()) - static_cast<long long>(before);
    }
    std::printf("heap growth over %d rounds: %+lld, then %+lld bytes\n", kRounds, growth[0],
                growth[1]);
    // One leaked actor, mapper or poly data is at least a few hundred bytes per round; the toolpath
    // and stock data are hundreds of kilobytes. 256 bytes a round leaves room for allocator
    // bookkeeping and nothing that a scene owns.
    const long long least = std::min(growth[0], growth[1]);
    if (least > 256LL * kRounds) {
        std::printf("leak: the heap grows by %lld bytes a round\n", least / kRounds);
        return 1;
    }
    return 0;
}
