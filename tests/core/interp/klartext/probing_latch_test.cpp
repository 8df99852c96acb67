// Touches from the machine's latch (settings.touchesFromMachine, docs/probing.md "How a cycle
// runs"): each touch leaves the interpreter as a probe move and a sync point, and the cycle goes
// on from the position the machine latched. A stand-in machine latches here: it moves the tip
// along each probe move and finds by bisection where its surface is first touched, the surface
// the move carries (the ball on the placed, machined part) or one the test moves elsewhere.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"
#include "core/tables/tool_table.h"
#include "tests/core/interp/klartext/latching_machine.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class ProbingLatchTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_probing_latch_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    // Runs the program: with `machine`, its touches come from that machine's latch.
    interp::RunStatus run(const std::string& body, LatchingMachine* latching) {
        KlartextSettings settings;
        settings.machine = &machineConfig;
        settings.tools = &tools;
        settings.ncRoot = dir;
        settings.presetInMachine = Pose{{0.0, 0.0, -400.0}};
        settings.touchesFromMachine = latching != nullptr;
        interpreter = std::make_unique<KlartextInterpreter>(sources, settings);
        writeFileAtomically(dir / "P.H", "0 BEGIN PGM P MM\n" + body + "99 END PGM P MM\n");
        if (!interpreter->load(dir / "P.H")) return interp::RunStatus::Failed;
        LatchingMachine plain([](const canon::ProbeSurface&, const Vec3&) { return false; });
        return runLatched(*interpreter, latching != nullptr ? *latching : plain);
    }
    double q(uint16_t index) const { return interpreter->parameters().get(QRef{QKind::Q, index}); }
    std::string firstError() const {
        for (const Diagnostic& d : interpreter->diagnostics())
            if (d.severity == Severity::Error) return d.code + ": " + d.format();
        return {};
    }

    fs::path dir;
    machine::MachineConfig machineConfig = *machine::parseMachine(
        "base = \"mill\"\n[simulation.setup]\nshift = [1.5, -0.8, -0.2]\nrotation = 0.7\n",
        "test.toml");
    // The probe (ball radius 2) and a D10 end mill.
    tables::ToolTable tools = *tables::ToolTable::parse(
        "BEGIN TOOL.T MM\nT    NAME   L      R      TP_NO\n"
        "1    TS     +50    +2     1\n"
        "5    D10    +80    +5\n[END]\n");
    program::SourceRegistry sources;
    std::unique_ptr<KlartextInterpreter> interpreter;
};

// A 100 x 60 x 40 blank, top at Z 0, a pocket of diameter 30 at (70, 30) 10 deep; then 400 on
// the front face, 411 the datum at the blank's centre, 421 the pocket.
const std::string kSetUpAndMeasure =
    "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
    "3 TOOL CALL 5 Z S3000\n4 L Z+100 R0 FMAX M3\n"
    "5 CYCL DEF 252 CIRCULAR POCKET\n  Q215=0\n  Q223=30\n  Q368=0\n  Q207=500\n"
    "  Q351=+1\n  Q201=-10\n  Q202=5\n  Q369=0\n  Q206=150\n  Q338=0\n"
    "  Q200=2\n  Q203=+0\n  Q204=20\n  Q370=1\n  Q366=0\n  Q385=300\n  Q439=0\n"
    "6 L X+70 Y+30 R0 FMAX M99\n7 L Z+100 R0 FMAX M5\n8 TOOL CALL 1 Z\n"
    "9 L X-20 Y-20 Z+50 R0 FMAX\n"
    "10 TCH PROBE 400 BASIC ROTATION\n  Q263=+10\n  Q264=+0\n  Q265=+80\n  Q266=+0\n"
    "  Q272=+2\n  Q267=+1\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=1\n  Q307=0\n  Q305=0\n"
    "11 TCH PROBE 411 DATUM OUTSIDE RECTAN.\n  Q321=+50\n  Q322=+30\n  Q323=100\n  Q324=60\n"
    "  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=1\n  Q305=0\n  Q331=+0\n  Q332=+0\n  Q303=+1\n"
    "  Q381=0\n  Q382=+0\n  Q383=+0\n  Q384=+0\n  Q333=+0\n"
    "12 FN 0: Q1 = Q151\n13 FN 0: Q2 = Q152\n"
    "14 TCH PROBE 421 MEASURE HOLE\n  Q273=+20\n  Q274=+0\n  Q262=30\n  Q325=+0\n"
    "  Q247=+90\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=1\n  Q275=0\n  Q276=0\n  Q279=0\n"
    "  Q280=0\n  Q281=0\n  Q309=0\n  Q330=0\n  Q423=4\n  Q365=1\n"
    "15 L X+0 Y+0 Z+10 R0 FMAX\n";

