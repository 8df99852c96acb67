#include "core/machine/table_kinematics.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"

namespace kerf::machine {
namespace {

constexpr double kEps = 1e-9;
const double kHalfRoot2 = std::sqrt(0.5);

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

TEST(TableKinematics, BuiltinMachinesDescribeTheirTables) {
    EXPECT_FALSE(TableKinematics::of(load("mill")).has_value());
    const MachineConfig mill5 = load("mill5");
    EXPECT_EQ(mill5.kinematics.type, KinematicsType::TableTable);
    EXPECT_EQ(mill5.enabledAxisLetters(), "XYZBC");
    EXPECT_EQ(mill5.axis('B')->minLimit, -110.0);
    EXPECT_EQ(mill5.axis('B')->maxLimit, 110.0);
    EXPECT_TRUE(mill5.axis('C')->endless);
    EXPECT_EQ(mill5.kinematics.pivotZMm, -400.0);
    const MachineConfig mill4 = load("mill4");
    EXPECT_EQ(mill4.kinematics.type, KinematicsType::Table);
    EXPECT_EQ(mill4.enabledAxisLetters(), "XYZA");
    EXPECT_EQ(mill4.kinematics.primary, 'A');
}

// The table that carries the workpiece and its axis in the machine (the cylinder-surface cycles
// need it perpendicular to the tool): mill4's A lies along X; mill5's C stands along Z at B 0
// and is laid along Rot_Y(-b) Z = (-sin b, 0, cos b): -X at B+90, +X at B-90. Both run through
// the pivot (0, 0, -400).
TEST(TableKinematics, InnerTableAxisFollowsTheTilt) {
    const TableKinematics mill4 = kinematicsOf("mill4");
    EXPECT_EQ(mill4.innerTable(), 'A');
    expectVec(mill4.innerTableAxis({30.0, 0.0}), Vec3::UnitX());
    const TableKinematics mill5 = kinematicsOf("mill5");
    EXPECT_EQ(mill5.innerTable(), 'C');
    expectVec(mill5.innerTableAxis({0.0, 40.0}), Vec3::UnitZ());
    expectVec(mill5.innerTableAxis({90.0, 40.0}), -Vec3::UnitX());
    expectVec(mill5.innerTableAxis({-90.0, 0.0}), Vec3::UnitX());
    expectVec(mill5.innerTableAxis({45.0, 0.0}), Vec3(-kHalfRoot2, 0.0, kHalfRoot2));
    expectVec(mill5.pivot(), Vec3(0.0, 0.0, -400.0));
}

TEST(TableKinematics, PrincipalRotationsAreRightHanded) {
    expectVec(principalRotation('A', 90.0) * Vec3::UnitY(), Vec3::UnitZ());
    expectVec(principalRotation('B', 90.0) * Vec3::UnitZ(), Vec3::UnitX());
    expectVec(principalRotation('C', 90.0) * Vec3::UnitX(), Vec3::UnitY());
}

TEST(TableKinematics, ToolDirectionInTheWorkpiece) {
    const TableKinematics k = kinematicsOf("mill5");
    // B+45: the tool leans towards workpiece +X.
    expectVec(k.toolDirection({45.0, 0.0}), Vec3(kHalfRoot2, 0.0, kHalfRoot2));
    // B+90 C+90: towards X first, then turned about Z onto +Y.
    expectVec(k.toolDirection({90.0, 90.0}), Vec3::UnitY());
    // mill4's A+90 turns the tool from +Z towards -Y.
    expectVec(kinematicsOf("mill4").toolDirection({90.0, 0.0}), -Vec3::UnitY());
}

TEST(TableKinematics, TablesTurnTheWorkpieceTheOtherWay) {
    const TableKinematics k = kinematicsOf("mill5");
    // B+90: the workpiece's +X side faces up (the tool looks at it from above).
    expectVec(k.workpieceToMachine({90.0, 0.0}) * Vec3::UnitX(), Vec3::UnitZ());
    // C+90 alone: workpiece +X turns to machine -Y.
    expectVec(k.workpieceToMachine({0.0, 90.0}) * Vec3::UnitX(), -Vec3::UnitY());
}

TEST(TableKinematics, AxesOfAPointAboutThePivot) {
    const TableKinematics k = kinematicsOf("mill5");  // pivot at machine (0, 0, -400)
    // Preset at the pivot: the point only turns.
    expectVec(k.axesOf(Vec3(10.0, 0.0, 0.0), {90.0, 0.0}, Vec3(0.0, 0.0, -400.0), 0.0),
              Vec3(0.0, 0.0, 10.0));
    // Preset 50 mm above the pivot: B+90 carries it to 50 mm beside the pivot at pivot height,
    // (-50, 0, -50) from where it was; the point 10 mm along X is 10 mm above that.
    expectVec(k.axesOf(Vec3(10.0, 0.0, 0.0), {90.0, 0.0}, Vec3(0.0, 0.0, -350.0), 0.0),
              Vec3(-50.0, 0.0, -40.0));
    // At B 0 C 0 nothing moves.
    expectVec(k.axesOf(Vec3(1.0, 2.0, 3.0), {0.0, 0.0}, Vec3(5.0, 6.0, 7.0), 0.0),
              Vec3(1.0, 2.0, 3.0));
}

TEST(TableKinematics, InverseGivesBothSolutions) {
    const TableKinematics k = kinematicsOf("mill5");
    const RotarySolutions s = k.solve(Vec3::UnitY(), 0.0);
    ASSERT_EQ(s.count, 2);
    // B+90 C+90 (tilt towards X, turn X onto Y) and B-90 C-90 (tilt towards -X, turn -X onto Y).
    EXPECT_NEAR(s.list[0].primaryDeg, 90.0, kEps);
    EXPECT_NEAR(s.list[0].secondaryDeg, 90.0, kEps);
    EXPECT_NEAR(s.list[1].primaryDeg, -90.0, kEps);
    EXPECT_NEAR(s.list[1].secondaryDeg, -90.0, kEps);
    for (const RotaryAngles& a : s.list)
        expectVec(k.toolDirection(a), Vec3::UnitY());
}

TEST(TableKinematics, InverseOfTheToolAxisLeavesTheSecondaryFree) {
    const TableKinematics k = kinematicsOf("mill5");
    const RotarySolutions s = k.solve(Vec3::UnitZ(), 30.0);
    ASSERT_EQ(s.count, 1);
    EXPECT_NEAR(s.list[0].primaryDeg, 0.0, kEps);
    EXPECT_NEAR(s.list[0].secondaryDeg, 30.0, kEps);
    // TABLE ROT: a plane turned 30 deg about Z is aligned by C+30 (C turns the part back by 30).
    EXPECT_NEAR(k.alignedSecondaryDeg(Vec3(std::cos(M_PI / 6), std::sin(M_PI / 6), 0.0), 0.0), 30.0,
                kEps);
}

TEST(TableKinematics, ChoiceBySequenceAndShortestPath) {
    const TableKinematics k = kinematicsOf("mill5");
    const RotarySolutions s = k.solve(Vec3::UnitY(), 0.0);
    auto positive = k.choose(s, SolutionChoice::PrimaryPositive, {});
    auto negative = k.choose(s, SolutionChoice::PrimaryNegative, {});
    ASSERT_TRUE(positive && negative);
    EXPECT_EQ(*positive, (RotaryAngles{90.0, 90.0}));
    EXPECT_EQ(*negative, (RotaryAngles{-90.0, -90.0}));
    // Shortest from B-80 C-80: the negative solution (20 deg in all, against 340).
    auto nearest = k.choose(s, SolutionChoice::Shortest, {-80.0, -80.0});
    ASSERT_TRUE(nearest);
    EXPECT_EQ(*nearest, (RotaryAngles{-90.0, -90.0}));
    // The endless C stays on its turn: from C+700 the angle -90 is reached at 630.
    auto turned = k.choose(s, SolutionChoice::PrimaryNegative, {0.0, 700.0});
    ASSERT_TRUE(turned);
    EXPECT_NEAR(turned->secondaryDeg, 630.0, kEps);
}

TEST(TableKinematics, SolutionsBeyondTheLimitsAreRefused) {
    const TableKinematics k = kinematicsOf("mill5");
    // Tool 120 deg from Z towards X: B+120 C0 or B-120 C180, both beyond B's +-110.
    const Vec3 steep(std::sin(2 * M_PI / 3), 0.0, std::cos(2 * M_PI / 3));
    const RotarySolutions s = k.solve(steep, 0.0);
    ASSERT_EQ(s.count, 2);
    EXPECT_FALSE(k.choose(s, SolutionChoice::Shortest, {}).has_value());
}

TEST(TableKinematics, OneTableReachesOnlyItsPlane) {
    const TableKinematics k = kinematicsOf("mill4");
    const RotarySolutions s = k.solve(Vec3(0.0, -kHalfRoot2, kHalfRoot2), 0.0);
    ASSERT_EQ(s.count, 1);
    EXPECT_NEAR(s.list[0].primaryDeg, 45.0, kEps);
    EXPECT_EQ(k.solve(Vec3::UnitX(), 0.0).count, 0);
}

TEST(TableKinematics, ValidationNamesTheKey) {
    DiagnosticList problems;
    auto config =
        parseMachine("base = \"mill\"\n[kinematics]\ntype = \"table-table\"\nprimary = \"B\"\n",
                     "k.toml", &problems);
    EXPECT_FALSE(config.ok());
    ASSERT_FALSE(problems.empty());
    EXPECT_NE(problems.front().message().find("kinematics.primary = \"B\" is not an enabled "
                                              "rotary axis"),
              std::string::npos)
        << problems.front().format();
}

}  // namespace
}  // namespace kerf::machine
