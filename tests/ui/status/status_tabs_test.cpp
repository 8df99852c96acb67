// The status tabs show what a ProgramStatus holds, in the program's unit; expected texts are
// written by hand from the values put in.
#include "ui/status/status_tabs.h"

#include <QHeaderView>
#include <QLineEdit>
#include <QTabBar>
#include <QTableWidget>

#include <gtest/gtest.h>

#include "qt_test_app.h"
#include "ui/status/machine_functions.h"

namespace kerf::ui {
namespace {

using Status = interp::ProgramStatus;
using Tab = StatusTabs::Tab;

Status millStatus() {
    Status s;
    s.mainProgram = "STAT.H";
    s.activeProgram = "SUB.H";
    s.label = "LBL 1";
    s.cycle = Status::Cycle{200, "DRILLING"};
    s.activeM = {3, 8};
    s.line = 20;
    s.blockNumber = 17;  // a CYCL DEF's parameter lines before it
    s.tool.number = 3;
    s.tool.name = "MILL_D12";
    s.tool.lengthMm = 40.0;
    s.tool.radiusMm = 6.0;
    s.tool.deltaLengthMm = 0.7;
    s.tool.deltaRadiusMm = -0.2;
    s.tool.axis = Axis::Z;
    s.transformations.datumShift[Axis::X] = 10.0;
    s.transformations.datumShift[Axis::Y] = -5.0;
    s.transformations.mirrored = axisBit(Axis::X);
    s.transformations.rotationDeg = 30.0;
    for (size_t i = 0; i < 3; ++i)
        s.transformations.scale[i] = 0.5;
    s.parameters = {{"Q5", 12.5, {}, Status::ParameterScope::Global, 0},
                    {"Q108", 5.8, {}, Status::ParameterScope::Global, 0},
                    {"QL2", 3.0, {}, Status::ParameterScope::Local, 0},
                    {"QS1", 0.0, "abc", Status::ParameterScope::Text, 0}};
    return s;
}

std::vector<QString> visibleParameters(const StatusTabs& tabs) {
    std::vector<QString> names;
    const QTableWidget* t = tabs.table(Tab::Parameters);
    for (int r = 0; r < t->rowCount(); ++r) {
        if (!t->isRowHidden(r)) names.push_back(t->item(r, 0)->text());
    }
    return names;
}

TEST(StatusTabs, TabsAreNamedAsOnTheControl) {
    test::testApp();
    StatusTabs tabs('Q');
    ASSERT_EQ(tabs.count(), 5);
    EXPECT_EQ(tabs.tabText(0), "PGM");
    EXPECT_EQ(tabs.tabText(1), "TOOL");
    EXPECT_EQ(tabs.tabText(2), "TRANS");
    EXPECT_EQ(tabs.tabText(3), "QPARA");
    EXPECT_EQ(tabs.tabText(4), "PROBE");
    StatusTabs fagor('P');
    EXPECT_EQ(fagor.tabText(3), "PPARA");
}

TEST(StatusTabs, ProgramToolAndTransformationsInMillimetres) {
    test::testApp();
    StatusTabs tabs;
    tabs.setProgramStatus(millStatus());

    EXPECT_EQ(tabs.valueOf(Tab::Program, "Program"), "STAT.H");
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Called program"), "SUB.H");
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Label"), "LBL 1");
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Cycle"), "200 DRILLING");
    EXPECT_EQ(tabs.valueOf(Tab::Program, "M functions"), "M3 M8");
    // The block as the program numbers it, not the file line.
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Block"), "17");
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Unit"), "mm");

    EXPECT_EQ(tabs.valueOf(Tab::Tool, "Tool"), "3");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "Name"), "MILL_D12");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "L"), "40.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "R"), "6.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "DL"), "0.700 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "DR"), "-0.200 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "Tool axis"), "Z");

    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Datum shift X"), "10.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Datum shift Y"), "-5.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Datum shift Z"), "0.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Datum shift A"), "");  // not shifted: no row
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Mirrored axes"), "X");
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Rotation"), QString("30.000\u00b0"));
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Scaling"), "0.5000");
}

