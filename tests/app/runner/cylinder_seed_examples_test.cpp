// The seed's chapter 8 examples (cycles 27 and 28, spec §7 as repaired there, the four seed
// examples with PLANE: the same two programs in seed 000 and 001) as written, on mill5, in
// examples/cylinder_surface: the tables after PLANE ... TURN, and the contour the cycles mill,
// unrolled from the canonical trace, against the figures' dimensions worked out by hand.
//
// On mill5 with B+90 the C table's axis lies along machine -X and the tool along Z: a point of
// the development (u round the circumference, v along the cylinder's axis) is milled with
// C = u / 25 rad (cycle 28 turns the table to the centre line and moves the rest of u sideways
// along +Y) and X = -v. So u = 25 C + Y and v = -X unroll every point of the trace.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& file) {
    std::stringstream text;
    text << std::ifstream(file, std::ios::binary).rdbuf();
    return text.str();
}

// The feed moves at one height, unrolled.
struct Pass {
    double length = 0.0;
    double uMin = 1e9, uMax = -1e9, vMin = 1e9, vMax = -1e9;
};

class CylinderSeedExamples : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_cylinder_seed_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::copy(fs::path(KERF_SOURCE_DIR) / "examples/cylinder_surface", dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    // kerf run on mill5; the trace's lines.
    std::string trace(const std::string& program) {
        const std::string command =
            std::string("\"") + KERF_BINARY + "\" run --machine mill5 --tool-table \"" +
            (dir / "TOOL.T").string() + "\" --trace \"" + (dir / "trace").string() + "\" \"" +
            (dir / program).string() + "\" 2> \"" + (dir / "errors").string() + "\"";
        EXPECT_EQ(std::system(command.c_str()), 0) << readText(dir / "errors");
        EXPECT_EQ(readText(dir / "errors"), "");
        return readText(dir / "trace");
    }

    // X Y Z B C where block `block` ends.
    static std::array<double, 5> endOfBlock(const std::string& text, int block) {
        std::istringstream lines(text);
        const std::string tag = " N" + std::to_string(block) + " ";
        std::string line;
        std::array<double, 5> end{1e9, 1e9, 1e9, 1e9, 1e9};
        while (std::getline(lines, line)) {
            const size_t at = line.find(tag);
            std::array<double, 5> a{};
            if (at != std::string::npos &&
                std::sscanf(line.c_str() + at + tag.size(), "%*s X%lf Y%lf Z%lf B%lf C%lf", &a[0],
                            &a[1], &a[2], &a[3], &a[4]) == 5)
                end = a;
        }
        return end;
    }

    // Every feed move that stays at one height, unrolled, summed per height.
    static std::map<double, Pass> unrolledPasses(const std::string& text) {
        std::istringstream lines(text);
        std::string line;
        std::map<double, Pass> passes;
        double x0 = 0, y0 = 0, z0 = 1e9, c0 = 0;
        while (std::getline(lines, line)) {
            double x, y, z, b, c;
            const size_t rapid = line.find(" RAPID "), feed = line.find(" LINE ");
            const size_t at = rapid != std::string::npos ? rapid : feed;
            if (at == std::string::npos ||
                std::sscanf(line.c_str() + at, " %*s X%lf Y%lf Z%lf B%lf C%lf", &x, &y, &z, &b,
                            &c) != 5)
                continue;
            if (feed != std::string::npos && std::fabs(z - z0) < 1e-9) {
                const double u0 = 25.0 * c0 * M_PI / 180.0 + y0, u1 = 25.0 * c * M_PI / 180.0 + y;
                Pass& pass = passes[std::round(z * 1000.0) / 1000.0];
                pass.length += std::hypot(u1 - u0, x - x0);
                for (const auto& [u, v] : {std::pair{u0, -x0}, std::pair{u1, -x}}) {
                    pass.uMin = std::min(pass.uMin, u);
                    pass.uMax = std::max(pass.uMax, u);
                    pass.vMin = std::min(pass.vMin, v);
                    pass.vMax = std::max(pass.vMax, v);
                }
            }
            x0 = x, y0 = y, z0 = z, c0 = c;
        }
        return passes;
    }

    fs::path dir;
};

