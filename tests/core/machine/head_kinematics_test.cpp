// Swivel heads: the built-in machines mill5h (B head, C table: head-table) and mill5hh (C/B fork
// head: head-head). Every value is worked out by hand in the comments; the head pivot lies
// 200 mm above the spindle nose on both.
#include <cmath>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "core/machine/table_kinematics.h"
#include "core/machine/workpiece_frame.h"

namespace kerf::machine {
namespace {

constexpr double kEps = 1e-9;

MachineConfig load(std::string_view nameOrText) {
    DiagnosticList problems;
    Expected<MachineConfig> config = loadMachine(nameOrText, &problems);
    EXPECT_TRUE(config.ok() && problems.empty());
    return config.ok() ? *config : MachineConfig{};
}

TableKinematics kinematicsOf(std::string_view name) {
    auto k = TableKinematics::of(load(name));
    EXPECT_TRUE(k.has_value()) << name;
    return k.value_or(TableKinematics{});
}

void expectVec(const Vec3& actual, const Vec3& expected) {
    EXPECT_NEAR(actual.x(), expected.x(), kEps);
    EXPECT_NEAR(actual.y(), expected.y(), kEps);
    EXPECT_NEAR(actual.z(), expected.z(), kEps);
}

const Vec3 kPivotPreset(0.0, 0.0, -400.0);  // the workpiece origin of mill on the C axis

TEST(HeadKinematics, BuiltinMachinesDescribeTheirHeads) {
    const MachineConfig head = load("mill5h");
    EXPECT_EQ(head.kinematics.type, KinematicsType::HeadTable);
    EXPECT_EQ(head.enabledAxisLetters(), "XYZBC");
    EXPECT_EQ(head.kinematics.headPivotZMm, 200.0);
    const MachineConfig fork = load("mill5hh");
    EXPECT_EQ(fork.kinematics.type, KinematicsType::HeadHead);
    EXPECT_EQ(fork.kinematics.primary, 'B');
    EXPECT_EQ(fork.kinematics.secondary, 'C');
    const TableKinematics h = kinematicsOf("mill5h");
    EXPECT_TRUE(h.hasHead());
    EXPECT_TRUE(h.hasTable());
    EXPECT_EQ(h.innerTable(), 'C');
    expectVec(h.innerTableAxis({90.0, 30.0}), Vec3::UnitZ());  // the table does not tilt
    const TableKinematics f = kinematicsOf("mill5hh");
    EXPECT_TRUE(f.hasHead());
    EXPECT_FALSE(f.hasTable());
}

// B head at +90: the tool, turned about Y, points (sin 90, 0, cos 90) = +X from the tip. With the
// linear axes kept, the tip would swing about the pivot (200 + L above the tip) to
// pivot - Ry(90)(0, 0, 200 + L): the axes make up for it by (200 + L)(+1, 0, -1): the pivot
// moves by the pivot length plus the tool length along +X and down to the tip's height.
TEST(HeadKinematics, TiltedHeadKeepsTheTipWhereTheAxesMakeUpForThePivot) {
    const TableKinematics h = kinematicsOf("mill5h");
    expectVec(h.toolDirection({90.0, 0.0}), Vec3::UnitX());
    expectVec(h.axesOf(Vec3::Zero(), {90.0, 0.0}, kPivotPreset, 0.0), Vec3(200.0, 0.0, -200.0));
    expectVec(h.axesOf(Vec3::Zero(), {90.0, 0.0}, kPivotPreset, 50.0), Vec3(250.0, 0.0, -250.0));
    // B -30: tool (-sin 30, 0, cos 30); the offset (H - I)(0, 0, 250) = (-125, 0, 250 cos 30 -
    // 250).
    expectVec(h.axesOf(Vec3(10.0, 20.0, 5.0), {-30.0, 0.0}, kPivotPreset, 50.0),
              Vec3(10.0 - 125.0, 20.0, 5.0 + 250.0 * std::cos(M_PI / 6.0) - 250.0));
    // At 0 the head adds nothing: the axes are the workpiece coordinates.
    expectVec(h.axesOf(Vec3(1.0, 2.0, 3.0), {0.0, 0.0}, kPivotPreset, 50.0), Vec3(1.0, 2.0, 3.0));
}

// C table at +90 turns the part by -90 about its axis (through the pivot): the part's point
// (10, 0, 0) comes to machine (0, -10, 0); on the part the tool (+X in the machine) points along
// Rz(90) X = +Y. The head's offset adds (200, 0, -200) as above.
TEST(HeadKinematics, TableTurnsThePartUnderTheTurnedHead) {
    const TableKinematics h = kinematicsOf("mill5h");
    expectVec(h.toolDirection({90.0, 90.0}), Vec3::UnitY());
    expectVec(h.axesOf(Vec3(10.0, 0.0, 0.0), {90.0, 90.0}, kPivotPreset, 0.0),
              Vec3(200.0, -10.0, -200.0));
    // A preset 30 mm beside the C axis turns with the table: (W - I)(30, 0, 0) = (-30, -30, 0).
    expectVec(h.axesOf(Vec3::Zero(), {0.0, 90.0}, Vec3(30.0, 0.0, -400.0), 0.0),
              Vec3(-30.0, -30.0, 0.0));
    const Vec3 axes = h.axesOf(Vec3(3.0, -4.0, 7.0), {37.0, -121.0}, kPivotPreset, 42.0);
    expectVec(h.tipOf(axes, {37.0, -121.0}, kPivotPreset, 42.0), Vec3(3.0, -4.0, 7.0));
}

// Fork head: C carries B, so the tool points along Rz(c) Ry(b) Z: B+90 C+90 gives Rz(90) X = +Y,
// and the pivot offset (H - I)(0, 0, 200) = (0, 200, -200). The part stands still.
TEST(HeadKinematics, ForkHeadTurnsTheToolAboutBothAxes) {
    const TableKinematics f = kinematicsOf("mill5hh");
    expectVec(f.toolDirection({90.0, 90.0}), Vec3::UnitY());
    expectVec(f.axesOf(Vec3(1.0, 2.0, 3.0), {90.0, 90.0}, kPivotPreset, 0.0),
              Vec3(1.0, 202.0, -197.0));
    EXPECT_TRUE(f.workpieceToMachine({40.0, 70.0}).isIdentity(kEps));
    // The same direction as a table-table machine gives for the same angles.
    expectVec(f.toolDirection({40.0, 70.0}), kinematicsOf("mill5").toolDirection({40.0, 70.0}));
}

// The solutions are those of the tables: tool along (sin 45, 0, cos 45) -> B+45 C0 or B-45 C180;
// along +Y -> B+90 C+90 or B-90 C-90. SEQ- picks the negative B.
TEST(HeadKinematics, SolutionsAndSeqChooseTheTiltingAxis) {
    for (std::string_view name : {"mill5h", "mill5hh"}) {
        const TableKinematics k = kinematicsOf(name);
        const RotarySolutions s = k.solve(Vec3(std::sqrt(0.5), 0.0, std::sqrt(0.5)), 0.0);
        ASSERT_EQ(s.count, 2) << name;
        auto plus = k.choose(s, SolutionChoice::PrimaryPositive, {});
        ASSERT_TRUE(plus.has_value());
        EXPECT_NEAR(plus->primaryDeg, 45.0, kEps);
        EXPECT_NEAR(plus->secondaryDeg, 0.0, kEps);
        auto minus = k.choose(k.solve(Vec3::UnitY(), 0.0), SolutionChoice::PrimaryNegative, {});
        ASSERT_TRUE(minus.has_value());
        EXPECT_NEAR(minus->primaryDeg, -90.0, kEps);
        EXPECT_NEAR(minus->secondaryDeg, -90.0, kEps);
        expectVec(k.toolDirection(*minus), Vec3::UnitY());
    }
}

// The graphics map the stream back onto the part with the tool in the spindle: a stream point of
// the B+90 head (200 + 50 beside and below) is the part's origin with the tool along +X.
TEST(HeadKinematics, WorkpieceFrameUsesTheToolLength) {
    Pose preset{};
    preset.setXyz(kPivotPreset);
    auto frame = WorkpieceFrame::of(load("mill5h"), preset);
    ASSERT_TRUE(frame.has_value());
    frame->setToolLength(50.0);
    Pose stream{};
    stream.setXyz(Vec3(250.0, 0.0, -250.0));
    stream[Axis::B] = 90.0;
    const ToolOnPart on = frame->toPart(stream);
    expectVec(on.tip, Vec3::Zero());
    expectVec(on.axis, Vec3::UnitX());
}

TEST(HeadKinematics, ValidationWantsATiltingPrimaryAxis) {
    DiagnosticList problems;
    auto config =
        parseMachine("base = \"mill5hh\"\n[kinematics]\nprimary = \"C\"\nsecondary = \"B\"\n",
                     "k.toml", &problems);
    EXPECT_FALSE(config.ok());
    ASSERT_FALSE(problems.empty());
    EXPECT_NE(problems.front().message().find("kinematics.primary is the tilting axis: A or B"),
              std::string::npos)
        << problems.front().format();
}

}  // namespace
}  // namespace kerf::machine
