// `kerf run --motion` on mill5 with the CAM-style 3+2 and 5-axis programs of examples/five_axis
// (docs/klartext.md, "Tilted working plane and rotary axes"): every joint within its soft limits
// and its velocity, acceleration and jerk limits (core/machine/presets/mill5.toml and mill.toml),
// and the tool tip on the part where it was worked out by hand at a few blocks.
//
// On mill5 the workpiece origin is the pivot, so a point w of the part is reached with the axes
// (the tip, relative to the origin) at T w, T = Ry(-B) Rz(-C): the tip on the part is
// Rz(C) Ry(B) axes.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

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

// X, Y, Z, B, C of a servo cycle or a trace move.
using Axes = std::array<double, 5>;
using Point = std::array<double, 3>;

Point tipOnThePart(const Axes& a) {
    const double b = a[3] * M_PI / 180.0, c = a[4] * M_PI / 180.0;
    const double x1 = std::cos(b) * a[0] + std::sin(b) * a[2];
    const double z1 = -std::sin(b) * a[0] + std::cos(b) * a[2];
    return {std::cos(c) * x1 - std::sin(c) * a[1], std::sin(c) * x1 + std::cos(c) * a[1], z1};
}

double distance(const Point& p, const Point& q) {
    return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

double toSegment(const Point& p, const Point& a, const Point& b) {
    double t = 0.0, len2 = 0.0;
    for (size_t i = 0; i < 3; ++i) {
        t += (b[i] - a[i]) * (p[i] - a[i]);
        len2 += (b[i] - a[i]) * (b[i] - a[i]);
    }
    t = len2 > 0.0 ? std::clamp(t / len2, 0.0, 1.0) : 0.0;
    const Point q{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    return distance(p, q);
}

void expectNear(const Point& actual, const Point& expected, const char* what) {
    for (size_t i = 0; i < 3; ++i)
        EXPECT_NEAR(actual[i], expected[i], 1e-3) << what << " coordinate " << i;
}

class FiveAxisExamples : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_five_axis_examples_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::copy(fs::path(KERF_SOURCE_DIR) / "examples/five_axis", dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    // kerf run --motion (on mill5) with the report, the trace and the servo cycles' samples.
    nlohmann::json run(const std::string& program, const std::string& machine = "mill5") {
        const std::string command =
            std::string("\"") + KERF_BINARY + "\" run --machine " + machine + " --tool-table \"" +
            (dir / "TOOL.T").string() + "\" --motion --samples \"" +
            (dir / "samples.csv").string() + "\" --trace \"" + (dir / "trace").string() +
            "\" --report \"" + (dir / "report.json").string() + "\" \"" +
            (dir / (program + ".H")).string() + "\" 2> \"" + (dir / "errors").string() + "\"";
        EXPECT_EQ(std::system(command.c_str()), 0) << readText(dir / "errors");
        EXPECT_EQ(readText(dir / "errors"), "");
        return nlohmann::json::parse(readText(dir / "report.json"));
    }

    std::vector<Axes> samples() const {
        std::istringstream csv(readText(dir / "samples.csv"));
        std::string line;
        std::getline(csv, line);
        EXPECT_EQ(line, "t_s,X,Y,Z,B,C,spindle_deg,path_velocity,move");
        std::vector<Axes> rows;
        while (std::getline(csv, line)) {
            double t = 0.0;
            Axes a{};
            if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &t, &a[0], &a[1], &a[2], &a[3],
                            &a[4]) == 6)
                rows.push_back(a);
        }
        return rows;
    }

    // Where the last move of block `block` ends, from the canonical trace.
    std::optional<Axes> endOfBlock(int block) const {
        std::istringstream trace(readText(dir / "trace"));
        const std::string tag = " N" + std::to_string(block) + " ";
        std::string line;
        std::optional<Axes> end;
        while (std::getline(trace, line)) {
            const size_t at = line.find(tag);
            if (at == std::string::npos) continue;
            Axes a{};
            if (std::sscanf(line.c_str() + at + tag.size(), "%*s X%lf Y%lf Z%lf B%lf C%lf", &a[0],
                            &a[1], &a[2], &a[3], &a[4]) == 5)
                end = a;
        }
        return end;
    }

    fs::path dir;
};

