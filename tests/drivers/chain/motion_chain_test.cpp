// Done-criterion of the issue: a program runs through the CAN chain (planner, servo cycle,
// CANopen master, simulated drives on the virtual bus) to the same end position as on motion's
// own simulated drives, and an injected fault stops it safely.
#include <cmath>

#include <gtest/gtest.h>

#include "app/runner/can_machine.h"
#include "canon_builders.h"
#include "core/machine/machine_loader.h"
#include "motion/sim/simulated_machine.h"

namespace kerf::drivers {
namespace {

using kerf::test::pose;

std::vector<canon::Command> program() {
    std::vector<canon::Command> commands;
    uint32_t line = 1;
    auto add = [&](canon::CommandBody body) {
        canon::Command c;
        c.location.line = line++;
        c.body = std::move(body);
        commands.push_back(std::move(c));
    };
    add(canon::SpindleControl{canon::SpindleDirection::Clockwise, 3000.0});
    add(canon::RapidMove{pose(10.0, 5.0, 2.0)});
    add(canon::LinearMove{pose(10.0, 5.0, -2.0), 600.0});
    add(canon::LinearMove{pose(40.0, 5.0, -2.0), 1200.0});
    canon::ArcMove arc;
    arc.target = pose(40.0, 25.0, -2.0);
    arc.center = Vec3(40.0, 15.0, 0.0);
    arc.plane = Plane::XY;
    arc.sweepRad = 3.14159265358979323846;
    arc.feed = 1200.0;
    add(arc);
    add(canon::LinearMove{pose(30.0, -20.0, -5.0), 1500.0});
    add(canon::SpindleControl{canon::SpindleDirection::Stopped, 0.0});
    add(canon::RapidMove{pose(30.0, -20.0, 10.0)});
    add(canon::ProgramStop{canon::StopKind::End, 30});
    return commands;
}

struct CanRun {
    app::CanRunResult result;
    bool booted = false;
    std::vector<double> velocitiesAfter;  // drive velocities (counts/s) 1.5 s after the end
};

CanRun onCan(const machine::MachineConfig& config, CanSimOptions options = {}) {
    CanRun run;
    auto machine = app::CanMachine::create(config, std::move(options), pose(0.0, 0.0, 0.0).values);
    if (!machine) {
        run.result.diagnostics.push_back(machine.error());
        return run;
    }
    run.booted = true;
    for (const canon::Command& c : program())
        (*machine)->consume(c);
    (*machine)->drain();
    // Nothing may keep moving: 1.5 s later (motion's spindle ramp from 3000 rpm takes 1 s) every
    // drive stands still.
    (*machine)->runFor(1.5);
    for (size_t i = 0; i < (*machine)->drives().driveCount(); ++i)
        run.velocitiesAfter.push_back((*machine)->drives().drive(i).plant().velocity());
    run.result = (*machine)->finish();
    return run;
}

motion::AxisVector onSimulatedDrives(const machine::MachineConfig& config) {
    motion::SimulationOptions options;
    options.startPosition = pose(0.0, 0.0, 0.0).values;
    options.maxSimulatedS = 30.0;
    motion::SimulatedMachine machine(config, options);
    for (const canon::Command& c : program())
        machine.consume(c);
    machine.drain();
    return machine.report().finalPosition;
}

TEST(MotionChain, ProgramEndsWhereItEndsOnMotionsSimulatedDrives) {
    machine::MachineConfig mill = machine::loadMachine("mill").value();
    CanRun run = onCan(mill);
    const app::CanRunResult& can = run.result;
    ASSERT_TRUE(run.booted) << (can.diagnostics.empty() ? "" : can.diagnostics[0].message());
    EXPECT_FALSE(can.stopped);
    EXPECT_TRUE(can.diagnostics.empty());
    EXPECT_EQ(can.mode, motion::MotionMode::Idle);
    motion::AxisVector reference = onSimulatedDrives(mill);
    for (int axis = 0; axis < 3; ++axis) {
        // The drives' feedback resolution is 1e-4 mm (10000 counts/mm).
        EXPECT_NEAR(can.finalPosition[static_cast<size_t>(axis)],
                    reference[static_cast<size_t>(axis)], 2e-4)
            << "axis " << axis;
    }
    EXPECT_NEAR(can.finalPosition[0], 30.0, 2e-4);
    EXPECT_NEAR(can.finalPosition[1], -20.0, 2e-4);
    EXPECT_NEAR(can.finalPosition[2], 10.0, 2e-4);
    // Setpoint minus feedback includes the bus's dead time: at 500 mm/s rapids ~4 ms.
    EXPECT_LT(can.maxFollowingErrorMm, 3.0);
    RecordProperty("max_following_error_mm", std::to_string(can.maxFollowingErrorMm));
    for (double v : run.velocitiesAfter)
        EXPECT_LT(std::fabs(v), 1.0) << "counts/s";
}

TEST(MotionChain, InjectedFaultStopsTheProgramAndEverything) {
    machine::MachineConfig mill = machine::loadMachine("mill").value();
    for (const char* spec :
         {"2:heartbeat@0.4", "1:emcy@0.4", "3:following-error@0.4", "2:pdo@0.4"}) {
        SCOPED_TRACE(spec);
        CanSimOptions options;
        options.faults.push_back(parseFaultInjection(spec).value());
        CanRun run = onCan(mill, options);
        const app::CanRunResult& can = run.result;
        ASSERT_TRUE(run.booted);
        EXPECT_TRUE(can.stopped);
        EXPECT_EQ(can.mode, motion::MotionMode::Fault);
        ASSERT_FALSE(can.diagnostics.empty());
        EXPECT_EQ(can.diagnostics[0].severity, Severity::Error);
        EXPECT_EQ(can.diagnostics[0].message().rfind("CAN node ", 0), 0u)
            << can.diagnostics[0].message();
        EXPECT_GT(std::fabs(can.finalPosition[1] + 20.0), 1.0) << "did not reach the end";
        for (double v : run.velocitiesAfter)
            EXPECT_LT(std::fabs(v), 1.0) << "nothing keeps moving";
    }
}

}  // namespace
}  // namespace kerf::drivers