// Untilted: no working-plane rows; tilted: its angles and the tool in its coordinates.
TEST(StatusTabs, TiltedWorkingPlaneShowsItsAnglesAndPosition) {
    test::testApp();
    StatusTabs tabs;
    Status s = millStatus();
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Working plane"), "");
    s.transformations.workingPlane =
        interp::ProgramStatus::Transformations::WorkingPlane{{0.0, 90.0, -15.5}, {10.0, 5.0, 12.0}};
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Working plane"),
              QString("SPA 0.000°  SPB 90.000°  SPC -15.500°"));
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Working plane X"), "10.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Working plane Y"), "5.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Working plane Z"), "12.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Rotary axes"), "");  // no kinematics given
    // The solved angles of a B/C machine, in degrees.
    s.transformations.workingPlane->rotaryAxes = axisBit(Axis::B) | axisBit(Axis::C);
    s.transformations.workingPlane->rotaryDeg = {0.0, -90.0, 195.5};
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Rotary axes"), QString("B -90.000°  C 195.500°"));
}

TEST(StatusTabs, InchProgramsShowInches) {
    test::testApp();
    StatusTabs tabs;
    Status s = millStatus();
    s.inch = true;
    s.tool.lengthMm = 25.4;
    s.transformations.datumShift[Axis::X] = 50.8;
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Unit"), "inch");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "L"), "1.0000 in");
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Datum shift X"), "2.0000 in");
}

TEST(StatusTabs, SpindleAndFeedAsProgrammed) {
    test::testApp();
    StatusTabs tabs;
    Status s = millStatus();
    s.motion.surfaceMPerMin = 180.0;
    s.motion.spindleLimitRpm = 3000.0;
    s.motion.feedMm = 0.2;
    s.motion.feedPerRevolution = true;
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Spindle"),
              "S 180 m/min (constant surface speed), limit 3000 rpm");
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Feed"), "F 0.200 mm/rev");
    // Inch: 180 m/min = 590.55 ft/min; 254 mm/min = 10 in/min.
    s.inch = true;
    s.motion.feedMm = 254.0;
    s.motion.feedPerRevolution = false;
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Spindle"),
              "S 591 ft/min (constant surface speed), limit 3000 rpm");
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Feed"), "F 10.00 in/min");
    s.motion.surfaceMPerMin.reset();
    s.motion.spindleLimitRpm = 0.0;
    s.motion.spindleRpm = 1200.0;
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Spindle"), "S 1200 rpm");
}

TEST(StatusTabs, NothingActiveSaysNone) {
    test::testApp();
    StatusTabs tabs;
    Status s;
    s.mainProgram = "A.H";
    s.activeProgram = "A.H";
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Called program"), "none");
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Label"), "none");
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Cycle"), "none");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "Tool"), "none");
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Mirrored axes"), "none");
    EXPECT_EQ(tabs.valueOf(Tab::Probe, "Probe"), "no result");
}

TEST(StatusTabs, ScalingPerAxisListsEachFactor) {
    test::testApp();
    StatusTabs tabs;
    Status s;
    s.transformations.scale[0] = 0.5;
    s.transformations.scale[1] = 2.0;
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Scaling"), "X 0.5000  Y 2.0000  Z 1.0000");
}

TEST(StatusTabs, ParametersWithValuesKindsAndFilter) {
    test::testApp();
    StatusTabs tabs;
    tabs.setProgramStatus(millStatus());
    EXPECT_EQ(tabs.valueOf(Tab::Parameters, "Q5"), "12.5");
    EXPECT_EQ(tabs.valueOf(Tab::Parameters, "Q108"), "5.8");
    EXPECT_EQ(tabs.valueOf(Tab::Parameters, "QS1"), "\"abc\"");
    EXPECT_EQ(tabs.table(Tab::Parameters)->item(2, 2)->text(), "local");
    EXPECT_EQ(visibleParameters(tabs), (std::vector<QString>{"Q5", "Q108", "QL2", "QS1"}));

    tabs.parameterFilter()->setText("QL");
    EXPECT_EQ(visibleParameters(tabs), (std::vector<QString>{"QL2"}));
    tabs.parameterFilter()->setText("q1");  // any case; QS1 does not contain "Q1"
    EXPECT_EQ(visibleParameters(tabs), (std::vector<QString>{"Q108"}));
    // The filter stays when new values arrive.
    Status s = millStatus();
    s.parameters.push_back({"Q150", 1.0, {}, Status::ParameterScope::Global, 0});
    tabs.setProgramStatus(s);
    EXPECT_EQ(visibleParameters(tabs), (std::vector<QString>{"Q108", "Q150"}));
}

