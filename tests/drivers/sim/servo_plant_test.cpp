#include "drivers/sim/servo_plant.h"

#include <cmath>

#include <gtest/gtest.h>

namespace kerf::drivers::sim {
namespace {

PlantParameters parameters() {
    PlantParameters p;
    p.positionGainPerS = 150.0;
    p.velocityLagS = 0.001;
    p.maxVelocity = 1.0e6;      // counts/s
    p.maxAcceleration = 2.0e7;  // counts/s^2
    p.frictionDecel = 1.0e6;
    return p;
}

// CSP: one target per millisecond on a ramp of 100 counts per period (100000 counts/s). With the
// interpolated target's velocity fed forward the axis follows with almost no error.
TEST(ServoPlant, FollowsARampInCsp) {
    ServoPlant plant;
    plant.configure(parameters());
    plant.reset(0.0);
    double maxError = 0.0;
    for (int k = 1; k <= 200; ++k) {
        plant.interpolateTo(100.0 * k, 0.001);
        plant.advance(0.001);
        if (k > 50) maxError = std::max(maxError, std::fabs(plant.followingError()));
    }
    EXPECT_LT(maxError, 1.0);
    EXPECT_NEAR(plant.velocity(), 1.0e5, 100.0);
    for (int k = 0; k < 100; ++k) {
        plant.interpolateTo(20000.0, 0.001);
        plant.advance(0.001);
    }
    EXPECT_NEAR(plant.position(), 20000.0, 0.5);
}

TEST(ServoPlant, VelocityAndAccelerationAreLimited) {
    ServoPlant plant;
    plant.configure(parameters());
    plant.reset(0.0);
    plant.interpolateTo(1.0e7, 0.001);  // far away in one period
    double lastVelocity = 0.0;
    for (int i = 0; i < 200; ++i) {
        plant.advance(0.0005);
        EXPECT_LE(plant.velocity(), 1.0e6 + 1e-6);
        EXPECT_LE((plant.velocity() - lastVelocity) / 0.0005, 2.0e7 * 1.0001);
        lastVelocity = plant.velocity();
    }
    EXPECT_NEAR(plant.velocity(), 1.0e6, 1.0);
}

// Quick stop: v0 = 1e6 counts/s with 2e6 counts/s^2 stops after about 0.5 s, then holds.
TEST(ServoPlant, RampDownStopsAndHolds) {
    ServoPlant plant;
    plant.configure(parameters());
    plant.reset(0.0);
    plant.velocityTo(1.0e6, 0.0);
    plant.advance(0.2);
    plant.rampDown(2.0e6, true);
    plant.advance(0.45);
    EXPECT_FALSE(plant.rampDone());
    EXPECT_GT(plant.velocity(), 0.0);
    plant.advance(0.1);
    EXPECT_TRUE(plant.rampDone());
    EXPECT_EQ(plant.control(), ServoPlant::Control::Position);
    double stoppedAt = plant.position();
    plant.advance(0.1);
    EXPECT_NEAR(plant.position(), stoppedAt, 1e-6);
}

TEST(ServoPlant, TorqueOffCoastsWithFriction) {
    ServoPlant plant;
    plant.configure(parameters());
    plant.reset(0.0);
    plant.velocityTo(1.0e5, 0.0);
    plant.advance(0.05);
    plant.torqueOff();
    plant.advance(0.05);  // 1e5 counts/s at 1e6 counts/s^2: stopped after 0.1 s, not yet
    EXPECT_NEAR(plant.velocity(), 0.5e5, 200.0);
    plant.advance(0.1);
    EXPECT_EQ(plant.velocity(), 0.0);
}

TEST(ServoPlant, OverloadPushesTheAxisAwayFromItsCommand) {
    ServoPlant plant;
    plant.configure(parameters());
    plant.reset(0.0);
    plant.hold();
    plant.setDrift(5.0e5);
    plant.advance(0.02);
    EXPECT_NEAR(plant.followingError(), -1.0e4, 1.0);
}

}  // namespace
}  // namespace kerf::drivers::sim
