// The trajectory rows of shared/anchors/FIGURES.md: gen_nc rasters through the planner and servo
// cycle in simulated time, feed time against the FIGURES bound (trapezoidal rows, U-turns at
// the centripetal limit) and against the jerk-aware bound, side by side with LinuxCNC's ratio.
// Usage: motion_figures [BLOCKS] [JERK...]   (defaults: 5000 blocks, jerk 50000 mm/s^3)
//        motion_figures mill [JERK [SAMPLES.csv]]   the built-in mill: 5000 x 0.02 mm at F6000
//                                                   (JERK 0 = the mill's own)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "motion/sim/simulated_machine.h"
#include "tests/motion/bench/raster_bound.h"
#include "tests/motion/motion_test_run.h"

using namespace kerf;
using namespace kerf::motion;

namespace {

int runMill(double jerk, const char* samplesPath) {
    test::RasterOptions raster;
    raster.blocks = 5000;
    raster.segMm = 0.02;
    raster.feedMmPerMin = 6000.0;
    SimulationOptions options;
    options.startPosition = test::rasterStart().values;
    if (samplesPath) options.samplesCsvPath = samplesPath;
    machine::MachineConfig config = test::millConfig();
    if (jerk > 0.0) {
        for (auto& axis : config.axes)
            axis.maxJerkPerS3 = jerk;
    }
    jerk = config.axes[0].maxJerkPerS3;
    SimulatedMachine sim(config, options);
    test::emitRaster(raster, sim);
    sim.drain();
    MotionReport report = sim.report();
    double bound = test::rasterBoundS(raster, 2000.0);
    double jerkBound = test::rasterBoundS(raster, 2000.0, jerk);
    std::printf(
        "mill 5000 x 0.02 mm F6000, J %.0f: feed time %.3f s, bound %.3f s (x%.2f), jerk bound "
        "%.3f s "
        "(x%.2f), max deviation %.4f mm\n",
        jerk, report.feedTimeS, bound, report.feedTimeS / bound, jerkBound,
        report.feedTimeS / jerkBound, report.maxPathDeviationMm);
    for (const AxisReport& a : report.axes) {
        std::printf("  %c max v %.2f mm/s, a %.1f mm/s^2, j %.0f mm/s^3\n", a.letter, a.maxVelocity,
                    a.maxAccel, a.maxJerk);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::string(argv[1]) == "mill") {
        return runMill(argc > 2 ? std::atof(argv[2]) : 0.0, argc > 3 ? argv[3] : nullptr);
    }
    int blocks = argc > 1 ? std::atoi(argv[1]) : 5000;
    std::vector<double> jerks;
    for (int i = 2; i < argc; ++i)
        jerks.push_back(std::atof(argv[i]));
    if (jerks.empty()) jerks.push_back(50000.0);
    struct Row {
        double seg;
        double feed;
        double linuxcnc;
    };
    const Row rows[] = {{0.2, 1500, 1.08},  {0.02, 1500, 2.12}, {0.2, 6000, 1.32},
                        {0.05, 6000, 1.89}, {0.02, 6000, 2.31}, {0.05, 1500, 0.0}};
    std::printf(
        "| segments | feed | jerk mm/s^3 | actual s | bound s | actual/bound | LinuxCNC | "
        "jerk bound s | actual/jerk bound | peak mm/s | max dev mm | plan+sim s |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (double jerk : jerks) {
        for (const Row& row : rows) {
            machine::MachineConfig config = test::figuresMill();
            for (auto& axis : config.axes)
                axis.maxJerkPerS3 = jerk;
            test::RasterOptions raster;
            raster.blocks = blocks;
            raster.segMm = row.seg;
            raster.feedMmPerMin = row.feed;
            SimulationOptions options;
            options.startPosition = test::rasterStart().values;
            auto begin = std::chrono::steady_clock::now();
            SimulatedMachine sim(config, options);
            test::emitRaster(raster, sim);
            sim.drain();
            double wall =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
            MotionReport report = sim.report();
            double bound = test::rasterBoundS(raster, 1000.0);
            double jerkBound = test::rasterBoundS(raster, 1000.0, jerk);
            char linuxcnc[16] = "-";
            if (row.linuxcnc > 0.0) std::snprintf(linuxcnc, sizeof linuxcnc, "%.2f", row.linuxcnc);
            std::printf(
                "| %.2f mm | %.0f mm/s | %.0f | %.3f | %.3f | %.2f | %s | %.3f | %.2f | %.1f | "
                "%.4f | %.1f |\n",
                row.seg, row.feed / 60.0, jerk, report.feedTimeS, bound, report.feedTimeS / bound,
                linuxcnc, jerkBound, report.feedTimeS / jerkBound, report.axes[0].maxVelocity,
                report.maxPathDeviationMm, wall);
            std::fflush(stdout);
        }
    }
}
