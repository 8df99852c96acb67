#include "ui/status/position_display.h"

#include <QLabel>
#include <QSignalSpy>
#include <QSlider>
#include <cmath>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "ui/status/override_controls.h"

namespace kerf::ui {
namespace {

task::AxisStatus axisAt(double nominal, double actual, double offset, double dist) {
    task::AxisStatus a;
    a.enabled = true;
    a.nominal = nominal;
    a.actual = actual;
    a.machineNominal = nominal + offset;
    a.machineActual = actual + offset;
    a.followingError = nominal - actual;
    a.distanceToGo = dist;
    return a;
}

TEST(PositionDisplay, EachKindShowsItsValue) {
    const task::AxisStatus a = axisAt(10.0, 9.99, 100.0, 4.0);
    EXPECT_DOUBLE_EQ(PositionDisplay::shownValue(a, PositionKind::Actual, false, false, false),
                     9.99);
    EXPECT_DOUBLE_EQ(PositionDisplay::shownValue(a, PositionKind::Nominal, false, false, false),
                     10.0);
    EXPECT_DOUBLE_EQ(
        PositionDisplay::shownValue(a, PositionKind::ReferenceActual, false, false, false), 109.99);
    EXPECT_DOUBLE_EQ(
        PositionDisplay::shownValue(a, PositionKind::ReferenceNominal, false, false, false), 110.0);
    EXPECT_NEAR(PositionDisplay::shownValue(a, PositionKind::Lag, false, false, false), 0.01,
                1e-12);
    EXPECT_DOUBLE_EQ(
        PositionDisplay::shownValue(a, PositionKind::DistanceToGo, false, false, false), 4.0);
}

TEST(PositionDisplay, LatheDiameterAndInch) {
    const task::AxisStatus a = axisAt(12.7, 12.7, 0.0, 0.0);
    // Radius 12.7 mm = diameter 25.4 mm = 1 inch.
    EXPECT_DOUBLE_EQ(PositionDisplay::shownValue(a, PositionKind::Nominal, true, false, false),
                     25.4);
    EXPECT_DOUBLE_EQ(PositionDisplay::shownValue(a, PositionKind::Nominal, true, true, false), 1.0);
    // Rotary axes stay in degrees.
    EXPECT_DOUBLE_EQ(PositionDisplay::shownValue(a, PositionKind::Nominal, false, true, true),
                     12.7);
}

TEST(PositionDisplay, ShowsTheLatheXAsDiameterAndFollowsTheSettings) {
    test::testApp();
    auto lathe = machine::loadMachine("lathe");
    ASSERT_TRUE(lathe.ok());
    PositionDisplay display(*lathe);
    task::MachineStatus status;
    status.axes[0] = axisAt(20.0, 19.5, 0.0, 0.0);  // X radius 20
    status.axes[2] = axisAt(-5.0, -5.0, 0.0, 0.0);
    status.toolNumber = 7;
    display.setStatus(status);
    EXPECT_EQ(display.axisText(Axis::X), "+39.000");  // actual radius 19.5 as a diameter
    EXPECT_EQ(display.axisText(Axis::Z), "-5.000");
    EXPECT_TRUE(display.axisText(Axis::Y).isEmpty());
    DisplaySettings settings;
    settings.positionKind = PositionKind::Nominal;
    settings.inch = true;
    display.setDisplaySettings(settings);
    EXPECT_EQ(display.axisText(Axis::X), "+1.5748");  // 40 mm / 25.4
    EXPECT_EQ(display.toolText(), "T 7");
}

TEST(PositionDisplay, TheBasicRotationTurnsXAndYExceptInRef) {
    // A basic rotation of 90 degrees: the turned X axis is the machine's Y, the turned Y the
    // machine's -X. The tip at (10, 20) from the preset shows X +20, Y -10; REF keeps the
    // machine's axes (preset at 100 in both).
    test::testApp();
    auto mill = machine::loadMachine("mill");
    ASSERT_TRUE(mill.ok());
    PositionDisplay display(*mill);
    task::MachineStatus status;
    status.axes[0] = axisAt(10.0, 10.0, 100.0, 3.0);
    status.axes[1] = axisAt(20.0, 20.0, 100.0, 4.0);
    status.axes[2] = axisAt(-5.0, -5.0, 0.0, 0.0);
    display.setStatus(status);
    display.setBasicRotation(90.0);
    EXPECT_EQ(display.axisText(Axis::X), "+20.000");
    EXPECT_EQ(display.axisText(Axis::Y), "-10.000");
    EXPECT_EQ(display.axisText(Axis::Z), "-5.000");
    EXPECT_TRUE(display.kindLabel().endsWith("  ROT")) << display.kindLabel().toStdString();
    DisplaySettings settings;
    settings.positionKind = PositionKind::DistanceToGo;  // (3, 4) turns to (4, -3)
    display.setDisplaySettings(settings);
    EXPECT_EQ(display.axisText(Axis::X), "+4.000");
    EXPECT_EQ(display.axisText(Axis::Y), "-3.000");
    settings.positionKind = PositionKind::ReferenceActual;
    display.setDisplaySettings(settings);
    EXPECT_EQ(display.axisText(Axis::X), "+110.000");
    EXPECT_EQ(display.axisText(Axis::Y), "+120.000");
    EXPECT_FALSE(display.kindLabel().contains("ROT"));
    // Without a basic rotation nothing turns.
    settings.positionKind = PositionKind::Actual;
    display.setDisplaySettings(settings);
    display.setBasicRotation(0.0);
    EXPECT_EQ(display.axisText(Axis::X), "+10.000");
    EXPECT_FALSE(display.kindLabel().contains("ROT"));
}

TEST(PositionDisplay, AValueThatRoundsToZeroHasNoMinusSign) {
    test::testApp();
    auto mill = machine::loadMachine("mill");
    ASSERT_TRUE(mill.ok());
    PositionDisplay display(*mill);
    task::MachineStatus status;
    status.axes[0] = axisAt(-0.0004, -0.0004, 0.0, 0.0);  // rounds to 0.000
    status.axes[1] = axisAt(-0.0006, -0.0006, 0.0, 0.0);  // rounds to -0.001
    status.axes[2] = axisAt(-1e-12, -1e-12, 0.0, 0.0);
    display.setStatus(status);
    EXPECT_EQ(display.axisText(Axis::X), "+0.000");
    EXPECT_EQ(display.axisText(Axis::Y), "-0.001");
    EXPECT_EQ(display.axisText(Axis::Z), "+0.000");
}

TEST(PositionDisplay, MarksEachAxisNotReferencedUntilItIsHomed) {
    test::testApp();
    auto mill = machine::loadMachine("mill");
    ASSERT_TRUE(mill.ok());
    PositionDisplay display(*mill);
    task::MachineStatus status;
    for (size_t i = 0; i < 3; ++i)
        status.axes[i] = axisAt(0.0, 0.0, 0.0, 0.0);
    display.setStatus(status);
    for (Axis a : {Axis::X, Axis::Y, Axis::Z})
        EXPECT_TRUE(display.notReferencedShown(a));
    // Z homed first (the mill's reference order): only X and Y keep the mark.
    status.axes[2].homed = true;
    display.setStatus(status);
    EXPECT_TRUE(display.notReferencedShown(Axis::X));
    EXPECT_TRUE(display.notReferencedShown(Axis::Y));
    EXPECT_FALSE(display.notReferencedShown(Axis::Z));
}

// The block being executed is named as the program numbers it: Klartext block 5 (on line 7
// after a CYCL DEF's parameter lines), FAGOR N30, a FAGOR block without N by its line.
TEST(PositionDisplay, NamesTheExecutingBlockByItsNumber) {
    test::testApp();
    auto state = [](const PositionDisplay& display) {
        return display.findChild<QLabel*>(QStringLiteral("runState"))->text();
    };
    PositionDisplay mill(*machine::loadMachine("mill"));
    task::MachineStatus status;
    status.block.line = 7;
    status.block.blockNumber = 5;
    mill.setStatus(status);
    EXPECT_TRUE(state(mill).endsWith(QStringLiteral("Block 5"))) << state(mill).toStdString();
    PositionDisplay lathe(*machine::loadMachine("lathe"));
    status.block.blockNumber = 30;
    lathe.setStatus(status);
    EXPECT_TRUE(state(lathe).endsWith(QStringLiteral("N30"))) << state(lathe).toStdString();
    status.block.blockNumber = -1;
    lathe.setStatus(status);
    EXPECT_TRUE(state(lathe).endsWith(QStringLiteral("Line 7"))) << state(lathe).toStdString();
}

// A plane tilted by SPB+30 on the B swivel head of mill5h (head pivot 200 mm above the nose):
// the machine's axes a hold R p + h with R = Ry(30) and the head's offset h = 200 (R z - z), so
// the tilted plane's coordinates are p = R^T a - 200 (sin30, 0, 1 - cos30). NOML and ACTL show
// p, LAG and DIST the differences turned by R^T, REF the machine's axes; B stays in degrees.
TEST(PositionDisplay, ShowsTheTiltedPlanesCoordinatesExceptInRef) {
    test::testApp();
    auto mill5h = machine::loadMachine("mill5h");
    ASSERT_TRUE(mill5h.ok());
    PositionDisplay display(*mill5h);
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    PositionDisplay::WorkingPlane plane;
    plane.axesToProgram = {c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c};
    plane.programAtAxesZeroMm = {-200.0 * s, 0.0, -200.0 * (1.0 - c)};
    // The tip at p = (10, 5, 2): a = R p + h = (10c + 2s + 200s, 5, -10s + 2c + 200(c - 1)).
    const double ax = 10.0 * c + 2.0 * s + 200.0 * s;
    const double az = -10.0 * s + 2.0 * c + 200.0 * (c - 1.0);
    // Actual 0.01 behind along the plane's X: a - R (0.01, 0, 0) = a - (0.01c, 0, -0.01s).
    // The move ends 4 mm further along the plane's Y.
    task::MachineStatus status;
    status.axes[0] = axisAt(ax, ax - 0.01 * c, -1000.0, 0.0);
    status.axes[1] = axisAt(5.0, 5.0, -200.0, 4.0);
    status.axes[2] = axisAt(az, az + 0.01 * s, -400.0, 0.0);
    status.axes[4] = axisAt(30.0, 30.0, 0.0, 0.0);
    display.setStatus(status);
    DisplaySettings settings;
    settings.positionKind = PositionKind::Nominal;
    display.setDisplaySettings(settings);
    EXPECT_EQ(display.axisText(Axis::X), "+109.660");  // untilted: the axes themselves
    display.setWorkingPlane(plane);
    EXPECT_EQ(display.axisText(Axis::X), "+10.000");
    EXPECT_EQ(display.axisText(Axis::Y), "+5.000");
    EXPECT_EQ(display.axisText(Axis::Z), "+2.000");
    EXPECT_EQ(display.axisText(Axis::B), "+30.000");
    EXPECT_TRUE(display.kindLabel().endsWith(QStringLiteral("3D ROT")));
    settings.positionKind = PositionKind::Actual;
    display.setDisplaySettings(settings);
    EXPECT_EQ(display.axisText(Axis::X), "+9.990");
    EXPECT_EQ(display.axisText(Axis::Z), "+2.000");
    settings.positionKind = PositionKind::Lag;
    display.setDisplaySettings(settings);
    EXPECT_EQ(display.axisText(Axis::X), "+0.010");
    EXPECT_EQ(display.axisText(Axis::Z), "+0.000");
    settings.positionKind = PositionKind::DistanceToGo;
    display.setDisplaySettings(settings);
    EXPECT_EQ(display.axisText(Axis::Y), "+4.000");
    settings.positionKind = PositionKind::ReferenceNominal;
    display.setDisplaySettings(settings);
    EXPECT_EQ(display.axisText(Axis::X), "-890.340");  // 109.660 - 1000
    EXPECT_EQ(display.axisText(Axis::Z), "-430.063");  // -30.062868 - 400
    EXPECT_FALSE(display.kindLabel().contains(QStringLiteral("3D ROT")));
    display.setWorkingPlane(std::nullopt);
    settings.positionKind = PositionKind::Nominal;
    display.setDisplaySettings(settings);
    EXPECT_EQ(display.axisText(Axis::X), "+109.660");
    EXPECT_FALSE(display.kindLabel().contains(QStringLiteral("3D ROT")));
}

// Under TCPM in a plane tilted by SPB+30 on mill5 (B/C tables, the preset at the pivot) the tables
// stand at B+60 C+90 while the tip is at the plane's (10, 5, 2): the axes hold
// Ry(-60) Rz(-90) Ry(30) (10, 5, 2) = (5.330127, -9.660254, 2.696152)
// (tests/core/task/working_plane_position_test.cpp). NOML shows the tip in the plane.
TEST(PositionDisplay, ShowsTheTipInTheTiltedPlaneWhileTcpmTurnsTheTables) {
    test::testApp();
    auto mill5 = machine::loadMachine("mill5");
    ASSERT_TRUE(mill5.ok());
    PositionDisplay display(*mill5);
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    PositionDisplay::WorkingPlane plane;
    plane.axesToProgram = {c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c};
    plane.tipFollowsTables = true;
    plane.presetInMachineMm = {0.0, 0.0, -400.0};
    task::MachineStatus status;
    status.axes[0] = axisAt(5.330127, 5.330127, 0.0, 0.0);
    status.axes[1] = axisAt(-9.660254, -9.660254, 0.0, 0.0);
    status.axes[2] = axisAt(2.696152, 2.696152, 0.0, 0.0);
    status.axes[4] = axisAt(60.0, 60.0, 0.0, 0.0);
    status.axes[5] = axisAt(90.0, 90.0, 0.0, 0.0);
    display.setStatus(status);
    DisplaySettings settings;
    settings.positionKind = PositionKind::Nominal;
    display.setDisplaySettings(settings);
    display.setWorkingPlane(plane);
    EXPECT_EQ(display.axisText(Axis::X), "+10.000");
    EXPECT_EQ(display.axisText(Axis::Y), "+5.000");
    EXPECT_EQ(display.axisText(Axis::Z), "+2.000");
    EXPECT_EQ(display.axisText(Axis::B), "+60.000");
}

TEST(OverrideControls, KeysStepTheOverrideAndTheyAreTouchSized) {
    test::testApp();
    OverrideControls controls;
    QSignalSpy feed(&controls, &OverrideControls::feedOverrideChanged);
    controls.feedSlider()->setValue(50);
    ASSERT_EQ(feed.count(), 1);
    EXPECT_DOUBLE_EQ(feed.at(0).at(0).toDouble(), 0.5);
    controls.feedSlider()->setValue(200);  // beyond 150 %: the slider stops there
    EXPECT_DOUBLE_EQ(feed.last().at(0).toDouble(), 1.5);
    EXPECT_EQ(controls.rapidSlider()->maximum(), 100);
    EXPECT_GE(controls.feedSlider()->minimumHeight(), 48);
}

}  // namespace
}  // namespace kerf::ui