TEST(StatusTabs, FagorToolOffsetAndLocalLevels) {
    test::testApp();
    StatusTabs tabs('P');
    Status s;
    s.parameterLetter = 'P';
    s.tool.number = 1;
    s.tool.radiusMm = 0.4;
    s.tool.lathe = Status::Tool::LatheOffset{1, 1.0, 2.0, 0.1, -0.2, 3};
    s.transformations.datum = "G54 G58";
    s.parameters = {{"P0", 2.0, {}, Status::ParameterScope::Local, 1},
                    {"P100", 7.0, {}, Status::ParameterScope::Global, 0}};
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.tabText(3), "PPARA");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "Offset"), "D1");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "X (radius)"), "1.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "Z"), "2.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "R"), "0.400 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "Wear X (I)"), "0.100 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "Wear Z (K)"), "-0.200 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "Location code (F)"), "3");
    EXPECT_EQ(tabs.valueOf(Tab::Tool, "L"), "");  // no milling rows on a lathe
    EXPECT_EQ(tabs.valueOf(Tab::Transformations, "Zero offset"), "G54 G58");
    EXPECT_EQ(tabs.table(Tab::Parameters)->item(0, 2)->text(), "local, level 1");
    EXPECT_EQ(tabs.table(Tab::Parameters)->item(1, 2)->text(), "global");
}

TEST(StatusTabs, FagorBlocksByTheirNNumberAndByLineWithout) {
    test::testApp();
    StatusTabs tabs('P');
    interp::ProgramStatus s;
    s.parameterLetter = 'P';
    s.line = 4;
    s.blockNumber = 30;
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Block"), "N30");
    s.blockNumber = -1;  // a FAGOR block without N
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Program, "Block"), "line 4");
}

TEST(StatusTabs, ProbeResult) {
    test::testApp();
    StatusTabs tabs;
    Status s;
    Status::Probe probe;
    probe.triggered = true;
    probe.position[Axis::X] = 1.0;
    probe.position[Axis::Y] = 2.0;
    probe.position[Axis::Z] = -3.5;
    s.probe = probe;
    tabs.setProgramStatus(s);
    EXPECT_EQ(tabs.valueOf(Tab::Probe, "Probe"), "touched");
    EXPECT_EQ(tabs.valueOf(Tab::Probe, "X"), "1.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Probe, "Y"), "2.000 mm");
    EXPECT_EQ(tabs.valueOf(Tab::Probe, "Z"), "-3.500 mm");
}

TEST(StatusTabs, RowsAndTabsAreTallEnoughForTouch) {
    test::testApp();
    StatusTabs tabs;
    tabs.resize(500, 600);
    tabs.setProgramStatus(millStatus());
    tabs.show();
    QApplication::processEvents();
    for (int i = 0; i < tabs.count(); ++i)
        EXPECT_GE(tabs.tabBar()->tabRect(i).height(), 48) << i;
    for (Tab tab : {Tab::Program, Tab::Tool, Tab::Transformations, Tab::Parameters, Tab::Probe}) {
        const QTableWidget* t = tabs.table(tab);
        ASSERT_GT(t->rowCount(), 0);
        EXPECT_GE(t->rowHeight(0), 48);
    }
    EXPECT_GE(tabs.parameterFilter()->height(), 48);
}

// The machine's spindle and coolant replace the program's in the M functions: M4 from a spindle
// turning backwards (negative speed), the program's M7 (mist) kept while a coolant is on, other
// M functions (M91 is not modal, M41 a FAGOR gear range) left as they are.
TEST(MachineFunctions, TheMachinesSpindleAndCoolantReplaceTheProgramsOnes) {
    Status program;
    program.activeM = {3, 7, 41};
    program.motion.spindleRpm = 800.0;
    task::MachineStatus machine;
    machine.programmedSpindleRpm = 1200.0;
    machine.actualSpindleRpm = -1150.0;  // ramping up counter-clockwise
    machine.coolant = true;
    Status shown = withMachineSpindleAndCoolant(program, machine);
    EXPECT_EQ(shown.activeM, (std::vector<int>{4, 7, 41}));
    EXPECT_EQ(shown.motion.spindleRpm, 1200.0);
    machine.programmedSpindleRpm = 0.0;
    machine.actualSpindleRpm = 0.0;
    machine.coolant = false;
    shown = withMachineSpindleAndCoolant(program, machine);
    EXPECT_EQ(shown.activeM, (std::vector<int>{5, 9, 41}));
    EXPECT_EQ(shown.motion.spindleRpm, 800.0);  // the S programmed stays while the spindle stands
}

}  // namespace
}  // namespace kerf::ui
