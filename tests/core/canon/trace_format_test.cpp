#include "core/canon/trace_format.h"

#include <gtest/gtest.h>

namespace kerf::canon {
namespace {

std::string line(CommandBody body, SourceLocation at = {0, 3, 1, 2}) {
    std::string out;
    TraceFormat format;
    format.fileName = [](uint32_t) { return std::string("SUB.H"); };
    appendCommand(out, Command{at, std::move(body)}, format);
    return out;
}

Pose xyz(double x, double y, double z) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

TEST(TraceFormat, MovesWithFixedDecimalsAndNoNegativeZero) {
    EXPECT_EQ(line(RapidMove{xyz(1, -0.0, -0.00001)}), "3:1 N2 RAPID X1.0000 Y0.0000 Z0.0000");
    EXPECT_EQ(line(LinearMove{xyz(1.23456, 2, 3), 100}),
              "3:1 N2 LINE X1.2346 Y2.0000 Z3.0000 F100.000");
    ArcMove arc{xyz(0, 10, 0), Vec3(0, 0, 0), Plane::XY, 3.14159265358979323846, 50};
    EXPECT_EQ(line(arc),
              "3:1 N2 ARC X0.0000 Y10.0000 Z0.0000 CENTER X0.0000 Y0.0000 PLANE XY SWEEP "
              "180.0000 F50.000");
}

TEST(TraceFormat, FileNamesOnlyForCalledPrograms) {
    EXPECT_EQ(line(Dwell{1.5}, {1, 4, 1, -1}), "SUB.H:4:1 DWELL 1.500");
}

TEST(TraceFormat, OtherCommands) {
    EXPECT_EQ(line(ToolChange{5, "MILL", {50, 5, 0}, Axis::Z}),
              "3:1 N2 TOOL T5 \"MILL\" L=50.0000 R=5.0000 R2=0.0000 AXIS Z");
    EXPECT_EQ(line(SpindleControl{SpindleDirection::CounterClockwise, 800}),
              "3:1 N2 SPINDLE CCW S800.000");
    EXPECT_EQ(line(CoolantControl{true, true}), "3:1 N2 COOLANT FLOOD+MIST");
    EXPECT_EQ(line(ProgramStop{StopKind::End, 30}), "3:1 N2 END M30");
    EXPECT_EQ(line(ProgramStop{StopKind::Program, -1}), "3:1 N2 STOP");
    EXPECT_EQ(line(Message{MessageKind::Print, "a\"b"}), "3:1 N2 MSG PRINT \"a\\\"b\"");
    EXPECT_EQ(line(SyncPoint{SyncReason::ReadPosition}), "3:1 N2 SYNC POSITION");
    EXPECT_EQ(line(SyncPoint{SyncReason::Operator}), "3:1 N2 SYNC OPERATOR");
}

}  // namespace
}  // namespace kerf::canon