// mill5's limits: X, Y, Z 500 mm/s, 2000 mm/s^2, 10^6 mm/s^3; B 90 deg/s, 720 deg/s^2, C 180
// deg/s, 1440 deg/s^2, both 10^5 deg/s^3 (1 % for the servo cycle's sampling). Soft limits in
// the samples' coordinates (the tip relative to the origin at machine Z -400, tool length 60):
// X +-400, Y +-300, the spindle nose Z + 60 - 400 within -500 .. 50, B within +-110.
TEST_F(FiveAxisExamples, AllRunOnMill5WithinEveryJointLimit) {
    struct Limit {
        const char* axis;
        double velocity, acceleration, jerk;
    };
    const Limit limits[] = {{"X", 500, 2000, 1e6},
                            {"Y", 500, 2000, 1e6},
                            {"Z", 500, 2000, 1e6},
                            {"B", 90, 720, 1e5},
                            {"C", 180, 1440, 1e5}};
    for (const char* program : {"FACE32", "TCPM5X", "M128SIDES"}) {
        SCOPED_TRACE(program);
        const nlohmann::json report = run(program);
        ASSERT_TRUE(report["ok"].get<bool>());
        EXPECT_FALSE(report["motion"]["refused"].get<bool>());
        for (const Limit& limit : limits) {
            const nlohmann::json& axis = report["motion"]["axes"][limit.axis];
            EXPECT_LE(axis["max_velocity"].get<double>(), limit.velocity * 1.01) << limit.axis;
            EXPECT_LE(axis["max_accel"].get<double>(), limit.acceleration * 1.01) << limit.axis;
            EXPECT_LE(axis["max_jerk"].get<double>(), limit.jerk * 1.01) << limit.axis;
        }
        const std::vector<Axes> rows = samples();
        ASSERT_GT(rows.size(), 1000u);
        for (const Axes& a : rows) {
            ASSERT_LE(std::fabs(a[0]), 400.0);
            ASSERT_LE(std::fabs(a[1]), 300.0);
            ASSERT_GE(a[2] + 60.0 - 400.0, -500.0);
            ASSERT_LE(a[2] + 60.0 - 400.0, 50.0 + 1e-6);
            ASSERT_LE(std::fabs(a[3]), 110.0);
        }
    }
}

// The same programs on the swivel heads: mill5h (B head, C table) and mill5hh (C/B fork head),
// whose linear axes also make up for the head's pivot 200 mm above the nose. Their soft limits
// (X +-600; Y +-300 on mill5h, +-500 on mill5hh; the nose's Z within -750 .. 50; B +-110) and
// mill5's joint limits hold at every servo cycle.
TEST_F(FiveAxisExamples, AllRunOnTheSwivelHeadMachinesWithinEveryJointLimit) {
    for (const auto& [machine, yLimit] :
         {std::pair{"mill5h", 300.0}, std::pair{"mill5hh", 500.0}}) {
        for (const char* program : {"FACE32", "TCPM5X", "M128SIDES"}) {
            SCOPED_TRACE(std::string(machine) + " " + program);
            const nlohmann::json report = run(program, machine);
            ASSERT_TRUE(report["ok"].get<bool>());
            EXPECT_FALSE(report["motion"]["refused"].get<bool>());
            for (const char* axis : {"X", "Y", "Z"}) {
                const nlohmann::json& a = report["motion"]["axes"][axis];
                EXPECT_LE(a["max_velocity"].get<double>(), 500.0 * 1.01) << axis;
                EXPECT_LE(a["max_accel"].get<double>(), 2000.0 * 1.01) << axis;
            }
            EXPECT_LE(report["motion"]["axes"]["B"]["max_velocity"].get<double>(), 90.0 * 1.01);
            EXPECT_LE(report["motion"]["axes"]["C"]["max_velocity"].get<double>(), 180.0 * 1.01);
            const std::vector<Axes> rows = samples();
            ASSERT_GT(rows.size(), 1000u);
            for (const Axes& a : rows) {
                ASSERT_LE(std::fabs(a[0]), 600.0);
                ASSERT_LE(std::fabs(a[1]), yLimit);
                ASSERT_GE(a[2] + 60.0 - 400.0, -750.0);
                ASSERT_LE(a[2] + 60.0 - 400.0, 50.0 + 1e-6);
                ASSERT_LE(std::fabs(a[3]), 110.0);
            }
        }
    }
}

