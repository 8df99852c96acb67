#include "ui/status/position_display.h"

#include <QLabel>
#include <QSignalSpy>
#include <QSlider>

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
