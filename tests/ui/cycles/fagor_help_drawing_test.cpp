// The FAGOR help pictures drawn as the passes meet the part: a lathe from the side, Z to the
// right, the call point and the tool at the upper right. Positions are read back from the
// drawing's own shapes (the part's outline, the dimension arrows), not from its coordinates.
#include "ui/cycles/fagor_help_drawing.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "core/interp/fagor/cycle_syntax.h"

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
// A picture names only what its cycle's block can program: G66 has no retract D (each pass goes
// back to the call point), G68/G69 no end point Q/R.
TEST(FagorHelpDrawing, EveryDimensionIsAParameterOfItsCycle) {
    for (const int g : {66, 68, 69, 81, 82, 83, 84, 85, 86, 87, 88, 89}) {
        const fagor::CycleSyntax* syntax = fagor::cycleSyntax(g);
        ASSERT_NE(syntax, nullptr) << g;
        for (const HelpDimension& dimension : fagorHelpDrawing(g).dimensions) {
            for (const QString& key : dimension.keys) {
                ASSERT_EQ(key.size(), 1) << "G" << g << " " << key.toStdString();
                EXPECT_NE(syntax->find(key.at(0).toLatin1()), nullptr)
                    << "G" << g << " draws " << key.toStdString();
            }
        }
    }
}

// G66 copies the profile: its passes step along X like the profile, not straight along Z.
TEST(FagorHelpDrawing, PatternRepeatPassesFollowTheProfile) {
    const HelpDrawing d = fagorHelpDrawing(66);
    // Left of the shoulder (x 30) the passes lie higher than right of it, as the profile does:
    // some stroke crosses x = 30 between the raw outline and the allowance (y 24 to 33); straight
    // passes along Z would end at the shoulder.
    bool passAboveTheHighStep = false;
    for (int i = 1; i < d.lines.elementCount(); ++i) {
        const QPainterPath::Element a = d.lines.elementAt(i - 1);
        const QPainterPath::Element b = d.lines.elementAt(i);
        if (!b.isLineTo()) continue;
        const bool crosses = std::min(a.x, b.x) <= 30.0 && std::max(a.x, b.x) >= 30.0;
        passAboveTheHighStep |= crosses && a.y > 24.0 && a.y < 33.0 && b.y > 24.0 && b.y < 33.0;
    }
    EXPECT_TRUE(passAboveTheHighStep);
    EXPECT_EQ(d.find(QStringLiteral("D")), nullptr);
    EXPECT_NE(d.find(QStringLiteral("I")), nullptr);
}

// The allowance, the passes and the raw outline lie outside the finished part: a line through
// the part would be a cut into it (the allowance's wall was drawn inside the high step).
TEST(FagorHelpDrawing, NoStrokeRunsThroughThePart) {
    for (const int g : {66, 68, 69, 81, 82, 84, 85}) {
        const HelpDrawing d = fagorHelpDrawing(g);
        for (int i = 1; i < d.lines.elementCount(); ++i) {
            const QPainterPath::Element a = d.lines.elementAt(i - 1);
            const QPainterPath::Element b = d.lines.elementAt(i);
            if (!b.isLineTo()) continue;
            const QPointF mid((a.x + b.x) / 2.0, (a.y + b.y) / 2.0);
            EXPECT_FALSE(d.solid.contains(QRectF(mid.x() - 0.5, mid.y() - 0.5, 1.0, 1.0)))
                << "G" << g << ": stroke through the part at " << mid.x() << ", " << mid.y();
        }
    }
}

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
