// The guard at the end of an interpreter's output: straight moves take a shortcut past the general
// inspection, so both must refuse the same numbers (the stream's bound is 1e6, limits included).
#include "core/interp/path/value_guard.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace kerf::interp {
namespace {

class Recorder : public canon::Sink {
public:
    void consume(const canon::Command& c) override { commands.push_back(c); }
    std::vector<canon::Command> commands;
};

canon::Command lineTo(Axis axis, double value, double feed) {
    canon::LinearMove move;
    move.target[axis] = value;
    move.feed = feed;
    return canon::Command{SourceLocation{1, 12, 1, -1}, move};
}

canon::Command rapidTo(Axis axis, double value) {
    canon::RapidMove move;
    move.target[axis] = value;
    return canon::Command{SourceLocation{1, 13, 1, -1}, move};
}

TEST(ValueGuard, PassesStraightMovesUpToTheBound) {
    Recorder out;
    ValueGuard guard;
    guard.setTarget(&out);
    guard.consume(lineTo(Axis::X, 1.0e6, 1.0e6));
    guard.consume(rapidTo(Axis::W, -1.0e6));
    EXPECT_EQ(out.commands.size(), 2u);
    EXPECT_FALSE(guard.takeError());
}

TEST(ValueGuard, RefusesAStraightMoveBeyondTheBoundAndWhatFollows) {
    Recorder out;
    ValueGuard guard;
    guard.setTarget(&out);
    guard.consume(lineTo(Axis::Y, 1.0e6 + 1.0, 100.0));
    guard.consume(lineTo(Axis::X, 1.0, 100.0));
    EXPECT_TRUE(out.commands.empty());
    const auto error = guard.takeError();
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "range");
    EXPECT_EQ(error->location.line, 12u);
    ASSERT_FALSE(error->args.empty());
    EXPECT_EQ(error->args[0], "Y");
}

TEST(ValueGuard, RefusesANotFiniteFeedOrCoordinate) {
    for (const canon::Command& command :
         {lineTo(Axis::X, 1.0, std::numeric_limits<double>::quiet_NaN()),
          rapidTo(Axis::C, -std::numeric_limits<double>::infinity()),
          lineTo(Axis::Z, std::numeric_limits<double>::quiet_NaN(), 100.0)}) {
        Recorder out;
        ValueGuard guard;
        guard.setTarget(&out);
        guard.consume(command);
        EXPECT_TRUE(out.commands.empty());
        EXPECT_TRUE(guard.takeError());
    }
}

}  // namespace
}  // namespace kerf::interp
