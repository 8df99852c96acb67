// The FAGOR help pictures drawn as the passes meet the part: a lathe from the side, Z to the
// right, the call point and the tool at the upper right. Positions are read back from the
// drawing's own shapes (the part's outline, the dimension arrows), not from its coordinates.
#include "ui/cycles/fagor_help_drawing.h"

#include <gtest/gtest.h>

namespace kerf::ui {
namespace {

// The height (smallest y, y down) of the part at `x` in the 100 x 100 drawing; 100: no part.
double partTop(const HelpDrawing& d, double x) {
    for (double y = 0.0; y < 100.0; y += 0.25)
        if (d.solid.contains(QPointF(x, y))) return y;
    return 100.0;
}

double partRightEnd(const HelpDrawing& d) {
    return d.solid.boundingRect().right();
}

QRectF dimension(const HelpDrawing& d, const QString& key) {
    const HelpDimension* found = d.find(key);
    return found ? found->path.boundingRect() : QRectF();
}

// Turning and stock removal: the passes come from the call point at the right, so the profile
// must grow away from it (an undercut otherwise), and X, Z name the start point at its right
// end, where the passes first meet it.
TEST(FagorHelpDrawing, TurningProfilesGrowAwayFromTheCallPointAndStartAtItsSide) {
    for (const int g : {66, 68, 69, 81, 82, 84, 85}) {
        const HelpDrawing d = fagorHelpDrawing(g);
        const double right = partRightEnd(d);
        const double nearCallPoint = partTop(d, right - 2.0);
        EXPECT_GT(nearCallPoint, partTop(d, d.solid.boundingRect().left() + 2.0))
            << "G" << g << ": the part must be higher away from the call point";
        const QRectF x = dimension(d, QStringLiteral("X"));
        const QRectF z = dimension(d, QStringLiteral("Z"));
        ASSERT_FALSE(x.isNull()) << g;
        ASSERT_FALSE(z.isNull()) << g;
        EXPECT_NEAR(x.top(), nearCallPoint, 0.3) << "G" << g << ": X ends at the start point";
        EXPECT_NEAR(z.right(), right, 0.3) << "G" << g << ": Z ends at the start point";
    }
}

// Threads: X and Z name the thread's start point at the right end of the part, not the
// approach point D: above it on the shaft (G86), in front of the face for the face thread (G87),
// whose depth I runs along Z into the face.
TEST(FagorHelpDrawing, ThreadsMeasureTheStartPointOnTheThread) {
    for (const int g : {86, 87}) {
        const HelpDrawing d = fagorHelpDrawing(g);
        const double right = partRightEnd(d);
        const double top = partTop(d, right - 2.0);
        EXPECT_NEAR(dimension(d, QStringLiteral("X")).top(), top, 0.3) << g;
        EXPECT_NEAR(dimension(d, QStringLiteral("Z")).right(), right, 0.3) << g;
        const QRectF approach = dimension(d, QStringLiteral("D"));
        const QRectF depth = dimension(d, QStringLiteral("I"));
        if (g == 86) {
            EXPECT_LT(approach.top(), top - 1.0) << "D lies above the start point";
            EXPECT_GT(depth.height(), depth.width()) << "the depth runs along X";
        } else {
            EXPECT_NEAR(approach.left(), right, 0.3) << "D starts at the face";
            EXPECT_GT(approach.right(), right + 1.0) << "D lies in front of the face";
            EXPECT_GT(depth.width(), depth.height()) << "the depth runs along Z";
        }
    }
}

}  // namespace
}  // namespace kerf::ui