// C27: PLANE SPATIAL SPB+90 TURN MBMAX retracts the tool to the nose's upper limit (tip Z
// 50 + 400 - 60 = 390) and turns B to +90 with C at 0 (B-90 C+180 tilts the tool the same way
// but turns C half a turn further). The figure: the contour X30..50 (20 mm round the
// circumference, Q17=1) by Y20..60 with corners R7.5, milled RL inside it with the D7 tool: the
// tool's centre runs round u 33.5..46.5 by v 23.5..56.5 with corners 7.5 - 3.5 = 4, so each pass
// is 2 (13 + 33) - 8 x 4 + 2 pi 4 = 85.1327 mm long on the development (the trace's chords of
// the corners are within 0.001 mm of them: 0.003 mm shorter at most). Depths 4 and 7: floors
// 25 - 4 = 21 and 25 - 7 = 18.
TEST_F(CylinderSeedExamples, Cycle27MillsTheFiguresRoundedRectangleOnEachPass) {
    const std::string text = trace("C27.H");
    const auto tilted = endOfBlock(text, 4);
    EXPECT_NEAR(tilted[2], 390.0, 1e-6);
    EXPECT_NEAR(tilted[3], 90.0, 1e-6);
    EXPECT_NEAR(tilted[4], 0.0, 1e-6);
    const std::map<double, Pass> passes = unrolledPasses(text);
    ASSERT_EQ(passes.size(), 2u);
    for (const double floor : {21.0, 18.0}) {
        ASSERT_TRUE(passes.count(floor)) << floor;
        const Pass& pass = passes.at(floor);
        EXPECT_NEAR(pass.length, 2 * (13 + 33) - 8 * 4 + 2 * M_PI * 4, 0.003) << floor;
        EXPECT_NEAR(pass.uMin, 33.5, 1e-3);
        EXPECT_NEAR(pass.uMax, 46.5, 1e-3);
        EXPECT_NEAR(pass.vMin, 23.5, 1e-3);
        EXPECT_NEAR(pass.vMax, 56.5, 1e-3);
    }
    // No BLK FORM: the cycle's call defines the cylinder it mills, R25 along Z, over the contour's
    // v 20..60 widened by the corner arcs' radius 7.5 (their ends' reach, as for any arc), two
    // tool radii 7 and 10 mm: v -4.5 .. 84.5, after block 8's own L C+0, before the cycle's first
    // move.
    const size_t blank = text.find("N8 STOCK CYLINDER Z R25.0000 RI0.0000 L89.0000 DIST84.5000");
    ASSERT_NE(blank, std::string::npos) << text.substr(0, 2000);
    EXPECT_LT(blank, text.find("N8 RAPID X-23.5000"));  // the cycle's first move
    // PLANE RESET TURN turns the tables back without moving X, Y, Z.
    const auto reset = endOfBlock(text, 10);
    EXPECT_NEAR(reset[2], 250.0, 1e-6);
    EXPECT_NEAR(reset[3], 0.0, 1e-6);
    EXPECT_NEAR(reset[4], 0.0, 1e-6);
}