Vec2 turned(const Vec2& v, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    return {std::cos(a) * v.x() - std::sin(a) * v.y(), std::sin(a) * v.x() + std::cos(a) * v.y()};
}

TEST_F(ProbingLatchTest, LatchedTouchesOnTheMisplacedPartGiveTheValuesOfTheGeometry) {
    LatchingMachine machine(
        [](const canon::ProbeSurface& surface, const Vec3& tip) { return surface.touches(tip); });
    ASSERT_EQ(run(kSetUpAndMeasure, &machine), interp::RunStatus::Finished) << firstError();
    // Every touch went to the machine: 2 of 400, 4 of 411, 4 of 421, and none was a feed move
    // of the interpreter's own to a trigger point.
    EXPECT_EQ(machine.probeMoves, 10);
    EXPECT_EQ(machine.probingFeedMoves, 0);
    // By hand: the part is turned by 0.7 degrees about the programmed origin and shifted by
    // (1.5, -0.8). 400 measures the front face's angle; 411 the blank's centre in the turned
    // system, the real corner turned back plus half the sides.
    const Vec2 corner = turned({1.5, -0.8}, -0.7);
    EXPECT_NEAR(q(1), corner.x() + 50.0, 0.002);
    EXPECT_NEAR(q(2), corner.y() + 30.0, 0.002);
    // 421 in the system whose origin is the real centre, turned by 0.7: the pocket lies where the
    // tool went, (70, 30) of the start preset; the D10 cut a wall of radius 15.
    const Vec2 centre = turned({50.0, 30.0}, 0.7) + Vec2(1.5, -0.8);
    const Vec2 pocket = turned(Vec2(70.0, 30.0) - centre, -0.7);
    EXPECT_NEAR(q(151), pocket.x(), 0.002);
    EXPECT_NEAR(q(152), pocket.y(), 0.002);
    EXPECT_NEAR(q(153), 30.0, 0.002);
    // L X+0 Y+0 ends over the real centre.
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::X], centre.x(), 0.002);
    EXPECT_NEAR(interpreter->nominalPosition()[Axis::Y], centre.y(), 0.002);

    // The plain run decides the same touches on the same part: the latch's bisection finds them
    // to far below a micrometre.
    const double latched[] = {q(1), q(2), q(151), q(152), q(153)};
    ASSERT_EQ(run(kSetUpAndMeasure, nullptr), interp::RunStatus::Finished) << firstError();
    const double plain[] = {q(1), q(2), q(151), q(152), q(153)};
    for (size_t i = 0; i < std::size(plain); ++i)
        EXPECT_NEAR(latched[i], plain[i], 1e-6) << i;
}

TEST_F(ProbingLatchTest, TheResultsFollowTheDrivesWhereTheyDisagreeWithTheModel) {
    // The drives' probe input sees the part 0.3 mm further in +X than the interpreter's model
    // of it: the datum of 411 is where the drives touched, moved by (0.3, 0) of the start
    // preset, which is (0.3 cos 0.7, -0.3 sin 0.7) in the turned system. 400's angle stays: the
    // face moves parallel to itself.
    LatchingMachine machine([](const canon::ProbeSurface& surface, const Vec3& tip) {
        return surface.touches(tip - Vec3(0.3, 0.0, 0.0));
    });
    ASSERT_EQ(run(kSetUpAndMeasure, &machine), interp::RunStatus::Finished) << firstError();
    const Vec2 corner = turned({1.5, -0.8}, -0.7);
    const Vec2 moved = turned({0.3, 0.0}, -0.7);
    EXPECT_NEAR(q(1), corner.x() + 50.0 + moved.x(), 0.002);
    EXPECT_NEAR(q(2), corner.y() + 30.0 + moved.y(), 0.002);
    EXPECT_GT(std::abs(q(1) - (corner.x() + 50.0)), 0.29);
}