// FACE32, 3+2. Frame 1: the datum shifted to X+20 on the top, SPB+30 tilts the tool to
// (sin 30, 0, cos 30); SEQ+ takes B+30, C0. The first hole's bottom (X0 Y0 Z-10 in the plane)
// lies on the part at (20, 0, 0) + Ry(30) (0, 0, -10) = (20 - 10 sin 30, 0, -10 cos 30) =
// (15, 0, -8.6603), the second (Y15) at (15, 15, -8.6603). MB MAX retracted to the nose's upper
// limit first: tip Z 50 + 400 - 60 = 390. Frame 2: the datum at X-20 Y+20, SPB+45 SPC+90 puts
// the tool along Rz(90) Ry(45) Z = (0, 0.7071, 0.7071): B+45 C+90 (SEQ+), positioned by
// L B+Q121 C+Q122; the hole's bottom at (-20, 20, 0) + Rz(90) Ry(45) (0, 0, -10) =
// (-20, 20, 0) + Rz(90) (-7.0711, 0, -7.0711) = (-20, 12.9289, -7.0711). Frame 2's L Z+100 puts
// the tip at (-20, 20 + 70.7107, 70.7107); the axes there are Ry(-45) Rz(-90) of it: Rz(-90)
// gives (90.7107, 20, 70.7107), Ry(-45) ((90.7107 - 70.7107) cos 45, 20, (90.7107 + 70.7107)
// cos 45) = (14.1421, 20, 114.1421); PLANE RESET STAY and L B+0 C+0 leave them there: machine
// Z 114.1421 - 400. Each hole removes the tilted cylinder of radius 4 between the top and its
// flat bottom 10 down the axis: pi 4^2 10 = 502.65 mm^3 (the top cuts it obliquely through the
// axis, which changes nothing), 1507.96 for the three (the voxels within 1 %), and no rapid cuts:
// the set-up clearance Q200=5 keeps the tilted tool's lowest edge (4 sin 45 = 2.83 below its
// centre) above the top.
TEST_F(FiveAxisExamples, Face32DrillsWhereTheTiltedPlanesPutTheHoles) {
    const nlohmann::json report = run("FACE32");
    ASSERT_TRUE(report["ok"].get<bool>());
    const std::optional<Axes> retract = endOfBlock(15);
    ASSERT_TRUE(retract);
    EXPECT_NEAR((*retract)[2], 390.0, 1e-6);
    EXPECT_NEAR((*retract)[3], 30.0, 1e-6);
    EXPECT_NEAR((*retract)[4], 0.0, 1e-6);

    // The deepest point of each hole: the drilling cycle's lowest feed move of its block (the
    // lowest axis Z is the lowest along the tool, which stands along the axes' Z).
    auto bottom = [&](int block) {
        std::istringstream trace(readText(dir / "trace"));
        const std::string tag = " N" + std::to_string(block) + " LINE ";
        std::string line;
        Axes lowest{0, 0, 1e9, 0, 0};
        while (std::getline(trace, line)) {
            const size_t at = line.find(tag);
            Axes a{};
            if (at != std::string::npos &&
                std::sscanf(line.c_str() + at + tag.size(), "X%lf Y%lf Z%lf B%lf C%lf", &a[0],
                            &a[1], &a[2], &a[3], &a[4]) == 5 &&
                a[2] < lowest[2])
                lowest = a;
        }
        return lowest;
    };
    expectNear(tipOnThePart(bottom(17)), {15.0, 0.0, -8.6603}, "frame 1, hole 1");
    expectNear(tipOnThePart(bottom(18)), {15.0, 15.0, -8.6603}, "frame 1, hole 2");
    const std::optional<Axes> tables = endOfBlock(27);
    ASSERT_TRUE(tables);
    EXPECT_NEAR((*tables)[3], 45.0, 1e-6);
    EXPECT_NEAR((*tables)[4], 90.0, 1e-6);
    expectNear(tipOnThePart(bottom(29)), {-20.0, 12.9289, -7.0711}, "frame 2");
    const nlohmann::json& end = report["final_machine_position"];
    EXPECT_NEAR(end["X"].get<double>(), 14.1421, 1e-4);
    EXPECT_NEAR(end["Y"].get<double>(), 20.0, 1e-6);
    EXPECT_NEAR(end["Z"].get<double>(), 114.1421 - 400.0, 1e-4);
    EXPECT_NEAR(end["B"].get<double>(), 0.0, 1e-6);
    EXPECT_NEAR(end["C"].get<double>(), 0.0, 1e-6);

    const std::string stock =
        std::string("\"") + KERF_BINARY + "\" run --machine mill5 --tool-table \"" +
        (dir / "TOOL.T").string() + "\" --stock --report \"" + (dir / "stock.json").string() +
        "\" \"" + (dir / "FACE32.H").string() + "\" 2> \"" + (dir / "notes").string() + "\"";
    ASSERT_EQ(std::system(stock.c_str()), 0) << readText(dir / "notes");
    const nlohmann::json removed = nlohmann::json::parse(readText(dir / "stock.json"))["stock"];
    EXPECT_NEAR(removed["removed_volume_mm3"].get<double>(), 3 * M_PI * 16 * 10, 15.0);
    EXPECT_EQ(removed["rapid_cuts"].get<int>(), 0);
}

