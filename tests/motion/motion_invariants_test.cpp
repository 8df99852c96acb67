#include <cmath>

#include <gtest/gtest.h>

#include "tests/motion/motion_test_run.h"
#include "tests/motion/random_program.h"
#include "tests/motion/raster_program.h"

namespace kerf::motion::test {
namespace {

struct Collect final : canon::Sink {
    std::vector<canon::Command> commands;
    void consume(const canon::Command& c) override { commands.push_back(c); }
};

std::vector<canon::Command> raster(int blocks, double seg, double feed) {
    Collect collect;
    RasterOptions options;
    options.blocks = blocks;
    options.segMm = seg;
    options.feedMmPerMin = feed;
    emitRaster(options, collect);
    return collect.commands;
}

Pose lastTarget(const std::vector<canon::Command>& commands, const Pose& start) {
    Pose p = start;
    for (const auto& c : commands) {
        if (const auto* l = std::get_if<canon::LinearMove>(&c.body)) p = l->target;
        if (const auto* r = std::get_if<canon::RapidMove>(&c.body)) p = r->target;
        if (const auto* a = std::get_if<canon::ArcMove>(&c.body)) p = a->target;
    }
    return p;
}

void expectEndsAt(const TestRun& run, const Pose& target) {
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(run.report.finalPosition[static_cast<size_t>(i)],
                    target.values[static_cast<size_t>(i)], 1e-6)
            << "axis " << i;
    }
}

TEST(MotionInvariants, RandomProgramsRespectLimitsToleranceAndEndExactly) {
    for (uint32_t seed = 1; seed <= 6; ++seed) {
        RandomProgramOptions options;
        options.seed = seed;
        options.moves = 80;
        options.tolerances = false;
        auto commands = randomProgram(options);
        TestRun run = runCommands(millConfig(), commands, Pose{});
        SCOPED_TRACE("seed " + std::to_string(seed) + ": " + run.checker->limitSummary());
        EXPECT_FALSE(run.report.refused)
            << (run.report.diagnostics.empty() ? "" : run.report.diagnostics[0].message());
        EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
        EXPECT_LE(run.checker->maxDeviation(), 0.01 * 1.01);
        expectEndsAt(run, lastTarget(commands, Pose{}));
    }
}

TEST(MotionInvariants, RandomProgramsWithToleranceChangesRespectLimits) {
    for (uint32_t seed = 100; seed <= 103; ++seed) {
        RandomProgramOptions options;
        options.seed = seed;
        options.moves = 80;
        auto commands = randomProgram(options);
        TestRun run = runCommands(figuresMill(), commands, Pose{});
        SCOPED_TRACE("seed " + std::to_string(seed) + ": " + run.checker->limitSummary());
        EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
        EXPECT_LE(run.checker->maxDeviation(), 0.1 * 1.01);
        expectEndsAt(run, lastTarget(commands, Pose{}));
    }
}

TEST(MotionInvariants, GenNcRastersRespectLimitsAndTolerance) {
    for (double seg : {0.2, 0.05, 0.02}) {
        for (double feed : {1500.0, 6000.0}) {
            auto commands = raster(1000, seg, feed);
            TestRun run = runCommands(figuresMill(), commands, rasterStart());
            SCOPED_TRACE("seg " + std::to_string(seg) + " F" + std::to_string(feed) + ": " +
                         run.checker->limitSummary());
            EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
            EXPECT_LE(run.checker->maxDeviation(), 0.01 * 1.01);
            EXPECT_LE(run.checker->axis(0).velocity, feed / 60.0 * 1.0001);
            expectEndsAt(run, lastTarget(commands, rasterStart()));
        }
    }
}

TEST(MotionInvariants, SameProgramSameSamples) {
    RandomProgramOptions options;
    options.seed = 7;
    auto commands = randomProgram(options);
    TestRun first = runCommands(millConfig(), commands, Pose{});
    TestRun second = runCommands(millConfig(), commands, Pose{});
    EXPECT_EQ(first.sampleHash, second.sampleHash);
    EXPECT_EQ(first.report.cycles, second.report.cycles);
}

TEST(MotionInvariants, FeedOverrideChangesStayWithinLimits) {
    RandomProgramOptions options;
    options.seed = 11;
    options.moves = 100;
    auto commands = randomProgram(options);
    int count = 0;
    const double overrides[] = {0.5, 1.5, 0.0, 1.0, 1.2, 0.3, 1.5};
    TestRun run = runCommands(
        millConfig(), commands, Pose{}, {},
        [&](SimulatedMachine& sim, const Sample&, const MotionStatus&) {
            if (++count % 700 == 0) {
                double value = overrides[(count / 700) % 7];
                sim.command({OperatorCommandKind::FeedOverride, -1, value});
                sim.command({OperatorCommandKind::RapidOverride, -1, std::min(1.0, value + 0.2)});
            }
        });
    SCOPED_TRACE(run.checker->limitSummary());
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
    expectEndsAt(run, lastTarget(commands, Pose{}));
}

}  // namespace
}  // namespace kerf::motion::test
