#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>

#include <gtest/gtest.h>

#include "motion/planner/planner.h"
#include "motion/rt/servo_cycle.h"
#include "motion/sim/sim_drive_set.h"
#include "tests/motion/motion_test_run.h"
#include "tests/motion/raster_program.h"

// Counts heap allocations made by this thread while counting is on: the servo cycle must make
// none once started (architecture: nothing allocated in the RT thread).
namespace {
thread_local bool t_counting = false;
std::atomic<long> g_allocations{0};
}  // namespace

// The replacements pair malloc with free; GCC cannot see that operator new is replaced too.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t size) {
    if (t_counting) ++g_allocations;
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    return operator new(size);
}
// The nothrow forms too (std::stable_sort's buffer): every new must pair with the free below.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    if (t_counting) ++g_allocations;
    return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
    return operator new(size, tag);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}

namespace kerf::motion::test {
namespace {

struct Feed final : canon::Sink {
    Planner* planner;
    void consume(const canon::Command& c) override { planner->add(c); }
};

TEST(ServoCycleAllocation, NoHeapAllocationAfterStart) {
    machine::MachineConfig config = millConfig();
    MachineModel model = makeMachineModel(config, {});
    SimDriveSet drives(model, {});
    drives.setProbeSurface([](const std::array<double, kMaxJoints>& j) { return j[2] < -30.0; });
    auto items = std::make_unique<ItemRing>();
    CommandRing commands;
    EventRing events;
    ServoCycle servo(model, drives, *items, commands, events);
    // Plan a program with arcs, blends, a spindle, a dwell and a probe move in this thread.
    Planner planner(model);
    planner.setPosition(rasterStart().values);
    Feed feed;
    feed.planner = &planner;
    RasterOptions raster;
    raster.blocks = 600;
    raster.segMm = 0.05;
    raster.feedMmPerMin = 6000.0;
    canon::Command spindle;
    spindle.body = canon::SpindleControl{canon::SpindleDirection::Clockwise, 3000.0};
    planner.add(spindle);
    emitRaster(raster, feed);
    canon::Command dwell;
    dwell.body = canon::Dwell{0.1};
    planner.add(dwell);
    planner.flush();
    while (auto item = planner.next()) {
        ASSERT_TRUE(items->push(*item));
    }
    servo.start();

    t_counting = true;
    bool returned = false;
    for (int i = 0; i < 20000; ++i) {
        if (i == 3000) commands.push({OperatorCommandKind::FeedOverride, -1, 1.4});
        if (i == 4000) commands.push({OperatorCommandKind::FeedHold});
        // Hold, jog away (the program moves about 1 s once the spindle is at speed, after 1 s);
        // the cycle start at 1600 returns to the path.
        if (i == 1300) commands.push({OperatorCommandKind::FeedHold});
        if (i == 1450) commands.push({OperatorCommandKind::JogIncrement, 1, 1.0});
        if (i == 4500) commands.push({OperatorCommandKind::CycleStart});
        if (i == 5000) commands.push({OperatorCommandKind::SingleBlock, -1, 0.0, 0.0, true});
        if (i == 5200) commands.push({OperatorCommandKind::SingleBlock, -1, 0.0, 0.0, false});
        if (i % 400 == 0) commands.push({OperatorCommandKind::CycleStart});
        servo.cycle();
        drives.advance(model.periodS);
        returned = returned || servo.status().mode == MotionMode::Returning;
        while (!events.empty())
            events.pop();
    }
    // Manual modes after the program.
    commands.push({OperatorCommandKind::JogContinuous, 0, 30.0});
    for (int i = 0; i < 500; ++i)
        servo.cycle(), drives.advance(model.periodS);
    commands.push({OperatorCommandKind::JogStop, 0});
    for (int i = 0; i < 500; ++i)
        servo.cycle(), drives.advance(model.periodS);
    commands.push({OperatorCommandKind::Handwheel, 1, 0.5});
    commands.push({OperatorCommandKind::EmergencyStop});
    commands.push({OperatorCommandKind::Reset});
    for (int i = 0; i < 500; ++i)
        servo.cycle(), drives.advance(model.periodS);
    t_counting = false;

    EXPECT_EQ(g_allocations.load(), 0);
    EXPECT_TRUE(returned);
    EXPECT_GT(servo.status().cycle, 20000u);
}

}  // namespace
}  // namespace kerf::motion::test
