#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "canon_builders.h"
#include "tests/motion/motion_test_run.h"
#include "tests/motion/raster_program.h"

// CAM output: runs of very short lines. Within one servo period the path passes many element
// ends; the sampled setpoints must stay within every axis limit however many there are.
namespace kerf::motion::test {
namespace {

using kerf::test::command;
using kerf::test::pose;

double rounded(double value, int decimals) {
    double scale = std::pow(10.0, decimals);
    return std::round(value * scale) / scale;
}

// Collects the commands with their end points written with 4 decimals, as a CAM file has them.
struct CollectRounded final : canon::Sink {
    std::vector<canon::Command> commands;
    void consume(const canon::Command& c) override {
        canon::Command copy = c;
        auto round = [](Pose& p) {
            for (double& value : p.values)
                value = rounded(value, 4);
        };
        if (auto* line = std::get_if<canon::LinearMove>(&copy.body)) round(line->target);
        if (auto* arc = std::get_if<canon::ArcMove>(&copy.body)) round(arc->target);
        commands.push_back(copy);
    }
};

// gen.py polycircle: the circle of radius r through the origin, centre (0, r), as lines of
// `seg` mm of arc, coordinates written with `decimals` decimals, `length` mm in all.
std::vector<canon::Command> polylineCircle(double r, double seg, int decimals, double length,
                                           double feedMmPerMin) {
    std::vector<canon::Command> commands;
    int count = static_cast<int>(std::lround(length / seg));
    for (int i = 1; i <= count; ++i) {
        double s = i * seg;
        double x = rounded(r * std::sin(s / r), decimals);
        double y = rounded(r - r * std::cos(s / r), decimals);
        commands.push_back(
            command(canon::LinearMove{pose(x, y, 0.0), feedMmPerMin}, static_cast<uint32_t>(i)));
    }
    return commands;
}

void expectWithinLimits(const TestRun& run, double tolerance) {
    EXPECT_FALSE(run.report.refused);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
    EXPECT_LE(run.checker->maxDeviation(), tolerance * 1.01);
}

TEST(ShortSegments, PolylineCirclesAtFiveMicrometresRespectEveryLimit) {
    // 0.005 mm elements at F6000 (100 mm/s): up to 20 element ends in one 1 ms period.
    for (double radius : {5.0, 50.0}) {
        for (int decimals : {4, 6}) {
            auto commands = polylineCircle(radius, 0.005, decimals, 20.0, 6000.0);
            TestRun run = runCommands(millConfig(), commands, Pose{});
            SCOPED_TRACE("R" + std::to_string(radius) + " " + std::to_string(decimals) +
                         " decimals: " + run.checker->limitSummary());
            expectWithinLimits(run, 0.01);
            EXPECT_NEAR(run.report.finalPosition[0],
                        std::get<canon::LinearMove>(commands.back().body).target[Axis::X], 1e-6);
        }
    }
}

TEST(ShortSegments, FmaxPlungeIntoAFineRasterRespectsEveryLimit) {
    // gen_nc's raster as written (4 decimals) at 0.005, 0.02 and 0.05 mm, after a rapid down
    // onto its start point.
    for (double seg : {0.005, 0.02, 0.05}) {
        CollectRounded collect;
        collect.consume(command(canon::RapidMove{pose(0.0, 0.0, 5.0)}, 1));
        collect.consume(command(canon::RapidMove{rasterStart()}, 2));
        RasterOptions options;
        options.blocks = 1000;
        options.segMm = seg;
        options.feedMmPerMin = 6000.0;
        emitRaster(options, collect);
        TestRun run = runCommands(millConfig(), collect.commands, pose(0.0, 0.0, 20.0));
        SCOPED_TRACE("seg " + std::to_string(seg) + ": " + run.checker->limitSummary());
        expectWithinLimits(run, 0.01);
    }
}

void expectHoldAndResumeWithinLimits(const std::vector<canon::Command>& commands) {
    int cycles = 0;
    int holdCycle = -1;
    int resumeCycle = -1;
    double commandS = -1.0;
    double holdS = -1.0;
    TestRun run =
        runCommands(millConfig(), commands, Pose{}, {},
                    [&](SimulatedMachine& sim, const Sample&, const MotionStatus& s) {
                        ++cycles;
                        if (holdCycle < 0 && s.pathPosition > 5.0) {
                            holdCycle = cycles;
                            commandS = s.pathPosition;
                            sim.command({OperatorCommandKind::FeedHold});
                        }
                        if (holdCycle > 0 && resumeCycle < 0 && s.mode == MotionMode::Hold) {
                            holdS = s.pathPosition;
                            resumeCycle = cycles + 100;
                        }
                        if (cycles == resumeCycle) sim.command({OperatorCommandKind::CycleStart});
                    });
    SCOPED_TRACE(run.checker->limitSummary());
    ASSERT_GT(resumeCycle, 0) << "never held";
    EXPECT_GE(holdS, commandS);
    expectWithinLimits(run, 0.01);
    EXPECT_NEAR(run.report.finalPosition[0],
                std::get<canon::LinearMove>(commands.back().body).target[Axis::X], 1e-6);
}

TEST(ShortSegments, FeedHoldAndResumeInsideARunOfShortSegments) {
    // Hold and resume inside a run (the samples of braking, standing and starting again are
    // checked against every limit), on fine runs and on 0.5 mm lines fitted between their
    // vertices (PolylineSmoother::knotAt).
    struct Case {
        double seg;
        int decimals;
    };
    for (Case c : {Case{0.005, 6}, Case{0.005, 4}, Case{0.02, 4}, Case{0.5, 4}}) {
        SCOPED_TRACE("seg " + std::to_string(c.seg) + ", " + std::to_string(c.decimals) +
                     " decimals");
        expectHoldAndResumeWithinLimits(polylineCircle(5.0, c.seg, c.decimals, 20.0, 6000.0));
    }
}

}  // namespace
}  // namespace kerf::motion::test