// TCPM5X, FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS: the tip runs along the front edge at
// Y-40 (Z-3) with the tool leaning outwards, B+45 C-90: (sin 45 cos -90, sin 45 sin -90, cos 45)
// = (0, -0.7071, 0.7071); round the corner to X+40 Y-30 while C turns to 0 (the tool leans
// along +X), and along the right edge to Y+30. The axes at the end of block 12, tip (30, -40, -3):
// Ry(-45) Rz(90) (30, -40, -3) = Ry(-45) (40, 30, -3) = (40 cos 45 + 3 sin 45, 30,
// 40 sin 45 - 3 cos 45) = (30.4056, 30, 26.1630); at the end of block 13, tip (40, -30, -3) with
// C0: Ry(-45) (40, -30, -3) = (30.4056, -30, 26.1630) - the same X and Z, Y turned over. Every
// servo cycle from (-30, -40, 20), where the rapid ends, until the lift lies on the plunge, the
// edges or the lift within the path
// tolerance (0.01 mm).
TEST_F(FiveAxisExamples, TcpmChamferKeepsTheTipOnTheEdges) {
    const nlohmann::json report = run("TCPM5X");
    ASSERT_TRUE(report["ok"].get<bool>());
    const std::optional<Axes> front = endOfBlock(12), corner = endOfBlock(13);
    ASSERT_TRUE(front && corner);
    const Axes frontAxes{30.4056, 30.0, 26.1630, 45.0, -90.0};
    const Axes cornerAxes{30.4056, -30.0, 26.1630, 45.0, 0.0};
    for (size_t i = 0; i < 5; ++i) {
        EXPECT_NEAR((*front)[i], frontAxes[i], 1e-4) << i;
        EXPECT_NEAR((*corner)[i], cornerAxes[i], 1e-4) << i;
    }
    // The path from the end of the TCPM rapid on: the plunge, the edges and the lift (its blended
    // corners stay within the tolerance of the lines they join).
    const Point path[] = {{-30, -40, 20}, {-30, -40, -3}, {30, -40, -3},
                          {40, -30, -3},  {40, 30, -3},   {40, 30, 50}};
    bool reached = false, down = false;
    double worst = 0.0, highestC = -1e9;
    int rows = 0;
    for (const Axes& a : samples()) {
        const Point tip = tipOnThePart(a);
        if (!reached) {
            reached = distance(tip, path[0]) < 1e-6;
            continue;
        }
        down = down || tip[2] < -3.0 + 1e-3;
        if (down && tip[2] > 0.0) break;  // lifted: the feed moves are behind
        double d = 1e9;
        for (size_t i = 0; i + 1 < std::size(path); ++i)
            d = std::min(d, toSegment(tip, path[i], path[i + 1]));
        worst = std::max(worst, d);
        highestC = std::max(highestC, a[4]);
        ++rows;
    }
    EXPECT_TRUE(reached);
    EXPECT_GT(rows, 1000);
    EXPECT_LE(worst, 0.01);
    EXPECT_NEAR(highestC, 0.0, 1e-6);
}

// M128SIDES, M128 with B+90: the tool lies along the part's +X, Rz(C) Ry(90) Z = (cos C, sin C, 0),
// square to the side the table turns to it. Block 11 ends with the tip 0.5 in front of the +X
// side, (39.5, -30, -10): axes Ry(-90) (39.5, -30, -10) = (10, -30, 39.5); block 15 with C+90
// in front of the +Y side, (0, 39.5, -10): Rz(-90) gives (39.5, 0, -10), so the axes are
// (10, 0, 39.5) again; block 16 at (-30, 39.5, -10): (10, 30, 39.5). Every side is milled at the
// same place of the machine. C indexes 0, 90, 180, 270 and with M126 (modal from block 7) from
// 270 to 0 the short way, +90: it never turns back and ends at machine 360.
TEST_F(FiveAxisExamples, M128SidesFaceEverySideAndIndexTheShortWay) {
    const nlohmann::json report = run("M128SIDES");
    ASSERT_TRUE(report["ok"].get<bool>());
    struct Expected {
        int block;
        Axes axes;
        Point tip;
    };
    const Expected expected[] = {{11, {10, -30, 39.5, 90, 0}, {39.5, -30, -10}},
                                 {15, {10, 0, 39.5, 90, 90}, {0, 39.5, -10}},
                                 {16, {10, 30, 39.5, 90, 90}, {-30, 39.5, -10}}};
    for (const Expected& e : expected) {
        const std::optional<Axes> end = endOfBlock(e.block);
        ASSERT_TRUE(end) << e.block;
        for (size_t i = 0; i < 5; ++i)
            EXPECT_NEAR((*end)[i], e.axes[i], 1e-4) << "block " << e.block << " axis " << i;
        expectNear(tipOnThePart(*end), e.tip, "tip");
    }
    double lastC = 0.0;
    for (const Axes& a : samples()) {
        ASSERT_GE(a[4], lastC - 1e-9);
        lastC = a[4];
    }
    EXPECT_NEAR(lastC, 360.0, 1e-6);
    EXPECT_NEAR(report["final_machine_position"]["C"].get<double>(), 360.0, 1e-6);
}

}  // namespace
