// Graphics benchmark: toolpath load (canonical stream -> compact arrays -> levels of detail ->
// VTK buffers -> first frame), frame rate on the machine's OpenGL (llvmpipe here) and stock
// simulation throughput. Figures in docs/benchmarks.md;
// programs from bench/gen_paths.py.
//
//   graphics_bench PROGRAM [--size WxH] [--frames N] [--resolution MM] [--tool-radius R]
//                  [--png FILE]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "app/runner/run_options.h"
#include "app/runner/session.h"
#include "graphics/headless/virtual_display.h"
#include "graphics/scene/scene.h"
#include "graphics/stock/stock_simulation.h"
#include "graphics/toolpath/toolpath_data.h"
#include "graphics/toolpath/toolpath_lod.h"

using namespace kerf;
using namespace kerf::graphics;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

class Recorder final : public canon::Sink {
public:
    std::vector<canon::Command> commands;
    void consume(const canon::Command& command) override { commands.push_back(command); }
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr,
                     "usage: graphics_bench PROGRAM [--size WxH] [--frames N] "
                     "[--resolution MM] [--tool-radius R] [--png FILE]\n");
        return 2;
    }
    int width = 1280;
    int height = 800;
    int frames = 60;
    double resolution = 0.1;
    double toolRadius = 3.0;
    std::string png;
    bool axes = true;
    bool gradient = false;
    for (int i = 2; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--size") == 0) std::sscanf(argv[i + 1], "%dx%d", &width, &height);
        if (std::strcmp(argv[i], "--frames") == 0) frames = std::atoi(argv[i + 1]);
        if (std::strcmp(argv[i], "--resolution") == 0) resolution = std::atof(argv[i + 1]);
        if (std::strcmp(argv[i], "--tool-radius") == 0) toolRadius = std::atof(argv[i + 1]);
        if (std::strcmp(argv[i], "--png") == 0) png = argv[i + 1];
        if (std::strcmp(argv[i], "--axes") == 0) axes = std::atoi(argv[i + 1]) != 0;
        if (std::strcmp(argv[i], "--gradient") == 0) gradient = std::atoi(argv[i + 1]) != 0;
    }

    // 1. Interpret once and keep the canonical stream (not part of the graphics figures).
    app::RunOptions options;
    options.program = argv[1];
    auto session = app::openSession(options);
    if (!session->ready()) {
        std::fprintf(stderr, "program does not load\n");
        return 1;
    }
    Recorder recorder;
    auto t = Clock::now();
    for (;;) {
        const auto status = session->program.interpreter->run(recorder, 1u << 16);
        if (status == interp::RunStatus::NeedsSync) {
            interp::WorldSnapshot world;
            session->program.interpreter->resume(world);
            continue;
        }
        if (status != interp::RunStatus::BudgetUsed) break;
    }
    const double interpretS = since(t);
    const Pose start = session->program.interpreter->nominalPosition();
    std::printf("program: %s\ncanonical commands: %zu (interpreted in %.3f s)\n", argv[1],
                recorder.commands.size(), interpretS);

    // 2. Toolpath load.
    t = Clock::now();
    ToolpathCollector collector;
    collector.setStart(start);
    for (const auto& command : recorder.commands)
        collector.consume(command);
    auto data = std::make_shared<ToolpathData>(collector.take());
    const double collectS = since(t);
    t = Clock::now();
    auto geometry = std::make_shared<ToolpathGeometry>(buildToolpathGeometry(*data));
    const double lodS = since(t);

    auto display = VirtualDisplay::ensure();
    if (!display) {
        std::fprintf(stderr, "%s\n", display.error().format().c_str());
        return 1;
    }
    SceneOptions sceneOptions;
    sceneOptions.showAxes = axes;
    sceneOptions.gradientBackground = gradient;
    Scene scene(sceneOptions);
    OffscreenRenderer renderer(width, height);
    t = Clock::now();
    scene.setToolpath(data, geometry);
    const double vtkS = since(t);
    t = Clock::now();
    scene.setViewportSize(width, height);
    scene.setView(View::Iso);
    (void)renderer.renderRgb(scene);
    const double firstFrameS = since(t);
    std::printf("segments: %zu in %zu moves, %zu chunks, %.1f MB compact arrays\n",
                data->segmentCount(), data->moveCount(), geometry->chunks.size(),
                static_cast<double>(data->memoryBytes()) / 1e6);
    for (size_t level = 0; level < geometry->tolerances.size(); ++level) {
        std::printf("  level %zu: tolerance %.5f mm, %zu segments\n", level,
                    geometry->tolerances[level], geometry->segmentCount(level));
    }
    std::printf(
        "load: collect %.3f s + levels %.3f s + VTK arrays %.3f s + first frame %.3f s = "
        "%.3f s\n",
        collectS, lodS, vtkS, firstFrameS, collectS + lodS + vtkS + firstFrameS);

    // 3. Frame rates at WxH while the camera turns.
    const double stillFps = renderer.measureFps(scene, frames);
    const SceneStats still = scene.stats();
    std::printf("fps %dx%d, whole part, still detail (0.75 px): %.1f  (%zu segments drawn)\n",
                width, height, stillFps, still.segmentsSelected);
    scene.setInteractive(true);
    const double interactiveFps = renderer.measureFps(scene, frames);
    std::printf("fps while dragging (3 px): %.1f  (%zu segments)\n", interactiveFps,
                scene.stats().segmentsSelected);
    scene.setInteractive(false);
    {
        // Side by side on the same machine: the same scene without level of detail (every
        // segment drawn each frame), as a single-actor viewer would.
        SceneOptions naiveOptions = sceneOptions;
        naiveOptions.lodErrorPx = 0.0;
        Scene naive(naiveOptions);
        naive.setToolpath(data, geometry);
        naive.setViewportSize(width, height);
        naive.setView(View::Iso);
        OffscreenRenderer naiveRenderer(width, height);
        const double naiveFps = naiveRenderer.measureFps(naive, std::max(5, frames / 4));
        std::printf("fps without level of detail (all %zu segments): %.1f\n",
                    naive.stats().segmentsSelected, naiveFps);
    }
    scene.setView(View::Top);
    scene.zoom(8.0);
    const double zoomFps = renderer.measureFps(scene, frames, 0.5);
    std::printf("fps top view zoomed 8x: %.1f  (%zu segments in the chosen levels)\n", zoomFps,
                scene.stats().segmentsSelected);
    if (!png.empty()) {
        scene.setView(View::Iso);
        if (auto error = renderer.renderToPng(scene, png)) {
            std::fprintf(stderr, "%s\n", error->format().c_str());
        }
    }

    if (std::getenv("KERF_BENCH_NO_STOCK") != nullptr) return 0;
    // 4. Stock simulation throughput (ball end mill of the given radius, resolution).
    StockOptions stockOptions;
    stockOptions.resolutionMm = resolution;
    stockOptions.deriveStockFromPath = true;
    for (const char* kind : {"ball", "flat"}) {
        const bool ball = std::strcmp(kind, "ball") == 0;
        stockOptions.millCutter = [&](const canon::ToolChange&) {
            return MillCutter::fromGeometry(toolRadius, ball ? toolRadius : 0.0);
        };
        StockSimulation stock(stockOptions);
        stock.setStart(start);
        t = Clock::now();
        for (const auto& command : recorder.commands)
            stock.consume(command);
        stock.finish();
        const double stockS = since(t);
        std::printf(
            "stock %s R%.1f at %.2f mm: %zu moves in %.2f s = %.0f moves/s, removed "
            "%.1f mm3\n",
            kind, toolRadius, stock.resolutionMm(), stock.movesSimulated(), stockS,
            static_cast<double>(stock.movesSimulated()) / stockS, stock.removedVolumeMm3());
        t = Clock::now();
        const Mesh mesh = stock.mesh(512);
        std::printf("  stock mesh %zu triangles in %.3f s\n", mesh.triangleCount(), since(t));
    }
    return 0;
}
