#include "motion/profile/jerk_profile.h"

#include <cmath>

#include <gtest/gtest.h>

#include "motion/profile/braking_envelope.h"

namespace kerf::motion {
namespace {

constexpr Limits kLimits{1000.0, 50000.0};

TEST(JerkProfile, AccelerationWithConstantPhaseMatchesHandComputation) {
    // 0 -> 100 mm/s with A = 1000, J = 50000: ramps of A/J = 20 ms gain A^2/(2J) = 10 mm/s each,
    // so the constant phase lasts (100 - 20) / 1000 = 80 ms; total 120 ms, distance = mean
    // velocity 50 mm/s times 0.12 s = 6 mm (the profile is symmetric).
    Profile p = velocityChange({0.0, 0.0, 0.0}, 100.0, kLimits);
    EXPECT_NEAR(p.duration(), 0.120, 1e-12);
    MotionState end = p.end();
    EXPECT_NEAR(end.v, 100.0, 1e-9);
    EXPECT_NEAR(end.a, 0.0, 1e-9);
    EXPECT_NEAR(end.s, 6.0, 1e-9);
}

TEST(JerkProfile, SmallChangeHasNoConstantPhase) {
    // dv = 8 < A^2/J = 20: peak acceleration sqrt(dv J) = 632.46, time 2 sqrt(dv/J) = 25.3 ms.
    Profile p = velocityChange({0.0, 10.0, 0.0}, 18.0, kLimits);
    EXPECT_NEAR(p.duration(), 2.0 * std::sqrt(8.0 / 50000.0), 1e-12);
    EXPECT_NEAR(p.at(p.duration() / 2.0).a, std::sqrt(8.0 * 50000.0), 1e-6);
    EXPECT_NEAR(p.end().s, 14.0 * p.duration(), 1e-9);
}

TEST(JerkProfile, ProfileNeverExceedsLimits) {
    for (double a0 : {-900.0, -300.0, 0.0, 400.0, 1000.0}) {
        for (double target : {0.0, 5.0, 50.0, 120.0}) {
            Profile p = velocityChange({0.0, 40.0, a0}, target, kLimits);
            double t = 0.0;
            for (int i = 0; i <= 2000; ++i, t = p.duration() * i / 2000.0) {
                MotionState x = p.at(t);
                EXPECT_LE(std::fabs(x.a), kLimits.accel * (1.0 + 1e-9));
            }
            EXPECT_NEAR(p.end().v, target, 1e-6) << a0 << " " << target;
            EXPECT_NEAR(p.end().a, 0.0, 1e-6);
        }
    }
}

TEST(BrakingEnvelope, RestingVelocityInvertsTheBrakingDistance) {
    for (Limits limits : {kLimits, Limits{40.0, 1000.0}}) {
        for (double anchor : {0.0, 3.0, 20.0}) {
            for (double d : {0.001, 0.05, 0.9, 3.0, 40.0}) {
                double v = maxRestingVelocity(d, anchor, limits);
                EXPECT_NEAR(distanceToMeet({0.0, v, 0.0}, anchor, limits), d, 1e-9 * (1.0 + d))
                    << limits.accel << " " << anchor << " " << d;
            }
        }
    }
}

TEST(BrakingEnvelope, EnvelopeIsTheLatestBrakingCurve) {
    // Following the braking profile from any resting velocity, the velocity at each point is at
    // most the envelope there, and equals it once the full deceleration is reached.
    for (double v0 : {30.0, 100.0, 200.0}) {
        Profile brake = velocityChange({0.0, v0, 0.0}, 5.0, kLimits);
        double total = brake.end().s;
        for (int i = 0; i <= 400; ++i) {
            MotionState x = brake.at(brake.duration() * i / 400.0);
            double envelope = brakingEnvelope(total - x.s, 5.0, kLimits);
            EXPECT_LE(x.v, envelope + 1e-9);
            if (std::fabs(x.a + kLimits.accel) < 1e-9) {
                EXPECT_NEAR(x.v, envelope, 1e-6);
            }
        }
    }
}

}  // namespace
}  // namespace kerf::motion