TEST_F(ProbingLatchTest, AProbeMoveWithoutATouchIsTheManualsError) {
    // The second point of 400 lies beyond the blank's end (X 100): nothing within DIST there.
    const std::string program =
        "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
        "3 TOOL CALL 1 Z\n4 L X-20 Y-20 Z+50 R0 FMAX\n"
        "5 TCH PROBE 400 BASIC ROTATION\n  Q263=+10\n  Q264=+0\n  Q265=+130\n  Q266=+0\n"
        "  Q272=+2\n  Q267=+1\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=1\n  Q307=0\n"
        "  Q305=0\n";
    LatchingMachine machine(
        [](const canon::ProbeSurface& surface, const Vec3& tip) { return surface.touches(tip); });
    ASSERT_EQ(run(program, &machine), interp::RunStatus::Failed);
    EXPECT_EQ(machine.probeMoves, 2);
    const std::string latched = firstError();
    EXPECT_NE(latched.find("PRB-001"), std::string::npos) << latched;
    ASSERT_EQ(run(program, nullptr), interp::RunStatus::Failed);
    EXPECT_EQ(firstError(), latched);
}

TEST_F(ProbingLatchTest, AxesStoppingBeyondTheStylusOvertravelStopTheProgram) {
    // The stand-in machine brakes 6 mm beyond the first touch of 400: more than the stylus's
    // 5 mm. Within them (4.9 mm) the cycle goes on.
    const std::string program =
        "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
        "3 TOOL CALL 1 Z\n4 L X-20 Y-20 Z+50 R0 FMAX\n"
        "5 TCH PROBE 400 BASIC ROTATION\n  Q263=+10\n  Q264=+0\n  Q265=+80\n  Q266=+0\n"
        "  Q272=+2\n  Q267=+1\n  Q261=-5\n  Q320=0\n  Q260=+20\n  Q301=1\n  Q307=0\n"
        "  Q305=0\n";
    auto onThePart = [](const canon::ProbeSurface& surface, const Vec3& tip) {
        return surface.touches(tip);
    };
    LatchingMachine far(onThePart, 6.0);
    ASSERT_EQ(run(program, &far), interp::RunStatus::Failed);
    EXPECT_EQ(far.probeMoves, 1);
    EXPECT_NE(firstError().find("PRB-025"), std::string::npos) << firstError();
    EXPECT_NE(firstError().find("6.000 mm beyond"), std::string::npos) << firstError();
    LatchingMachine near(onThePart, 4.9);
    EXPECT_EQ(run(program, &near), interp::RunStatus::Finished) << firstError();
    // The front face's 0.7 degrees became row 0's basic rotation.
    std::stringstream presets;
    presets << std::ifstream(dir / "PRESET.PR").rdbuf();
    EXPECT_NE(presets.str().find("+0.7  "), std::string::npos) << presets.str();
}

// Cycle 1416 on the front-left corner (edge 1 the front face probed along +Y, edge 2 the left
// face along +X) with the nominal positions written as given.
std::string semiAutomatic(const std::string& q1100, const std::string& q1101,
                          const std::string& q1102) {
    return "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
           "3 TOOL CALL 1 Z\n4 L X-20 Y-20 Z+50 R0 FMAX\n"
           "5 TCH PROBE 1416 PROBING INTERSECTION ~\n  Q1100=" +
           q1100 + " ~\n  Q1101=" + q1101 + " ~\n  Q1102=" + q1102 +
           " ~\n  QS400=\"\" ~\n  Q1130=+0 ~\n  Q1131=+1 ~\n  Q1132=+10 ~\n  Q1133=+40 ~\n"
           "  QS401=\"\" ~\n  Q1134=+90 ~\n  Q1135=-1 ~\n  Q1136=+10 ~\n  Q1137=+40 ~\n"
           "  Q1139=+3 ~\n  Q320=+0 ~\n  Q260=+100 ~\n  Q1125=+2 ~\n  Q309=+0 ~\n  Q1126=+0 ~\n"
           "  Q1120=+0 ~\n  Q1121=+0\n";
}

