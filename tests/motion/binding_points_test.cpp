#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "motion/kinematics/machine_model.h"
#include "motion/planner/planner.h"
#include "tests/motion/motion_test_run.h"

// Binding points (the servo cycle meets them with a = 0) on a polyline circle: equal limits
// along a run, and limits only as high as the element before allows, must not bind.
namespace kerf::motion::test {
namespace {

constexpr double kFarVelocity = 1e11;

Pose at(double x, double y) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    return p;
}

// gen.py polycircle R50, 0.005 mm, 6 decimals, F6000, `length` mm.
std::vector<canon::Command> polylineCircle(double length) {
    const double r = 50.0;
    const double seg = 0.005;
    std::vector<canon::Command> commands;
    int count = static_cast<int>(std::lround(length / seg));
    for (int i = 1; i <= count; ++i) {
        double s = i * seg;
        canon::Command c;
        c.location.line = static_cast<uint32_t>(i);
        c.body = canon::LinearMove{at(std::round(r * std::sin(s / r) * 1e6) / 1e6,
                                      std::round((r - r * std::cos(s / r)) * 1e6) / 1e6),
                                   6000.0};
        commands.push_back(c);
    }
    return commands;
}

TEST(BindingPoints, FewOnAPolylineCircle) {
    // 20 mm of R50 as 4000 lines: one curve, every blend alike but for 1e-6 mm of rounding.
    // Before: the step limits of the blends all equalled F x 1.5 and each bound, and the share
    // of the tangential limits flipped between neighbours (a binding point at each flip).
    MachineModel model = makeMachineModel(millConfig(), {});
    Planner planner(model);
    planner.setPosition(Pose{}.values);
    std::set<double> binding;
    size_t elements = 0;
    auto take = [&] {
        while (auto item = planner.next()) {
            if (item->kind != MotionItem::Kind::Element) continue;
            ++elements;
            if (item->element.bindVelocity < kFarVelocity) binding.insert(item->element.bindS);
        }
    };
    for (const canon::Command& c : polylineCircle(20.0)) {
        ASSERT_TRUE(planner.add(c));
        take();
    }
    planner.flush();
    take();
    EXPECT_GT(elements, 4000u);
    // Measured: 2597 of 6125 before, 58 now (where the share steps down and back up).
    EXPECT_LE(binding.size(), elements / 50) << binding.size() << " of " << elements;
}

TEST(BindingPoints, PolylineCircleReachesTheFeedAsFastAsTheLimitsAllow) {
    // From rest to 100 mm/s along R50 (centripetal 200 mm/s^2). With a = 0 at every element end
    // the start ramped as v ~ s^(1/3) and did not reach the feed within these 20 mm. With the
    // 30 % share of the limits all the way (600 mm/s^2, 3e5 mm/s^3) it takes
    // v / A + A / J = 100 / 600 + 600 / 3e5 = 0.169 s; measured now 0.121 s.
    double reached = -1.0;
    double time = 0.0;
    SimulationOptions options;
    TestRun run = runCommands(millConfig(), polylineCircle(20.0), Pose{}, options,
                              [&](SimulatedMachine& sim, const Sample&, const MotionStatus& s) {
                                  time += sim.model().periodS;
                                  if (reached < 0.0 && s.pathVelocity >= 99.9) reached = time;
                              });
    SCOPED_TRACE(run.checker->limitSummary());
    ASSERT_GT(reached, 0.0) << "never at the feed";
    EXPECT_LE(reached, 0.169);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
}

}  // namespace
}  // namespace kerf::motion::test
