// The tilted working plane and the rotary axes on the built-in machines mill5 (B/C table-table)
// and mill4 (A table), every value derived by hand (docs/klartext.md, "Tilted working plane").
// mill5's pivot is the workpiece origin, so the stream holds (table turn) x (tilt) x program.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class PlaneTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_plane_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    // Runs the blocks (numbered from 1) on the machine; the interpreter stays for inspection.
    interp::RunStatus run(const std::string& machineName, const std::string& blocks) {
        machine = *machine::loadMachine(machineName);
        KlartextSettings settings;
        settings.machine = &machine;
        settings.ncRoot = dir;
        // The machine file's workpiece origin (mill5: the pivot).
        for (const machine::AxisConfig& axis : machine.axes)
            settings.presetInMachine[*axisFromLetter(axis.letter)] = axis.presetPosition;
        k = std::make_unique<KlartextInterpreter>(sources, settings);
        const fs::path path = dir / "P.H";
        writeFileAtomically(path, "0 BEGIN PGM P MM\n" + blocks + "99 END PGM P MM\n");
        if (!k->load(path)) return interp::RunStatus::Failed;
        interp::RunStatus status;
        do {
            status = k->run(sink, 1000);
        } while (status == interp::RunStatus::BudgetUsed);
        return status;
    }
    double q(int number) const { return k->parameters().get(QRef{QKind::Q, uint16_t(number)}); }
    void expectAt(double x, double y, double z) const {
        const Pose p = k->nominalPosition();
        EXPECT_NEAR(p[Axis::X], x, 1e-9);
        EXPECT_NEAR(p[Axis::Y], y, 1e-9);
        EXPECT_NEAR(p[Axis::Z], z, 1e-9);
    }
    std::string firstError() const {
        for (const Diagnostic& d : k->diagnostics()) {
            if (d.severity == Severity::Error) return d.message();
        }
        return "";
    }

    struct Null : canon::Sink {
        void consume(const canon::Command&) override {}
    } sink;
    fs::path dir;
    machine::MachineConfig machine;
    program::SourceRegistry sources;
    std::unique_ptr<KlartextInterpreter> k;
};

// One plane, B tilted by +30 (tilted X = (cos30, 0, -sin30), tool axis (sin30, 0, cos30)), in
// every form: each solves B+30 C0, and the table's Ry(-30) takes the tilted axes back onto the
// machine's, so the program point (10, 5, 2) is at the axes (10, 5, 2).
TEST_F(PlaneTest, EveryFormDescribesTheSamePlane) {
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    auto text = [](double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.12f", v);
        return std::string(buffer);
    };
    const std::string cs = text(c), ss = text(s);
    const std::vector<std::string> forms{
        "PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY",
        "PLANE PROJECTED PROPR+30 PROMIN+0 ROT+0 STAY",
        // Precession 90 about Z, nutation 30 about the new X (= Y), back by -90 about Z.
        "PLANE EULER EULPR+90 EULNU+30 EULROT-90 STAY",
        "PLANE VECTOR BX+" + cs + " BY+0 BZ-" + ss + " NX+" + ss + " NY+0 NZ+" + cs + " STAY",
        // P1 -> P2 along the tilted X, P3 on the tilted Y axis.
        "PLANE POINTS P1X+0 P1Y+0 P1Z+0 P2X+" + cs + " P2Y+0 P2Z-" + ss + " P3X+0 P3Y+1 P3Z+0 STAY",
        "PLANE SPATIAL SPA+0 SPB+10 SPC+0 STAY\n3 PLANE RELATIV SPB+20 STAY",
        "PLANE AXIAL B+30 STAY",
    };
    for (const std::string& form : forms) {
        SCOPED_TRACE(form);
        ASSERT_EQ(
            run("mill5", "1 L X+0 Y+0 Z+100 R0 FMAX\n2 " + form + "\n4 L X+10 Y+5 Z+2 FMAX\n"),
            interp::RunStatus::Finished)
            << firstError();
        EXPECT_NEAR(q(121), 30.0, 1e-9);
        EXPECT_NEAR(q(122), 0.0, 1e-9);
        expectAt(10.0, 5.0, 2.0);
    }
}

