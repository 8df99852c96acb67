#include "drivers/cia402/drive_axis.h"

#include <vector>

#include <gtest/gtest.h>

namespace kerf::drivers::cia402 {
namespace {

using namespace std::chrono_literals;

class DriveAxisTest : public testing::Test {
protected:
    DriveAxisTest() { axis.configure(Mode::CyclicPosition, 500ms); }
    uint16_t step(uint16_t statusword, std::chrono::nanoseconds now = 0ms) {
        axis.onStatusword(statusword, now);
        return axis.nextControlword();
    }
    DriveAxis axis;
};

TEST_F(DriveAxisTest, EnablesThroughEachConfirmedState) {
    axis.setGoal(Goal::Enabled, 0ms);
    EXPECT_EQ(step(0x0250), 0x06);
    EXPECT_EQ(step(0x0250), 0x06) << "holds the command until the statusword confirms";
    EXPECT_EQ(step(0x0231), 0x07);
    EXPECT_EQ(step(0x0233), 0x0F);
    EXPECT_FALSE(axis.followsTarget());
    EXPECT_EQ(step(0x0237), 0x0F);
    EXPECT_FALSE(axis.followsTarget()) << "CSP: not before statusword bit 12";
    EXPECT_EQ(step(0x1237), 0x0F);
    EXPECT_TRUE(axis.followsTarget());
}

TEST_F(DriveAxisTest, QuickStopKeepsTheEnableBits) {
    axis.setGoal(Goal::Enabled, 0ms);
    step(0x1237);
    axis.setGoal(Goal::QuickStop, 1ms);
    EXPECT_EQ(axis.nextControlword(), 0x0B);
    EXPECT_EQ(step(0x0217), 0x0B) << "held in Quick stop active";
}

TEST_F(DriveAxisTest, DisableGoesThroughDisableOperation) {
    axis.setGoal(Goal::Enabled, 0ms);
    step(0x1237);
    axis.setGoal(Goal::Disabled, 1ms);
    EXPECT_EQ(axis.nextControlword(), 0x07);
    EXPECT_EQ(step(0x0233), 0x00);
    EXPECT_EQ(step(0x0250), 0x00);
}

// A2.3: the fault reset acts on the rising edge of bit 7 (0x00, then 0x80), only on request,
// and once: a fault that persists needs a new request.
TEST_F(DriveAxisTest, FaultResetIsOneEdgeOnRequest) {
    axis.setGoal(Goal::Enabled, 0ms);
    EXPECT_EQ(step(0x0218), 0x00);
    EXPECT_EQ(step(0x0218), 0x00) << "no reset without a request";
    axis.requestFaultReset();
    EXPECT_EQ(step(0x0218), 0x00);
    EXPECT_EQ(step(0x0218), 0x80);
    EXPECT_EQ(step(0x0218), 0x80) << "bit 7 stays set: no second edge";
    EXPECT_EQ(step(0x0250), 0x06) << "out of Fault: enable again";
}

TEST_F(DriveAxisTest, ResetRequestOutsideFaultIsForgotten) {
    axis.setGoal(Goal::Enabled, 0ms);
    step(0x1237);
    axis.requestFaultReset();
    EXPECT_EQ(step(0x0218), 0x00) << "a later fault is not reset by the old request";
    EXPECT_EQ(step(0x0218), 0x00);
}

TEST_F(DriveAxisTest, UnconfirmedStepTimesOut) {
    axis.setGoal(Goal::Enabled, 0ms);
    step(0x0250, 0ms);
    step(0x0231, 100ms);
    EXPECT_FALSE(axis.stepTimedOut(600ms));
    EXPECT_TRUE(axis.stepTimedOut(601ms));
    step(0x1237, 650ms);
    EXPECT_FALSE(axis.stepTimedOut(2000ms));
}

TEST_F(DriveAxisTest, FollowingErrorBitInCsp) {
    axis.setGoal(Goal::Enabled, 0ms);
    step(0x1237);
    EXPECT_FALSE(axis.followingError());
    step(0x3237);
    EXPECT_TRUE(axis.followingError());
}

TEST(DriveAxisModes, ProfileVelocityFollowsWhenEnabled) {
    DriveAxis axis;
    axis.configure(Mode::ProfileVelocity, 500ms);
    axis.onStatusword(0x0237, 0ms);
    EXPECT_TRUE(axis.followsTarget()) << "PV has no 'target ignored' bit";
    EXPECT_FALSE(axis.followingError());
}

}  // namespace
}  // namespace kerf::drivers::cia402
