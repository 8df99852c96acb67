// The surface a TT cycle hands to the simulated machine: the real tool on the TT's stylus, its
// gauge point an affine map of the drives' tool tip.
#include "core/workpiece/tool_probe_surface.h"

#include <gtest/gtest.h>

namespace kerf::workpiece {
namespace {

TEST(ToolProbeSurface, TheRealToolsEndFaceAndSideTouchTheStylus) {
    // The TT: a disc of diameter 40, top at machine (-200, 50, -300). The drives report the tip
    // of a tool whose table length is 100 in a preset at machine Z -400: the gauge point is the
    // tip + (0, 0, -400 + 100). The real tool is 100.05 long and 4.988 in radius.
    const SimulatedToolProbe tt({{-200.0, 50.0, -300.0}, 40.0, false});
    const ToolProbeSurface surface(tt, Eigen::Affine3d(Eigen::Translation3d(0.0, 0.0, -300.0)),
                                   {100.05, 4.988, {0.0, 0.0}});
    // Over the disc at X -195: the end face, 100.05 below the gauge point, meets the top
    // (machine Z -300) when the tip the control computes with L = 100 is at 100.05.
    EXPECT_FALSE(surface.touches({-195.0, 50.0, 100.05 + 1e-6}));
    EXPECT_TRUE(surface.touches({-195.0, 50.0, 100.05 - 1e-6}));
    // Beside the disc on the -X side, the end face below the top: the side meets the disc's -X
    // face (machine X -220) when the axis is 4.988 before it.
    EXPECT_FALSE(surface.touches({-224.988 - 1e-6, 50.0, 98.0}));
    EXPECT_TRUE(surface.touches({-224.988 + 1e-6, 50.0, 98.0}));
    // There, but with the end face above the top: free.
    EXPECT_FALSE(surface.touches({-224.0, 50.0, 100.06}));
}

}  // namespace
}  // namespace kerf::workpiece
