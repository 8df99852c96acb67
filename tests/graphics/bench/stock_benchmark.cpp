// Material removal per move: the height field (vertical tool) against the voxel stock (any tool
// direction) on the same 100 x 100 x 30 mm blank. Figures in docs/benchmarks.md. Run:
//   stock_benchmark [--benchmark_repetitions=N]
#include <cmath>

#include <benchmark/benchmark.h>

#include "graphics/stock/height_field_stock.h"
#include "graphics/stock/voxel_stock.h"

namespace kerf::graphics {
namespace {

const Vec3 kMin(0.0, 0.0, -30.0);
const Vec3 kMax(100.0, 100.0, 0.0);
constexpr size_t kHeightFieldCells = 25'000'000;
constexpr size_t kVoxels = 64'000'000;

// One 0.1 mm step of a raster at depth 1 mm along X, row by row 2 mm apart (a 3-axis finish).
Vec3 rasterPoint(long step) {
    const long row = (step / 1000) % 50;
    const double x = 0.1 * static_cast<double>(step % 1000);
    return {row % 2 == 0 ? x : 100.0 - x, 2.0 * static_cast<double>(row), -1.0};
}

void heightFieldRaster(benchmark::State& state, const MillCutter& cutter) {
    HeightFieldStock stock(kMin, kMax, 0.1, kHeightFieldCells);
    long step = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(stock.cut(rasterPoint(step), rasterPoint(step + 1), cutter));
        ++step;
    }
    state.SetItemsProcessed(state.iterations());
}

void voxelRaster(benchmark::State& state, const MillCutter& cutter) {
    VoxelStock stock(kMin, kMax, 0.1, kVoxels);
    long step = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(
            stock.cut(rasterPoint(step), rasterPoint(step + 1), Vec3::UnitZ(), cutter));
        ++step;
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["cell_mm"] = stock.cellMm();
}

// The same raster with the tool tilted 30 deg about Y (a 3+2 finish on a tilted plane).
void voxelTiltedRaster(benchmark::State& state, const MillCutter& cutter) {
    VoxelStock stock(kMin, kMax, 0.1, kVoxels);
    const Vec3 axis(std::sin(0.5235987755982988), 0.0, std::cos(0.5235987755982988));
    long step = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(stock.cut(rasterPoint(step), rasterPoint(step + 1), axis, cutter));
        ++step;
    }
    state.SetItemsProcessed(state.iterations());
}

// 5 mm holes 10 mm deep drilled horizontally into the side face x = 100, 6 mm apart.
void voxelSideHoles(benchmark::State& state) {
    VoxelStock stock(kMin, kMax, 0.1, kVoxels);
    const MillCutter drill = MillCutter::fromGeometry(2.5, 0.0, 118.0);
    long hole = 0;
    for (auto _ : state) {
        const double y = 3.0 + 6.0 * static_cast<double>(hole % 16);
        const double z = -5.0 - 6.0 * static_cast<double>((hole / 16) % 4);
        benchmark::DoNotOptimize(stock.cut({105.0, y, z}, {90.0, y, z}, Vec3::UnitX(), drill));
        ++hole;
    }
    state.SetItemsProcessed(state.iterations());
}

void voxelFromHeightField(benchmark::State& state) {
    const HeightFieldStock field(kMin, kMax, 0.1, kHeightFieldCells);
    for (auto _ : state) {
        const VoxelStock stock = VoxelStock::fromHeightField(field, kVoxels);
        benchmark::DoNotOptimize(stock.cellMm());
    }
}

void voxelMesh(benchmark::State& state) {
    VoxelStock stock(kMin, kMax, 0.1, kVoxels);
    for (long hole = 0; hole < 64; ++hole) {
        const double y = 3.0 + 6.0 * static_cast<double>(hole % 16);
        const double z = -5.0 - 6.0 * static_cast<double>(hole / 16);
        stock.cut({105.0, y, z}, {90.0, y, z}, Vec3::UnitX(), MillCutter::fromGeometry(2.5, 0.0));
    }
    size_t triangles = 0;
    for (auto _ : state) {
        const Mesh mesh = stock.mesh(200);
        triangles = mesh.triangleCount();
        benchmark::DoNotOptimize(triangles);
    }
    state.counters["triangles"] = static_cast<double>(triangles);
}

const MillCutter kFlat3 = MillCutter::fromGeometry(3.0, 0.0);
const MillCutter kBall3 = MillCutter::fromGeometry(3.0, 3.0);

BENCHMARK_CAPTURE(heightFieldRaster, flat_r3, kFlat3);
BENCHMARK_CAPTURE(heightFieldRaster, ball_r3, kBall3);
BENCHMARK_CAPTURE(voxelRaster, flat_r3, kFlat3);
BENCHMARK_CAPTURE(voxelRaster, ball_r3, kBall3);
BENCHMARK_CAPTURE(voxelTiltedRaster, flat_r3, kFlat3);
BENCHMARK_CAPTURE(voxelTiltedRaster, ball_r3, kBall3);
BENCHMARK(voxelSideHoles);
BENCHMARK(voxelFromHeightField)->Unit(benchmark::kMillisecond);
BENCHMARK(voxelMesh)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace kerf::graphics

BENCHMARK_MAIN();
