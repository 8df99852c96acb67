// The tilted working plane and the rotary axes on the built-in machines mill5 (B/C table-table)
// and mill4 (A table), every value derived by hand (docs/klartext.md, "Tilted working plane").
// mill5's pivot is the workpiece origin, so the stream holds (table turn) x (tilt) x program.
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <variant>
#include <vector>

#include <Eigen/Geometry>
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
    // A read of the machine's position (FN 18 ID240/270) is answered with `world`, or without it
    // with the position the stream reached.
    interp::RunStatus run(const std::string& machineName, const std::string& blocks,
                          std::optional<Pose> world = std::nullopt) {
        machine = *machine::loadMachine(machineName);
        KlartextSettings settings;
        settings.machine = &machine;
        settings.ncRoot = dir;
        // The machine file's workpiece origin (mill5: the pivot).
        for (const machine::AxisConfig& axis : machine.axes)
            settings.presetInMachine[*axisFromLetter(axis.letter)] = axis.presetPosition;
        k = std::make_unique<KlartextInterpreter>(sources, settings);
        sink.moves.clear();
        sink.feeds.clear();
        sink.arcs = 0;
        const fs::path path = dir / "P.H";
        writeFileAtomically(path, "0 BEGIN PGM P MM\n" + blocks + "99 END PGM P MM\n");
        if (!k->load(path)) return interp::RunStatus::Failed;
        interp::RunStatus status;
        do {
            status = k->run(sink, 1000);
            if (status == interp::RunStatus::NeedsSync) {
                interp::WorldSnapshot snapshot;
                snapshot.position = world.value_or(k->nominalPosition());
                k->resume(snapshot);
                status = interp::RunStatus::BudgetUsed;
            }
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

    // Keeps the moves (block number, target) the run emitted.
    struct Recorder : canon::Sink {
        void consume(const canon::Command& c) override {
            if (const auto* m = std::get_if<canon::LinearMove>(&c.body)) {
                moves.push_back({c.location.blockNumber, m->target});
                feeds.push_back(m->feed);
            }
            if (const auto* m = std::get_if<canon::RapidMove>(&c.body))
                moves.push_back({c.location.blockNumber, m->target});
            if (std::holds_alternative<canon::ArcMove>(c.body)) ++arcs;
        }
        std::vector<std::pair<int64_t, Pose>> moves;
        std::vector<double> feeds;  // of the linear moves, in order
        int arcs = 0;
    } sink;
    std::vector<Pose> movesOf(int64_t block) const {
        std::vector<Pose> out;
        for (const auto& [at, target] : sink.moves)
            if (at == block) out.push_back(target);
        return out;
    }
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

// What the position display needs on a swivel head (mill5h, head pivot 200 mm above the nose,
// no tool): SPB+30 solves B+30 C0, the table stays, so the axes of a tilted-plane point p are
// a = R (p + s) + h with R = Ry(30), the shift s = (5, 0, 0) programmed after the tilt and the
// head's offset h = 200 (R z - z). Back: p = R^T a - R^T h - s, and R^T h = 200 (z - R^T z) =
// 200 (sin30, 0, 1 - cos30).
TEST_F(PlaneTest, StatusMapsTheAxesIntoTheTiltedPlane) {
    ASSERT_EQ(run("mill5h",
                  "1 L X+0 Y+0 Z+100 R0 FMAX\n"
                  "2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n"
                  "3 CYCL DEF 7.0 DATUM SHIFT\n4 CYCL DEF 7.1 X+5\n"
                  "5 L X+10 Y+5 Z+2 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    const auto plane = k->programStatus().transformations.workingPlane;
    ASSERT_TRUE(plane.has_value());
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    const double rt[9] = {c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c};  // R^T, row by row
    for (size_t i = 0; i < 9; ++i)
        EXPECT_NEAR(plane->axesToProgram[i], rt[i], 1e-9) << i;
    EXPECT_NEAR(plane->programAtAxesZeroMm[0], -200.0 * s - 5.0, 1e-9);
    EXPECT_NEAR(plane->programAtAxesZeroMm[1], 0.0, 1e-9);
    EXPECT_NEAR(plane->programAtAxesZeroMm[2], -200.0 * (1.0 - c), 1e-9);
    EXPECT_EQ(plane->rotaryAxes, axisBit(Axis::B) | axisBit(Axis::C));
    EXPECT_NEAR(plane->rotaryDeg[1], 30.0, 1e-9);
    EXPECT_NEAR(plane->rotaryDeg[2], 0.0, 1e-9);
    // The stream position maps back onto the programmed point.
    const Pose at = k->nominalPosition();
    for (size_t row = 0; row < 3; ++row) {
        double v = plane->programAtAxesZeroMm[row];
        for (size_t column = 0; column < 3; ++column)
            v += plane->axesToProgram[3 * row + column] * at.values[column];
        EXPECT_NEAR(v, (std::array<double, 3>{10.0, 5.0, 2.0})[row], 1e-9) << row;
    }
}

// FN 18 of the tilt, with the TNC 320's IDs (docs/klartext.md, "FN 18 of the tilt"): ID210 NR5
// the spatial angles, NR6 the tilt of the program run (-1 active), NR7 manual operation's (none),
// ID240 the rotary axes' machine angles, ID270 the tilted plane's coordinates, ID280 NR1 TCPM.
// mill5 with SPB+30 TURN: B+30 C0, the origin at the pivot, so the axes equal the program's
// coordinates of the tilted plane.
TEST_F(PlaneTest, SysreadReadsTheTilt) {
    ASSERT_EQ(run("mill5",
                  "1 L X+0 Y+0 Z+100 R0 FMAX\n"
                  "2 FN 18: SYSREAD Q10 = ID210 NR6\n"
                  "3 PLANE SPATIAL SPA+10 SPB+30 SPC+20 STAY\n"
                  "4 FN 18: SYSREAD Q1 = ID210 NR5 IDX1\n"
                  "5 FN 18: SYSREAD Q2 = ID210 NR5 IDX2\n"
                  "6 FN 18: SYSREAD Q3 = ID210 NR5 IDX3\n"
                  "7 FN 18: SYSREAD Q4 = ID210 NR6\n"
                  "8 FN 18: SYSREAD Q5 = ID210 NR7\n"
                  "9 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX SEQ+ TABLE ROT\n"
                  "10 L X+10 Y+5 Z+2 FMAX\n"
                  "11 FN 18: SYSREAD Q6 = ID240 NR1 IDX5\n"
                  "12 FN 18: SYSREAD Q7 = ID270 NR1 IDX1\n"
                  "13 FN 18: SYSREAD Q8 = ID270 NR1 IDX3\n"
                  "14 PLANE RESET STAY\n"
                  "15 FN 18: SYSREAD Q9 = ID210 NR6\n"
                  "16 FN 18: SYSREAD Q11 = ID210 NR5 IDX2\n"
                  "17 FN 18: SYSREAD Q12 = ID280 NR1\n"),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(10), 0.0, 1e-12);
    EXPECT_NEAR(q(1), 10.0, 1e-9);
    EXPECT_NEAR(q(2), 30.0, 1e-9);
    EXPECT_NEAR(q(3), 20.0, 1e-9);
    EXPECT_NEAR(q(4), -1.0, 1e-12);
    EXPECT_NEAR(q(5), 0.0, 1e-12);
    EXPECT_NEAR(q(6), 30.0, 1e-9);
    EXPECT_NEAR(q(7), 10.0, 1e-9);
    EXPECT_NEAR(q(8), 2.0, 1e-9);
    EXPECT_NEAR(q(9), 0.0, 1e-12);
    EXPECT_NEAR(q(11), 0.0, 1e-12);
    EXPECT_NEAR(q(12), 0.0, 1e-12);
    // TCPM: C+90 turns the part by Rz(-90), so the tip at (10, 0, 50) on the part has the axes
    // at (0, -10, 50); ID270 reads the tip, the program's coordinate, not the axes.
    Pose axes{};
    axes[Axis::Y] = -10.0;
    axes[Axis::Z] = 50.0;
    axes[Axis::C] = 90.0;
    ASSERT_EQ(run("mill5",
                  "1 L X+10 Y+0 Z+50 R0 FMAX\n2 M128\n3 L C+90 F1000\n"
                  "4 FN 18: SYSREAD Q1 = ID280 NR1\n"
                  "5 FN 18: SYSREAD Q2 = ID270 NR1 IDX1\n"
                  "6 FN 18: SYSREAD Q3 = ID270 NR1 IDX2\n"
                  "7 FN 18: SYSREAD Q4 = ID240 NR1 IDX6\n"
                  "8 M129\n9 FN 18: SYSREAD Q5 = ID280 NR1\n",
                  axes),
              interp::RunStatus::Finished)
        << firstError();
    EXPECT_NEAR(q(1), -1.0, 1e-12);
    EXPECT_NEAR(q(2), 10.0, 1e-9);
    EXPECT_NEAR(q(3), 0.0, 1e-9);
    EXPECT_NEAR(q(4), 90.0, 1e-9);
    EXPECT_NEAR(q(5), 0.0, 1e-12);
}

// An arc in the plane the B swivel head of mill5h turns by SPB+30 (B+30 C0, no tool): the axes
// of a tilted-plane point p are a = R p + h, R = Ry(30), h = 200 (R z - z). The quarter circle of
// radius 10 about the origin leaves as straight pieces of the axes whose ends lie on the circle,
// R^T (a - h) = (10 cos t, 10 sin t, 0); half the path tolerance (0.005 mm) allows a chord of at
// most 2 acos(1 - 0.005 / 10) = 0.0632 rad, so a quarter takes 32 (the next power of two above
// 24.8) pieces, the last at R (0, 10, 0) + h = (100, 10, 200 (cos30 - 1)).
TEST_F(PlaneTest, ArcInTheSwivelHeadsObliquePlane) {
    ASSERT_EQ(run("mill5h",
                  "1 L X+0 Y+0 Z+100 R0 FMAX\n"
                  "2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n"
                  "3 L X+10 Y+0 Z+0 FMAX\n"
                  "4 CC X+0 Y+0\n"
                  "5 C X+0 Y+10 DR+ F500\n"),
              interp::RunStatus::Finished)
        << firstError();
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    const Vec3 h(200.0 * s, 0.0, 200.0 * (c - 1.0));
    Eigen::Matrix3d r;
    r << c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c;
    const std::vector<Pose> arc = movesOf(5);
    ASSERT_EQ(arc.size(), 32u);
    EXPECT_EQ(sink.arcs, 0);
    for (const Pose& a : arc) {
        const Vec3 p = r.transpose() * (a.xyz() - h);
        EXPECT_NEAR(p.z(), 0.0, 1e-9);
        EXPECT_NEAR(std::hypot(p.x(), p.y()), 10.0, 1e-9);
    }
    EXPECT_NEAR(arc.back()[Axis::X], 100.0, 1e-9);
    EXPECT_NEAR(arc.back()[Axis::Y], 10.0, 1e-9);
    EXPECT_NEAR(arc.back()[Axis::Z], 200.0 * (c - 1.0), 1e-9);
    expectAt(100.0, 10.0, 200.0 * (c - 1.0));
}

// Radius compensation in the same plane, tool R5 (L0): from (20, -10) RL to (10, 0), then along
// -X to (-10, 0): the tool runs 5 to the left, at Y -5. The activation ends perpendicular to the
// next element, at (10, -5); the compensated line ends perpendicular to itself before R0, at
// (-10, -5). On the axes: R (10, -5, 0) + h = (10c + 100, -5, -10s + 200(c - 1)) and
// R (-10, -5, 0) + h = (-10c + 100, -5, 10s + 200(c - 1)), one straight move each.
TEST_F(PlaneTest, RadiusCompensationInTheSwivelHeadsObliquePlane) {
    ASSERT_EQ(run("mill5h",
                  "1 TOOL DEF 1 L+0 R+5\n2 TOOL CALL 1 Z\n"
                  "3 L X+0 Y+0 Z+100 R0 FMAX\n"
                  "4 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n"
                  "5 L X+20 Y-10 Z+0 R0 FMAX\n"
                  "6 L X+10 Y+0 RL F500\n"
                  "7 L X-10 Y+0\n"
                  "8 L X-20 Y-10 R0\n"),
              interp::RunStatus::Finished)
        << firstError();
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    const std::vector<Pose> activation = movesOf(6), along = movesOf(7);
    ASSERT_FALSE(activation.empty());
    ASSERT_EQ(along.size(), 1u);
    EXPECT_NEAR(activation.back()[Axis::X], 10.0 * c + 100.0, 1e-9);
    EXPECT_NEAR(activation.back()[Axis::Y], -5.0, 1e-9);
    EXPECT_NEAR(activation.back()[Axis::Z], -10.0 * s + 200.0 * (c - 1.0), 1e-9);
    EXPECT_NEAR(along[0][Axis::X], -10.0 * c + 100.0, 1e-9);
    EXPECT_NEAR(along[0][Axis::Y], -5.0, 1e-9);
    EXPECT_NEAR(along[0][Axis::Z], 10.0 * s + 200.0 * (c - 1.0), 1e-9);
}

// TCPM with a quarter circle of radius 20 about the C table's axis while C turns 90: the table
// carries the tip along the circle, so X, Y, Z stand at (20, 0, 50) (Rz(-90) (0, 20) = (20, 0))
// and the one move turns C alone. It takes as long as the arc's 10 pi mm at F 1000: its feed is
// 90 deg / (10 pi / 1000) min = 2864.789 deg/min (it was 0, a move that never ended).
TEST_F(PlaneTest, TcpmCircleAboutTheTableAxisTurnsTheTableAtTheTipsFeed) {
    ASSERT_EQ(run("mill5",
                  "1 L X+20 Y+0 Z+50 R0 FMAX\n2 M128\n3 CC X+0 Y+0\n"
                  "4 C X+0 Y+20 C+90 DR+ F1000\n5 M129\n"),
              interp::RunStatus::Finished)
        << firstError();
    const std::vector<Pose> arc = movesOf(4);
    ASSERT_EQ(arc.size(), 1u);
    EXPECT_NEAR(arc[0][Axis::X], 20.0, 1e-9);
    EXPECT_NEAR(arc[0][Axis::Y], 0.0, 1e-9);
    EXPECT_NEAR(arc[0][Axis::Z], 50.0, 1e-9);
    EXPECT_NEAR(arc[0][Axis::C], 90.0, 1e-9);
    ASSERT_EQ(sink.feeds.size(), 1u);
    EXPECT_NEAR(sink.feeds[0], 90.0 * 1000.0 / (10.0 * M_PI), 1e-6);
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
// The seed's cycle 19 example with F (chapter 10: 19.1 A+0 B+45 C+0 F5000 DIST50, then L Z+80
// and L Y-10) on mill5h: the head stays at B+45 for the moves after the cycle. Tool L 60:
// the head adds (Ry(45) - I)(0, 0, 260) = (183.848, 0, -76.152); the tilted point (-8.5, -10, 80)
// is Ry(45) (-8.5, -10, 80) = (50.558, -10, 62.579) on the part, so the axes stand at
// (234.406, -10, -13.573).
TEST_F(PlaneTest, Cycle19WithFeedKeepsTheHeadTurnedForTheNextMoves) {
    ASSERT_EQ(run("mill5h",
                  "1 TOOL DEF 1 L+60 R+3.5\n"
                  "1 TOOL CALL 1 Z S2000\n"
                  "2 L Z+100 R0 FMAX\n"
                  "3 L X+25 Y+10 R0 FMAX\n"
                  "4 CYCL DEF 19.0 WORKING PLANE\n"
                  "5 CYCL DEF 19.1 A+0 B+45 C+0 F5000 DIST50\n"
                  "6 L Z+80 R0 FMAX\n"
                  "7 L X-8.5 Y-10 R0 FMAX\n"),
              interp::RunStatus::Finished)
        << firstError();
    ASSERT_EQ(movesOf(5).size(), 1u);
    EXPECT_NEAR(movesOf(5)[0][Axis::B], 45.0, 1e-9);
    for (const int64_t block : {6, 7}) {
        ASSERT_EQ(movesOf(block).size(), 1u) << block;
        EXPECT_NEAR(movesOf(block)[0][Axis::B], 45.0, 1e-9) << block;
    }
    const double s = std::sqrt(0.5);
    const Pose end = movesOf(7)[0];
    EXPECT_NEAR(end[Axis::X], -8.5 * s + 80.0 * s + 260.0 * s, 1e-6);
    EXPECT_NEAR(end[Axis::Y], -10.0, 1e-9);
    EXPECT_NEAR(end[Axis::Z], 8.5 * s + 80.0 * s + 260.0 * s - 260.0, 1e-6);
}

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
    EXPECT_EQ(run("mill5", "1 FUNCTION TCPM F TCP AXIS POS REFPNT CENTER-CENTER\n"),
              interp::RunStatus::Failed);
}

// The tip of a stream pose on mill5's part (origin at the pivot): Rz(C) Ry(B) axes.
Vec3 tipOnMill5(const Pose& axes) {
    using machine::principalRotation;
    return principalRotation('C', axes[Axis::C]) * principalRotation('B', axes[Axis::B]) *
           axes.xyz();
}

// TCPM in a tilted plane (PLANE SPATIAL SPB+90 TURN: B+90 C0): the program's X, Y, Z are tip
// positions in the plane, Ry(90) p = (z, y, -x) on the part. (0, 0, 50) is the part's (50, 0, 0),
// at the axes Ry(-90) (50, 0, 0) = (0, 0, 50) while B stands at 90. B+60 keeps the tip there: the
// axes go to Ry(-60) (50, 0, 0) = (25, 0, 25 sqrt 3). X+20 in the plane is the part's (50, 0, -20):
// Ry(-60) (50, 0, -20) = (25 + 10 sqrt 3, 0, 25 sqrt 3 - 10). Every piece of both blocks keeps
// the tip on the part's line within half the path tolerance.
TEST_F(PlaneTest, TcpmInTheTiltedPlaneKeepsTheTipInThePlanesCoordinates) {
    ASSERT_EQ(run("mill5",
                  "1 L X+0 Y+0 Z+100 R0 FMAX\n"
                  "2 PLANE SPATIAL SPA+0 SPB+90 SPC+0 TURN FMAX SEQ+\n"
                  "3 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
                  "4 L X+0 Y+0 Z+50 FMAX\n"
                  "5 L B+60 F1000\n"
                  "6 L X+20\n"
                  "7 FUNCTION RESET TCPM\n"),
              interp::RunStatus::Finished)
        << firstError();
    const std::vector<Pose> at = movesOf(4), turn = movesOf(5), line = movesOf(6);
    ASSERT_EQ(at.size(), 1u);
    EXPECT_NEAR(at[0][Axis::X], 0.0, 1e-9);
    EXPECT_NEAR(at[0][Axis::Z], 50.0, 1e-9);
    EXPECT_NEAR(at[0][Axis::B], 90.0, 1e-9);
    ASSERT_FALSE(turn.empty());
    for (const Pose& p : turn)
        EXPECT_LE((tipOnMill5(p) - Vec3(50, 0, 0)).norm(), 0.005);
    EXPECT_NEAR(turn.back()[Axis::X], 25.0, 1e-9);
    EXPECT_NEAR(turn.back()[Axis::Z], 25.0 * std::sqrt(3.0), 1e-9);
    EXPECT_NEAR(turn.back()[Axis::B], 60.0, 1e-9);
    ASSERT_FALSE(line.empty());
    for (const Pose& p : line) {
        const Vec3 tip = tipOnMill5(p);
        EXPECT_NEAR(tip.x(), 50.0, 1e-9);
        EXPECT_NEAR(tip.y(), 0.0, 1e-9);
    }
    EXPECT_NEAR(line.back()[Axis::X], 25.0 + 10.0 * std::sqrt(3.0), 1e-9);
    EXPECT_NEAR(line.back()[Axis::Z], 25.0 * std::sqrt(3.0) - 10.0, 1e-9);
    // Off again, the plane counts from the solved B+90 (as without TCPM); the axes stay.
    expectAt(25.0 + 10.0 * std::sqrt(3.0), 0.0, 25.0 * std::sqrt(3.0) - 10.0);
    // The tables are the program's with TCPM on: PLANE may only STAY.
    EXPECT_EQ(run("mill5", "1 M128\n2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\n"),
              interp::RunStatus::Failed);
    EXPECT_EQ(run("mill5", "1 M128\n2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 STAY\n3 M129\n"),
              interp::RunStatus::Finished)
        << firstError();
}

// AXIS SPAT in the plane tilted by SPB+30 (B+30 C0): B+15 is the tool's spatial angle in the
// plane, so on the part it stands at Ry(30) Ry(15) Z: the axes turn to B+45 C0 (the nearer of
// B+45 C0 and B-45 C180). The tip stays at the plane's (0, 0, 50), Ry(30) (0, 0, 50) =
// (25, 0, 25 sqrt 3) on the part: the axes end at Ry(-45) of it = (50 sin -15, 0, 50 cos 15).
TEST_F(PlaneTest, TcpmAxisSpatTurnsTheToolToSpatialAnglesInThePlane) {
    ASSERT_EQ(run("mill5",
                  "1 L X+0 Y+0 Z+100 R0 FMAX\n"
                  "2 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX SEQ+\n"
                  "3 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS\n"
                  "4 L X+0 Y+0 Z+50 FMAX\n"
                  "5 L A+0 B+15 C+0 F1000\n"
                  "6 FUNCTION RESET TCPM\n"),
              interp::RunStatus::Finished)
        << firstError();
    const std::vector<Pose> turn = movesOf(5);
    ASSERT_FALSE(turn.empty());
    const double r = M_PI / 180.0;
    EXPECT_NEAR(turn.back()[Axis::B], 45.0, 1e-9);
    EXPECT_NEAR(turn.back()[Axis::C], 0.0, 1e-9);
    EXPECT_NEAR(turn.back()[Axis::X], 50.0 * std::sin(-15.0 * r), 1e-9);
    EXPECT_NEAR(turn.back()[Axis::Z], 50.0 * std::cos(15.0 * r), 1e-9);
    for (const Pose& p : turn)
        EXPECT_LE((tipOnMill5(p) - Vec3(25.0, 0.0, 25.0 * std::sqrt(3.0))).norm(), 0.005);
    // A direction the tables cannot reach: the B table's 110 deg leave 20 deg below the part.
    EXPECT_EQ(run("mill5",
                  "1 L X+0 Y+0 Z+100 R0 FMAX\n2 FUNCTION TCPM F TCP AXIS SPAT PATHCTRL AXIS\n"
                  "3 L B+120 F1000\n"),
              interp::RunStatus::Failed);
}

// F CONT: the circle of TcpmCircleAboutTheTableAxisTurnsTheTableAtTheTipsFeed, where only C
// turns, now moves at the axes' own feed: 1000 deg/min instead of the tip's 2864.789.
TEST_F(PlaneTest, TcpmFeedContIsTheAxesFeed) {
    ASSERT_EQ(run("mill5",
                  "1 L X+20 Y+0 Z+50 R0 FMAX\n2 FUNCTION TCPM F CONT AXIS POS PATHCTRL AXIS\n"
                  "3 CC X+0 Y+0\n4 C X+0 Y+20 C+90 DR+ F1000\n5 FUNCTION RESET TCPM\n"),
              interp::RunStatus::Finished)
        << firstError();
    ASSERT_EQ(movesOf(4).size(), 1u);
    ASSERT_EQ(sink.feeds.size(), 1u);
    EXPECT_NEAR(sink.feeds[0], 1000.0, 1e-9);
}

// PATHCTRL VECTOR: from B+30 C0 (tool (1/2, 0, sqrt 3 / 2)) to B+30 C+90 (tool (0, 1/2, sqrt 3 /
// 2)) the tool turns on the great circle between them, not on B's cone: half way it points along
// their sum (1/2, 1/2, sqrt 3) / sqrt 3.5, i.e. C+45 and B = acos sqrt(6/7) = 22.21 deg. Every
// piece's tool direction lies in the plane of the two (normal: their cross product) within the
// tolerance at the tool's reach, and the tip stays at Ry(30) (0, 0, 50) = (25, 0, 25 sqrt 3).
// With PATHCTRL AXIS, B stays at 30.
TEST_F(PlaneTest, TcpmPathctrlVectorTurnsTheToolInOnePlane) {
    const std::string blocks =
        "1 L X+0 Y+0 Z+50 R0 FMAX\n2 L B+30 C+0 FMAX\n"
        "3 FUNCTION TCPM F TCP AXIS POS PATHCTRL VECTOR\n"
        "4 L C+90 F1000\n5 FUNCTION RESET TCPM\n";
    ASSERT_EQ(run("mill5", blocks), interp::RunStatus::Finished) << firstError();
    const std::vector<Pose> turn = movesOf(4);
    ASSERT_GE(turn.size(), 2u);
    const double r = M_PI / 180.0;
    const Vec3 from(0.5, 0.0, std::sqrt(3.0) / 2.0), to(0.0, 0.5, std::sqrt(3.0) / 2.0);
    const Vec3 normal = from.cross(to).normalized();
    double lowestB = 90.0;
    for (const Pose& p : turn) {
        const double b = p[Axis::B] * r, c = p[Axis::C] * r;
        const Vec3 tool(std::cos(c) * std::sin(b), std::sin(c) * std::sin(b), std::cos(b));
        EXPECT_LE(std::abs(tool.dot(normal)), 1e-9);
        EXPECT_LE((tipOnMill5(p) - Vec3(25.0, 0.0, 25.0 * std::sqrt(3.0))).norm(), 0.005);
        lowestB = std::min(lowestB, p[Axis::B]);
        if (std::abs(p[Axis::C] - 45.0) < 1e-9) {
            EXPECT_NEAR(p[Axis::B], std::acos(std::sqrt(6.0 / 7.0)) / r, 1e-9);
        }
    }
    EXPECT_NEAR(lowestB, std::acos(std::sqrt(6.0 / 7.0)) / r, 1e-9);
    EXPECT_NEAR(turn.back()[Axis::B], 30.0, 1e-9);
    EXPECT_NEAR(turn.back()[Axis::C], 90.0, 1e-9);
    std::string axisPath = blocks;
    axisPath.replace(axisPath.find("VECTOR"), 6, "AXIS");
    ASSERT_EQ(run("mill5", axisPath), interp::RunStatus::Finished) << firstError();
    for (const Pose& p : movesOf(4))
        EXPECT_NEAR(p[Axis::B], 30.0, 1e-9);
}

// Thread milling under TCPM in a tilted plane: PLANE SPATIAL SPB+30 TURN solves B+30 C0, M128
// keeps the tip at the plane's (10, 20, 50) while the tables turn on to B+40 C+20, and cycle 262
// (nominal diameter 10, tool of radius 0 without a tool table) mills its helix about the hole's
// axis (10, 20) in the plane: every piece end's tip on the part, Rz(C) Ry(B) axes, turned back
// into the plane by Ry(-30), lies within 5 of that axis (half the path tolerance, 0.005, for the
// pieces) and reaches 5 there. 263, 264, 265 and 267 run there too. Tapping (cycle 207: one
// spindle-synchronised straight move of the axes) is refused while TCPM is on, with the reason.
TEST_F(PlaneTest, ThreadMillingRunsUnderTcpmInTheTiltedPlane) {
    const std::string before =
        "1 TOOL CALL 5 Z S1000\n2 L X+10 Y+20 Z+50 R0 FMAX M3\n"
        "3 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX\n4 M128\n5 L B+40 C+20 F1000\n";
    const std::string thread262 =
        "6 CYCL DEF 262 THREAD MILLING\n"
        "  Q335=10\n  Q239=+1.5\n  Q201=-6\n  Q355=0\n  Q253=750\n  Q351=+1\n"
        "  Q200=2\n  Q203=+0\n  Q204=20\n  Q207=500\n  Q512=0\n"
        "7 CYCL CALL\n";
    ASSERT_EQ(run("mill5", before + thread262), interp::RunStatus::Finished) << firstError();
    const std::vector<Pose> helix = movesOf(7);
    ASSERT_GT(helix.size(), 10u);
    const Eigen::Matrix3d back = machine::principalRotation('B', -30.0);
    double widest = 0.0;
    for (const Pose& p : helix) {
        const Vec3 inPlane = back * tipOnMill5(p);
        const double radius = std::hypot(inPlane.x() - 10.0, inPlane.y() - 20.0);
        EXPECT_LE(radius, 5.0 + 0.005);
        widest = std::max(widest, radius);
    }
    EXPECT_NEAR(widest, 5.0, 0.005);
    const std::vector<std::string> others{
        "6 CYCL DEF 263 THREAD MLLNG/CNTSNKG\n"
        "  Q335=10\n  Q239=+1.5\n  Q201=-6\n  Q356=-8\n  Q253=750\n  Q351=+1\n"
        "  Q200=2\n  Q357=0.2\n  Q358=+0\n  Q359=+0\n  Q203=+0\n  Q204=20\n"
        "  Q254=150\n  Q207=500\n  Q512=0\n"
        "7 CYCL CALL\n",
        "6 CYCL DEF 264 THREAD DRILLNG/MLLNG\n"
        "  Q335=10\n  Q239=+1.5\n  Q201=-6\n  Q356=-8\n  Q253=750\n  Q351=+1\n"
        "  Q202=5\n  Q258=0.2\n  Q257=0\n  Q256=0.2\n  Q358=-1\n  Q359=1\n"
        "  Q200=2\n  Q203=+0\n  Q204=20\n  Q206=150\n  Q207=500\n  Q512=100\n"
        "7 CYCL CALL\n",
        "6 CYCL DEF 265 HEL. THREAD DRLG/MLG\n"
        "  Q335=10\n  Q239=+1.5\n  Q201=-3\n  Q253=750\n  Q358=-1\n  Q359=1\n"
        "  Q360=1\n  Q200=2\n  Q203=+0\n  Q204=20\n  Q254=150\n  Q207=500\n"
        "7 CYCL CALL\n",
        "6 CYCL DEF 267 OUTSIDE THREAD MLLNG\n"
        "  Q335=10\n  Q239=+1.5\n  Q201=-3\n  Q355=1\n  Q253=750\n  Q351=+1\n"
        "  Q200=2\n  Q358=+0\n  Q359=+0\n  Q203=+0\n  Q204=20\n  Q254=150\n"
        "  Q207=500\n  Q512=0\n"
        "7 CYCL CALL\n"};
    for (const std::string& cycle : others) {
        EXPECT_EQ(run("mill5", before + cycle), interp::RunStatus::Finished)
            << cycle << firstError();
        EXPECT_FALSE(movesOf(7).empty()) << cycle;
    }
    EXPECT_EQ(run("mill5", before + "6 CYCL DEF 207 RIGID TAPPING\n  Q200=2\n  Q201=-6\n  "
                                    "Q239=+1\n  Q203=+0\n  Q204=20\n7 CYCL CALL\n"),
              interp::RunStatus::Failed);
    EXPECT_NE(firstError().find("switch TCPM off first"), std::string::npos) << firstError();
}

// PATHCTRL VECTOR turns the tool on the great circle between its directions, which can lean it
// further than either end: from B+108 C0, tool (sin108, 0, cos108), to B+108 C+90, tool
// (0, sin108, cos108), the middle direction (sin108/2, sin108/2, cos108) / 0.740099 leans
// acos(cos108 / 0.740099) = acos(-0.417535) = 114.679 deg from Z, so B passes 110 although both
// ends stand at 108: the block is refused at its line before anything of it leaves. From B+100
// the middle leans acos(cos100 / sqrt(sin100^2 / 2 + cos100^2)) = 104.002 deg: the block runs,
// and B reaches that lean in its middle (C+45), a piece end.
TEST_F(PlaneTest, PathctrlVectorKeepsTheRotaryLimitsAlongTheBlock) {
    auto blocks = [](int b) {
        return "1 L X+0 Y+0 Z+50 R0 FMAX\n2 FUNCTION TCPM F TCP AXIS POS PATHCTRL VECTOR\n"
               "3 L B+" +
               std::to_string(b) + " C+0 F3000\n4 L C+90 F3000\n5 FUNCTION RESET TCPM\n";
    };
    ASSERT_EQ(run("mill5", blocks(100)), interp::RunStatus::Finished) << firstError();
    double highestB = 0.0;
    for (const Pose& p : movesOf(4))
        highestB = std::max(highestB, p[Axis::B]);
    const double c100 = std::cos(100.0 * M_PI / 180.0), s100 = std::sin(100.0 * M_PI / 180.0);
    EXPECT_NEAR(highestB,
                std::acos(c100 / std::sqrt(s100 * s100 / 2.0 + c100 * c100)) * 180.0 / M_PI, 1e-9);
    EXPECT_EQ(run("mill5", blocks(108)), interp::RunStatus::Failed);
    const Diagnostic& d = k->diagnostics().front();
    EXPECT_EQ(d.line, 5u);  // block 4
    EXPECT_NE(d.message().find("the move would take axis B to 11"), std::string::npos)
        << d.message();
    EXPECT_NE(d.message().find("beyond its soft limit 110.000"), std::string::npos) << d.message();
    EXPECT_TRUE(movesOf(4).empty());
}

}  // namespace
}  // namespace kerf::klartext