// C28: the slot 10 wide round the centre line (60, 0) -> (60, -35) -> (40, -52.5) -> (40, -70)
// (lengths 35, hypot(20, 17.5) = 26.5754 and 17.5; it turns by acos(17.5 / 26.5754) = 48.81 deg
// at each bend, right then left). The D7 tool's centre runs 1.5 beside it on both walls: on the
// inside of a bend a wall is 2 x 1.5 tan(48.81 / 2) = 1.3612 shorter, on the outside the
// transition arc adds 1.5 x 0.85197 = 1.2780; half circles of 1.5 round both ends, and the
// tangential approach and departure are half circles of 0.75. One pass:
// 2 (35 + 26.5754 + 17.5) - 2 x 1.3612 + 2 x 1.2780 + 2 pi 1.5 + 2 pi 0.75 = 172.1212 mm
// (the trace's chords of the arcs: up to 0.006 mm shorter). Floors 21 and 18; Q21 = 0.02 goes
// round once more at the full depth. The walls reach u 40 - 1.5 .. 60 + 1.5, v -70 - 1.5 .. 0
// + 1.5.
TEST_F(CylinderSeedExamples, Cycle28MillsBothWallsOfTheFiguresSlot) {
    const std::string text = trace("C28.H");
    const auto tilted = endOfBlock(text, 4);
    EXPECT_NEAR(tilted[2], 250.0, 1e-6);  // TURN without MB: no retract
    EXPECT_NEAR(tilted[3], 90.0, 1e-6);
    EXPECT_NEAR(tilted[4], 0.0, 1e-6);
    const double bend = std::acos(17.5 / std::hypot(20.0, 17.5));
    const double pass = 2 * (35 + std::hypot(20.0, 17.5) + 17.5) - 4 * 1.5 * std::tan(bend / 2) +
                        2 * 1.5 * bend + 2 * M_PI * 1.5 + 2 * M_PI * 0.75;
    EXPECT_NEAR(pass, 172.1212, 1e-4);
    const std::map<double, Pass> passes = unrolledPasses(text);
    ASSERT_EQ(passes.size(), 2u);
    ASSERT_TRUE(passes.count(21.0) && passes.count(18.0));
    EXPECT_NEAR(passes.at(21.0).length, pass, 0.006);
    EXPECT_NEAR(passes.at(18.0).length, 2 * pass, 0.012);
    for (const auto& [floor, p] : passes) {
        EXPECT_NEAR(p.uMin, 38.5, 1e-3) << floor;
        EXPECT_NEAR(p.uMax, 61.5, 1e-3) << floor;
        EXPECT_NEAR(p.vMin, -71.5, 1e-3) << floor;
        EXPECT_NEAR(p.vMax, 1.5, 1e-3) << floor;
    }
}

// Both programs on mill5h, the B head and C table they were written for, through planner and
// servo cycle. Block 9's L Z+250 in the plane tilted to B+90 puts the tip 250 mm from the C axis
// along +X with the tool lying along +X, so the axes stand the head pivot (200) and the tool
// (60) further out: X = 510, inside mill5h's travel of +-600 (mill's +-400 refused it). PLANE
// RESET TURN then turns the head back without moving X: the run ends at machine X 510, B 0.
TEST_F(CylinderSeedExamples, BothRunWithMotionOnTheSwivelHeadMachine) {
    for (const std::string program : {"C27.H", "C28.H"}) {
        const fs::path report = dir / "report.json";
        const std::string command =
            std::string("\"") + KERF_BINARY + "\" run --machine mill5h --motion --tool-table \"" +
            (dir / "TOOL.T").string() + "\" --report \"" + report.string() + "\" \"" +
            (dir / program).string() + "\" 2> \"" + (dir / "errors").string() + "\"";
        EXPECT_EQ(std::system(command.c_str()), 0) << program << readText(dir / "errors");
        const nlohmann::json r = nlohmann::json::parse(readText(report));
        ASSERT_TRUE(r["ok"].get<bool>()) << program;
        EXPECT_NEAR(r["feed_bounds"]["max"]["X"].get<double>(), 25.0 + 2.0 + 200.0 + 60.0, 1e-6)
            << program;  // clearance Q6 = 2 above the surface
        EXPECT_NEAR(r["final_machine_position"]["X"].get<double>(), 250.0 + 200.0 + 60.0, 1e-6)
            << program;
        EXPECT_NEAR(r["final_machine_position"]["B"].get<double>(), 0.0, 1e-9) << program;
        EXPECT_FALSE(r["motion"]["refused"].get<bool>()) << program;
    }
}

}  // namespace