// The status shows the tilt as spatial angles and the tool in the tilted plane's coordinates
// (the program's), here the point the program went to; after PLANE RESET none.
TEST_F(PlaneTest, StatusShowsTheWorkingPlane) {
    ASSERT_EQ(run("mill5",
                  "1 L X+0 Y+0 Z+100 R0 FMAX\n"
                  "2 PLANE SPATIAL SPA+10 SPB+30 SPC+20 STAY\n"
                  "3 L X+10 Y+5 Z+2 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    const auto plane = k->programStatus().transformations.workingPlane;
    ASSERT_TRUE(plane.has_value());
    EXPECT_NEAR(plane->spatialDeg[0], 10.0, 1e-9);
    EXPECT_NEAR(plane->spatialDeg[1], 30.0, 1e-9);
    EXPECT_NEAR(plane->spatialDeg[2], 20.0, 1e-9);
    EXPECT_NEAR(plane->positionMm[0], 10.0, 1e-9);
    EXPECT_NEAR(plane->positionMm[1], 5.0, 1e-9);
    EXPECT_NEAR(plane->positionMm[2], 2.0, 1e-9);
    ASSERT_EQ(run("mill5",
                  "1 PLANE SPATIAL SPA+0 SPB+90 SPC+0 STAY\n"
                  "2 PLANE RESET STAY\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_FALSE(k->programStatus().transformations.workingPlane.has_value());
}

// SEQ- takes B-30 with C180; the table's turn then leaves the tilted axes turned by 180 about Z
// (Ry(30) Rz(-180) Ry(30) = Rz(180)): (10, 5) is at (-10, -5).
TEST_F(PlaneTest, SequenceMinusTakesTheOtherSolution) {
    ASSERT_EQ(run("mill5",
                  "1 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY SEQ-\n"
                  "2 L X+10 Y+5 Z+2 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(121), -30.0, 1e-9);
    EXPECT_NEAR(std::abs(q(122)), 180.0, 1e-9);
    expectAt(-10.0, -5.0, 2.0);
}

// TURN positions the tables; MOVE keeps the point DIST above the tip on the part: from the tip at
// (0, 0, 10), the point (0, 0, 60) stays; with the tool along the part's +X after B+90 the tip is
// at the part's (-50, 0, 60), the tilted (-60, 0, -50), which are also the axes.
TEST_F(PlaneTest, MoveKeepsThePointAtDistOnThePart) {
    ASSERT_EQ(run("mill5",
                  "1 L X+0 Y+0 Z+10 R0 FMAX\n"
                  "2 PLANE SPATIAL SPA+0 SPB+90 SPC+0 MOVE DIST50 F1000\n"),
              interp::RunStatus::Finished)
        << firstError();
    expectAt(-60.0, 0.0, -50.0);
    EXPECT_NEAR(k->nominalPosition()[Axis::B], 90.0, 1e-9);
    EXPECT_NEAR(k->nominalPosition()[Axis::C], 0.0, 1e-9);
}

// A shift after the tilt acts in the tilted system, a rotation (cycle 10) innermost; PLANE RESET
// turns the tilted shift back into the untilted one: tilted X+5 under B+90 is the part's Z-5.
TEST_F(PlaneTest, ShiftAndRotationComposeWithTheTilt) {
    ASSERT_EQ(run("mill5",
                  "1 PLANE SPATIAL SPA+0 SPB+90 SPC+0 STAY\n"
                  "2 CYCL DEF 7.0 DATUM SHIFT\n3 CYCL DEF 7.1 X+5\n"
                  "4 CYCL DEF 10.0 ROTATION\n5 CYCL DEF 10.1 ROT+90\n"
                  "6 L X+10 Y+0 Z+0 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    // (10, 0, 0) turned by 90 about Z: (0, 10, 0); shifted: (5, 10, 0).
    expectAt(5.0, 10.0, 0.0);
    ASSERT_EQ(run("mill5",
                  "1 PLANE SPATIAL SPA+0 SPB+90 SPC+0 STAY\n"
                  "2 CYCL DEF 7.0 DATUM SHIFT\n3 CYCL DEF 7.1 X+5\n"
                  "4 PLANE RESET STAY\n5 L B+0 C+0 R0 FMAX\n6 L X+0 Y+0 Z+0 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    expectAt(0.0, 0.0, -5.0);
}

TEST_F(PlaneTest, SolutionsOutsideTheLimitsAreAnError) {
    EXPECT_EQ(run("mill5", "1 PLANE SPATIAL SPA+0 SPB+120 SPC+0 TURN FMAX\n"),
              interp::RunStatus::Failed);
    EXPECT_EQ(firstError(),
              "no solution for the rotary axes lies within their soft limits (and the SEQ "
              "chosen): B120.000 C0.000, B-120.000 C180.000");
    EXPECT_EQ(run("mill5", "1 L B+120 FMAX\n"), interp::RunStatus::Failed);
    EXPECT_EQ(firstError(),
              "the move would take axis B to 120.000 deg (machine coordinates), beyond its soft "
              "limit 110.000");
}

TEST_F(PlaneTest, MachinesThatCannotTilt) {
    // mill4's A table tilts about X only: B is out of reach, A+90 tilts towards -Y.
    EXPECT_EQ(run("mill4", "1 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n"), interp::RunStatus::Failed);
    EXPECT_EQ(firstError(),
              "the rotary axes of this machine cannot turn the tool perpendicular to this plane");
    ASSERT_EQ(run("mill4", "1 PLANE SPATIAL SPA+90 SPB+0 SPC+0 TURN FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(120), 90.0, 1e-9);
    EXPECT_NEAR(k->nominalPosition()[Axis::A], 90.0, 1e-9);
    EXPECT_EQ(run("mill", "1 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n"), interp::RunStatus::Failed);
    EXPECT_EQ(firstError(), "PLANE needs rotary axes: this machine has none");
}

// The endless C shows its angle modulo 360: without M126 it moves by the difference from the shown
// angle, with M126 the short way; incremental moves count on.
TEST_F(PlaneTest, EndlessAxisTurnsTheShortWayWithM126) {
    ASSERT_EQ(run("mill5", "1 L C+350 FMAX\n2 L C+10 FMAX\n"), interp::RunStatus::Finished);
    EXPECT_NEAR(k->nominalPosition()[Axis::C], 10.0, 1e-9);  // -340
    ASSERT_EQ(run("mill5", "1 L C+350 FMAX\n2 L C+10 FMAX M126\n3 L C+20 FMAX M127\n"),
              interp::RunStatus::Finished);
    EXPECT_NEAR(k->nominalPosition()[Axis::C], 380.0, 1e-9);  // +20 to 370, then 10 -> 20
    ASSERT_EQ(run("mill5", "1 M126\n2 L C+350 FMAX\n3 L IC+30 FMAX\n4 L C+0 FMAX M94\n"),
              interp::RunStatus::Finished);
    EXPECT_NEAR(k->nominalPosition()[Axis::C], 0.0, 1e-9);  // -10, 20, back to 0
}

// M94 with an axis letter reduces the axes it names (docs/klartext.md); an axis the machine lacks
// is an error at the block, as on the TNC.
TEST_F(PlaneTest, M94NamesOnlyRotaryAxesOfTheMachine) {
    ASSERT_EQ(run("mill5", "1 M126\n2 L C+350 FMAX\n3 L IC+30 FMAX\n4 L C+0 FMAX M94 C\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(k->nominalPosition()[Axis::C], 0.0, 1e-9);  // as M94 without a letter
    EXPECT_EQ(run("mill5", "1 L M94 A\n"), interp::RunStatus::Failed);
    EXPECT_EQ(firstError(), "M94 A: the machine has no rotary axis A");
    EXPECT_EQ(run("mill5", "1 L M94 X\n"), interp::RunStatus::Failed);
    EXPECT_EQ(firstError(), "M94 X: the machine has no rotary axis X");
}

// TCPM: the tip stays at (0, 0, 50) on the part while B turns to 90: the table's Ry(-90) carries
// it to the axes (-50, 0, 0); then C+90 with the tip at (10, 0, 50): Rz(-90) gives (0, -10, 50).
TEST_F(PlaneTest, TcpmComputesTheAxesFromTheTip) {
    ASSERT_EQ(run("mill5",
                  "1 L X+0 Y+0 Z+50 R0 FMAX\n2 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
                  "3 L B+90 F1000\n4 FUNCTION RESET TCPM\n"),
              interp::RunStatus::Finished)
        << firstError();
    expectAt(-50.0, 0.0, 0.0);
    ASSERT_EQ(run("mill5", "1 L X+10 Y+0 Z+50 R0 FMAX\n2 M128\n3 L C+90 F1000\n4 M129\n"),
              interp::RunStatus::Finished)
        << firstError();
    expectAt(0.0, -10.0, 50.0);
    EXPECT_EQ(run("mill", "1 M128\n"), interp::RunStatus::Failed);
    EXPECT_EQ(run("mill5", "1 FUNCTION TCPM F CONT AXIS POS PATHCTRL AXIS\n"),
              interp::RunStatus::Failed);
}

}  // namespace
}  // namespace kerf::klartext
