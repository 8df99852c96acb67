// The position display's X, Y, Z in a tilted working plane (core/task/working_plane_position.h),
// from the interpreter's status and the axes the stream reached, on mill5 (B/C table-table, the
// workpiece origin at the pivot, so the axes are T w with T = Ry(-B) Rz(-C) the tables' turn).
#include "core/task/working_plane_position.h"

#include <cmath>
#include <filesystem>
#include <variant>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::task {
namespace {

namespace fs = std::filesystem;

// Where the axes stand after the moves of one line.
struct LastMoveOfLine : canon::Sink {
    void consume(const canon::Command& c) override {
        if (c.location.line != line) return;
        if (const auto* m = std::get_if<canon::LinearMove>(&c.body)) target = m->target;
        if (const auto* m = std::get_if<canon::RapidMove>(&c.body)) target = m->target;
    }
    uint32_t line = 0;
    Pose target{};
};

// PLANE SPATIAL SPB+30 turns the tables to B+30 C0; M128 then keeps the tip at the plane's
// (10, 5, 2) while the block turns them on to B+60 C+90. On the part the tip is
// w = Ry(30) (10, 5, 2) = (10 cos30 + 2 sin30, 5, -10 sin30 + 2 cos30) = (9.660254, 5, -3.267949);
// Rz(-90) takes it to (5, -9.660254, -3.267949), Ry(-60) to
// (5 * 0.5 + 3.267949 * 0.866025, -9.660254, 5 * 0.866025 - 3.267949 * 0.5)
// = (5.330127, -9.660254, 2.696152): the axes. The display shows the tip in the plane,
// (10, 5, 2), not the plane's map of the axes alone, Ry(-30) a = (3.267949, -9.660254, 5).
// A step of the axes Ry(-60) Rz(-90) Ry(30) (1, 0, 0) = (0.433013, -0.866025, -0.25) there is a
// step of 1 along the plane's X.
TEST(WorkingPlanePosition, TcpmShowsTheTipInThePlaneWhileTheTablesTurn) {
    const fs::path dir =
        fs::temp_directory_path() / ("kerf_plane_position_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const machine::MachineConfig mill5 = *machine::loadMachine("mill5");
    klartext::KlartextSettings settings;
    settings.machine = &mill5;
    settings.ncRoot = dir;
    // The machine file's workpiece origin: mill5's pivot.
    for (const machine::AxisConfig& axis : mill5.axes)
        settings.presetInMachine[*axisFromLetter(axis.letter)] = axis.presetPosition;
    program::SourceRegistry sources;
    klartext::KlartextInterpreter k(sources, settings);
    writeFileAtomically(dir / "P.H",
                        "0 BEGIN PGM P MM\n1 L X+0 Y+0 Z+100 R0 FMAX\n"
                        "2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\n3 M128\n"
                        "4 L X+10 Y+5 Z+2 B+60 C+90 F1000\n5 END PGM P MM\n");
    ASSERT_TRUE(k.load(dir / "P.H"));
    LastMoveOfLine sink;
    sink.line = 5;  // block 4
    interp::RunStatus status;
    do {
        status = k.run(sink, 1000);
    } while (status == interp::RunStatus::BudgetUsed);
    fs::remove_all(dir);
    ASSERT_EQ(status, interp::RunStatus::Finished);
    const auto plane = k.programStatus().transformations.workingPlane;
    ASSERT_TRUE(plane.has_value());
    EXPECT_TRUE(plane->tipFollowsTables);
    std::array<double, kAxisCount> axes = sink.target.values;
    EXPECT_NEAR(axes[0], 5.330127, 1e-6);
    EXPECT_NEAR(axes[1], -9.660254, 1e-6);
    EXPECT_NEAR(axes[2], 2.696152, 1e-6);
    EXPECT_NEAR(axes[4], 60.0, 1e-9);
    EXPECT_NEAR(axes[5], 90.0, 1e-9);
    const auto kinematics = machine::TableKinematics::of(mill5);
    const Vec3 shown = positionInWorkingPlane(*plane, kinematics, axes);
    EXPECT_NEAR(shown.x(), 10.0, 1e-6);
    EXPECT_NEAR(shown.y(), 5.0, 1e-6);
    EXPECT_NEAR(shown.z(), 2.0, 1e-6);
    const Vec3 step =
        differenceInWorkingPlane(*plane, kinematics, Vec3(0.433013, -0.866025, -0.25), axes);
    EXPECT_NEAR(step.x(), 1.0, 1e-6);
    EXPECT_NEAR(step.y(), 0.0, 1e-6);
    EXPECT_NEAR(step.z(), 0.0, 1e-6);
}

}  // namespace
}  // namespace kerf::task
