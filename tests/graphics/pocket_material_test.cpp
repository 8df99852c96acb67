// Material checks of the pocket, slot and stud cycles (issue 16): each program in pockets/ runs
// through the interpreter into the height-field stock; the removed volume must match the
// analytic volume within 1 %, no cell more than one cell outside the programmed contour (plus
// allowance) may lose material, and every cell more than one cell inside it must reach the depth.
// The shapes are described here independently of the cycles, by signed distance functions.
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <gtest/gtest.h>

#include "app/runner/session.h"
#include "graphics/stock/stock_simulation.h"

namespace kerf {
namespace {

namespace fs = std::filesystem;
using graphics::HeightFieldStock;
using graphics::StockSimulation;

constexpr double kPi = std::numbers::pi;
const fs::path kPrograms = fs::path(KERF_SOURCE_DIR) / "tests" / "graphics" / "pockets";

// Signed distance to a rectangle of half sides (hx, hy) with corner radius r, centred at c and
// turned by `angleDeg`: negative inside.
std::function<double(double, double)> roundedBox(Vec2 c, double hx, double hy, double r,
                                                 double angleDeg) {
    return [=](double x, double y) {
        const double a = -angleDeg * kPi / 180.0;
        const double dx = x - c.x();
        const double dy = y - c.y();
        const double u = std::fabs(std::cos(a) * dx - std::sin(a) * dy) - (hx - r);
        const double v = std::fabs(std::sin(a) * dx + std::cos(a) * dy) - (hy - r);
        const double outside = std::hypot(std::max(u, 0.0), std::max(v, 0.0));
        return outside + std::min(std::max(u, v), 0.0) - r;
    };
}

std::function<double(double, double)> circle(Vec2 c, double r) {
    return [=](double x, double y) { return std::hypot(x - c.x(), y - c.y()) - r; };
}

// Signed distance to a circular slot: the band of half width h about the arc of radius r about c
// from `fromDeg` over `sweepDeg` (counter-clockwise).
std::function<double(double, double)> arcBand(Vec2 c, double r, double fromDeg, double sweepDeg,
                                              double h) {
    return [=](double x, double y) {
        const double a0 = fromDeg * kPi / 180.0;
        const double sweep = sweepDeg * kPi / 180.0;
        double along = std::atan2(y - c.y(), x - c.x()) - a0;
        along -= 2.0 * kPi * std::floor(along / (2.0 * kPi));
        if (along <= sweep) return std::fabs(std::hypot(x - c.x(), y - c.y()) - r) - h;
        const double a1 = a0 + sweep;
        const double d0 = std::hypot(x - c.x() - r * std::cos(a0), y - c.y() - r * std::sin(a0));
        const double d1 = std::hypot(x - c.x() - r * std::cos(a1), y - c.y() - r * std::sin(a1));
        return std::min(d0, d1) - h;
    };
}

std::unique_ptr<StockSimulation> machine(const std::string& program) {
    app::RunOptions options;
    options.program = kPrograms / program;
    options.toolTable = kPrograms / "TOOL.T";
    auto session = app::openSession(options);
    EXPECT_TRUE(session && session->ready());
    auto stock = std::make_unique<StockSimulation>();
    if (!session || !session->ready()) return stock;
    interp::Interpreter& interpreter = *session->program.interpreter;
    stock->setStart(interpreter.nominalPosition());
    for (;;) {
        const interp::RunStatus status = interpreter.run(*stock, 100000);
        if (status == interp::RunStatus::NeedsSync) {
            interp::WorldSnapshot world;
            world.position = interpreter.nominalPosition();
            interpreter.resume(world);
            continue;
        }
        if (status != interp::RunStatus::BudgetUsed) {
            EXPECT_EQ(status, interp::RunStatus::Finished);
            break;
        }
    }
    for (const Diagnostic& d : interpreter.diagnostics())
        EXPECT_NE(d.severity, Severity::Error) << d.code;
    stock->finish();
    return stock;
}

// `removedInside`: the shape is a pocket (material inside goes) or a stud (material outside goes).
void expectShape(const HeightFieldStock& s, const std::function<double(double, double)>& shape,
                 bool removedInside, double depth) {
    const double cell = s.cellMm();
    const double margin = 1.5 * cell;
    int cut = 0;
    int kept = 0;
    for (int j = 0; j < s.cellsY(); ++j) {
        for (int i = 0; i < s.cellsX(); ++i) {
            const double x = s.minCorner().x() + (i + 0.5) * cell;
            const double y = s.minCorner().y() + (j + 0.5) * cell;
            const double d = removedInside ? shape(x, y) : -shape(x, y);
            const double top = s.topAt(i, j);
            if (d > margin) {
                ASSERT_NEAR(top, 0.0, 1e-6) << "material removed at X" << x << " Y" << y;
                ++kept;
            } else if (d < -margin) {
                ASSERT_NEAR(top, -depth, 0.01) << "material left at X" << x << " Y" << y;
                ++cut;
            }
        }
    }
    EXPECT_GT(cut, 1000);
    EXPECT_GT(kept, 1000);
}

TEST(PocketMaterial, RectangularPocketTurnedAndFinished) {
    auto stock = machine("pocket_251.H");
    ASSERT_TRUE(stock->millStock());
    // 60 x 40, corners R5 (not smaller than the tool radius 4), 10 deep, turned 30 degrees.
    const double volume = (60.0 * 40.0 - (4.0 - kPi) * 25.0) * 10.0;
    EXPECT_NEAR(stock->removedVolumeMm3(), volume, 0.01 * volume);
    expectShape(*stock->millStock(), roundedBox({50, 50}, 30, 20, 5, 30), true, 10.0);
}

TEST(PocketMaterial, CircularPocketUpCut) {
    auto stock = machine("pocket_252.H");
    ASSERT_TRUE(stock->millStock());
    const double volume = kPi * 25.0 * 25.0 * 12.0;
    EXPECT_NEAR(stock->removedVolumeMm3(), volume, 0.01 * volume);
    expectShape(*stock->millStock(), circle({50, 50}, 25), true, 12.0);
}

TEST(PocketMaterial, SlotFromItsLeftEndTurnedUpright) {
    auto stock = machine("slot_253.H");
    ASSERT_TRUE(stock->millStock());
    // 50 x 12 from X25 Y50 (Q367 = 1: left end) turned 90 degrees: centre X25 Y75, along Y.
    const double volume = (38.0 * 12.0 + kPi * 36.0) * 6.0;
    EXPECT_NEAR(stock->removedVolumeMm3(), volume, 0.01 * volume);
    expectShape(*stock->millStock(), roundedBox({25, 75}, 25, 6, 6, 90), true, 6.0);
}

TEST(PocketMaterial, CircularSlotsRepeatedAboutThePitchCentre) {
    auto stock = machine("slot_254.H");
    ASSERT_TRUE(stock->millStock());
    // Two slots 12 wide on the pitch circle R35 about X50 Y50, 45..135 and 225..315 degrees,
    // 10 deep: each a quarter of the annulus 29..41 and two half discs of radius 6.
    const double slot = (41.0 * 41.0 - 29.0 * 29.0) * kPi / 4.0 + kPi * 36.0;
    EXPECT_NEAR(stock->removedVolumeMm3(), 2.0 * slot * 10.0, 0.01 * 2.0 * slot * 10.0);
    const auto first = arcBand({50, 50}, 35, 45, 90, 6);
    const auto second = arcBand({50, 50}, 35, 225, 90, 6);
    expectShape(
        *stock->millStock(),
        [&](double x, double y) { return std::min(first(x, y), second(x, y)); }, true, 10.0);
}

TEST(PocketMaterial, RectangularStudKeepsItsSizePlusAllowance) {
    auto stock = machine("stud_256.H");
    ASSERT_TRUE(stock->millStock());
    // Roughing only: 40 x 30 R6 plus 0.4 all round stays; the 60 x 50 blank around it goes.
    const double stud = 40.8 * 30.8 - (4.0 - kPi) * 6.4 * 6.4;
    const double volume = (60.0 * 50.0 - stud) * 10.0;
    EXPECT_NEAR(stock->removedVolumeMm3(), volume, 0.01 * volume);
    expectShape(*stock->millStock(), roundedBox({50, 50}, 20.4, 15.4, 6.4, 0), false, 10.0);
}

TEST(PocketMaterial, CircularStudFinishedToSize) {
    auto stock = machine("stud_257.H");
    ASSERT_TRUE(stock->millStock());
    const double volume = (60.0 * 60.0 - kPi * 20.0 * 20.0) * 8.0;
    EXPECT_NEAR(stock->removedVolumeMm3(), volume, 0.01 * volume);
    expectShape(*stock->millStock(), circle({50, 50}, 20), false, 8.0);
}

// Signed distance to a regular hexagon of inradius `ri` about c whose first corner lies at
// `cornerDeg`, corners rounded with r: the hexagon of inradius ri - r grown by r.
double roundedHexagon(Vec2 c, double ri, double cornerDeg, double r, double x, double y) {
    const double inner = ri - r;
    const double innerCorner = inner / std::cos(kPi / 6.0);
    double sideMax = -1e9;
    for (int k = 0; k < 6; ++k) {
        const double normal = (cornerDeg + 30.0 + 60.0 * k) * kPi / 180.0;
        sideMax = std::max(sideMax,
                           (x - c.x()) * std::cos(normal) + (y - c.y()) * std::sin(normal) - inner);
    }
    if (sideMax <= 0.0) return sideMax - r;  // inside the inner hexagon
    // Outside it: the distance to the nearest point of its sides.
    double nearest = 1e9;
    for (int k = 0; k < 6; ++k) {
        const double a0 = (cornerDeg + 60.0 * k) * kPi / 180.0;
        const double a1 = a0 + kPi / 3.0;
        const Vec2 p0 = c + innerCorner * Vec2(std::cos(a0), std::sin(a0));
        const Vec2 p1 = c + innerCorner * Vec2(std::cos(a1), std::sin(a1));
        const Vec2 d = p1 - p0;
        const double t = std::clamp((Vec2(x, y) - p0).dot(d) / d.squaredNorm(), 0.0, 1.0);
        nearest = std::min(nearest, (p0 + t * d - Vec2(x, y)).norm());
    }
    return nearest - r;
}

TEST(PocketMaterial, PolygonStudFromARoundBlank) {
    auto stock = machine("stud_258.H");
    ASSERT_TRUE(stock->millStock());
    // Hexagon with inscribed circle D40, first corner at 30 degrees, corners R3, from a D60
    // cylinder, 8 deep: pi 30^2 less the hexagon (6 ri^2 tan 30) less six corner rests
    // r^2 (tan 30 - pi / 6).
    const double hexagon =
        6.0 * 400.0 * std::tan(kPi / 6.0) - 6.0 * 9.0 * (std::tan(kPi / 6.0) - kPi / 6.0);
    const double volume = (kPi * 900.0 - hexagon) * 8.0;
    EXPECT_NEAR(stock->removedVolumeMm3(), volume, 0.01 * volume);
    const auto shape = [](double x, double y) {
        return roundedHexagon({0, 0}, 20.0, 30.0, 3.0, x, y);
    };
    // Cells of the blank outside the cylinder hold no material and are skipped by the blank.
    const HeightFieldStock& s = *stock->millStock();
    int kept = 0;
    int cut = 0;
    for (int j = 0; j < s.cellsY(); ++j) {
        for (int i = 0; i < s.cellsX(); ++i) {
            const double x = s.minCorner().x() + (i + 0.5) * s.cellMm();
            const double y = s.minCorner().y() + (j + 0.5) * s.cellMm();
            if (!s.hasMaterial(i, j) && std::hypot(x, y) > 29.0) continue;
            const double d = shape(x, y);
            if (d < -0.15) {
                ASSERT_NEAR(s.topAt(i, j), 0.0, 1e-6) << "stud cut at X" << x << " Y" << y;
                ++kept;
            } else if (d > 0.15 && std::hypot(x, y) < 29.85) {
                ASSERT_NEAR(s.topAt(i, j), -8.0, 0.01) << "material left at X" << x << " Y" << y;
                ++cut;
            }
        }
    }
    EXPECT_GT(kept, 1000);
    EXPECT_GT(cut, 1000);
}

}  // namespace
}  // namespace kerf