TEST_F(ProbingLatchTest, SemiAutomatic1416ProbesFromWhereTheOperatorPutTheProbe) {
    // Every nominal position unknown: the program stops before each of the four touches, and
    // the operator jogs the tool tip (ball centre 2 higher) in front of the faces.
    LatchingMachine machine(
        [](const canon::ProbeSurface& surface, const Vec3& tip) { return surface.touches(tip); });
    machine.places = {
        {20.0, -10.0, -7.0}, {60.0, -10.0, -7.0}, {-10.0, 15.0, -7.0}, {-10.0, 45.0, -7.0}};
    ASSERT_EQ(run(semiAutomatic("?", "?", "?"), &machine), interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(machine.placed, 4u);
    EXPECT_EQ(machine.stops, 4);
    EXPECT_EQ(machine.probeMoves, 4);
    ASSERT_EQ(machine.messages.size(), 4u);
    EXPECT_EQ(machine.messages[2],
              "cycle 1416 (semi-automatic mode): position the probe before touch point 1 of "
              "edge 2, within 20.000 mm of the edge, probing at 0.000 degrees in the plane; "
              "then NC start");
    // By hand: the blank's corner is at (1.5, -0.8), its faces turned by a = 0.7 degrees. A
    // ball of radius 2 at x probing +Y touches the front face (inward normal (-sin a, cos a))
    // with its centre at y = (-2 + sin a (x - 1.5)) / cos a - 0.8; the surface point is 2
    // further. Likewise the left face (normal (cos a, sin a)) probed along +X at y.
    const double a = 0.7 * std::numbers::pi / 180.0;
    auto front = [&](double x) {
        return (-2.0 + std::sin(a) * (x - 1.5)) / std::cos(a) - 0.8 + 2.0;
    };
    auto left = [&](double y) {
        return (-2.0 - std::sin(a) * (y + 0.8)) / std::cos(a) + 1.5 + 2.0;
    };
    EXPECT_NEAR(q(950), 20.0, 1e-9);
    EXPECT_NEAR(q(951), front(20.0), 0.002);
    EXPECT_NEAR(q(952), -5.0, 1e-9);
    EXPECT_NEAR(q(953), 60.0, 1e-9);
    EXPECT_NEAR(q(954), front(60.0), 0.002);
    EXPECT_NEAR(q(956), left(15.0), 0.002);
    EXPECT_NEAR(q(957), 15.0, 1e-9);
    // The two lines y = front(20) + t (x - 20) and x = left(15) - t (y - 15), t = tan a.
    const double t = std::tan(a);
    const double x = (left(15.0) - t * (front(20.0) - 15.0) + 20.0 * t * t) / (1.0 + t * t);
    const double y = front(20.0) + t * (x - 20.0);
    EXPECT_NEAR(q(959), x, 0.002);
    EXPECT_NEAR(q(960), y, 0.002);
    EXPECT_NEAR(q(994), 0.7, 0.002);
    // Nominal = actual: no deviation anywhere, the part is good.
    for (uint16_t d = 980; d <= 990; ++d)
        EXPECT_NEAR(q(d), 0.0, 1e-9) << d;
    EXPECT_EQ(q(183), 0.0);

    // Q1101 known (0): only the intersection's Y is compared with it.
    LatchingMachine again(
        [](const canon::ProbeSurface& surface, const Vec3& tip) { return surface.touches(tip); });
    again.places = machine.places;
    ASSERT_EQ(run(semiAutomatic("?", "+0", "-5"), &again), interp::RunStatus::Finished)
        << firstError();
    EXPECT_EQ(again.stops, 4);
    EXPECT_NEAR(q(959), x, 0.002);
    EXPECT_NEAR(q(989), 0.0, 1e-9);
    EXPECT_NEAR(q(990), y, 0.002);
}

TEST_F(ProbingLatchTest, SemiAutomatic1416WithoutAnOperatorProbesFromWhereTheProgramLeftIt) {
    // Plain run: nobody moves the probe, so each touch starts where block 4 left it, in front of
    // the front face: touches 1 and 2 find it, touch 3 probes along +X in front of the part and
    // finds nothing within DIST.
    std::string program = semiAutomatic("?", "+0", "-5");
    program.replace(program.find("4 L X-20 Y-20 Z+50"), 18, "4 L X+20 Y-10 Z-7");
    ASSERT_EQ(run(program, nullptr), interp::RunStatus::Failed);
    const std::string plain = firstError();
    EXPECT_NE(plain.find("PRB-001"), std::string::npos) << plain;
    // A machine nobody jogs at the stops gives the same, after the third stop.
    LatchingMachine machine(
        [](const canon::ProbeSurface& surface, const Vec3& tip) { return surface.touches(tip); });
    machine.places.assign(3, Vec3(20.0, -10.0, -7.0));
    ASSERT_EQ(run(program, &machine), interp::RunStatus::Failed);
    EXPECT_EQ(firstError(), plain);
    EXPECT_EQ(machine.stops, 3);
    EXPECT_EQ(machine.probeMoves, 3);
}

}  // namespace
}  // namespace kerf::klartext
