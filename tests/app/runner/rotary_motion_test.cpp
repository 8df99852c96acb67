// `kerf run --motion` on mill5 with rotary moves: the B and C joints keep their limits in deg/s,
// deg/s^2 and deg/s^3 (core/machine/presets/mill5.toml), the machine ends where the golden case
// computed by hand (tests/golden/klartext/plane_spatial_stay_q121_mill5), and a rotary axis beyond
// its soft limit stops the program with the block named.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
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

class RotaryMotion : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_rotary_motion_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::copy(fs::path(KERF_SOURCE_DIR) / "tests/golden/klartext/plane_spatial_stay_q121_mill5",
                 dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    // kerf run on mill5; the exit code and the report.
    int run(const std::string& program, nlohmann::json& report,
            const std::string& machine = "mill5") {
        const std::string command = std::string("\"") + KERF_BINARY + "\" run --machine " +
                                    machine + " --tool-table \"" + (dir / "TOOL.T").string() +
                                    "\" --motion \"" + (dir / program).string() + "\" --report \"" +
                                    (dir / "report.json").string() + "\" 2> \"" +
                                    (dir / "errors").string() + "\"";
        const int status = std::system(command.c_str());
        report = nlohmann::json::parse(readText(dir / "report.json"));
        return status;
    }

    fs::path dir;
};

TEST_F(RotaryMotion, RotaryJointsKeepTheirLimits) {
    nlohmann::json report;
    ASSERT_EQ(run("program.H", report), 0) << readText(dir / "errors");
    ASSERT_TRUE(report["ok"].get<bool>());
    const nlohmann::json& axes = report["motion"]["axes"];
    // Both tables turn 90 deg at rapid: B reaches its 90 deg/s, C (180 deg/s) is held to B's
    // time; neither goes beyond its limits (1 % for the servo cycle's sampling).
    EXPECT_NEAR(axes["B"]["max_velocity"].get<double>(), 90.0, 0.9);
    EXPECT_LE(axes["B"]["max_accel"].get<double>(), 720.0 * 1.01);
    EXPECT_LE(axes["B"]["max_jerk"].get<double>(), 100000.0 * 1.01);
    EXPECT_GT(axes["C"]["max_velocity"].get<double>(), 0.0);
    EXPECT_LE(axes["C"]["max_velocity"].get<double>(), 180.0 * 1.01);
    EXPECT_LE(axes["C"]["max_accel"].get<double>(), 1440.0 * 1.01);
    const nlohmann::json& end = report["motion"]["final_position"];
    EXPECT_NEAR(end["X"].get<double>(), -5.0, 1e-3);
    EXPECT_NEAR(end["Y"].get<double>(), 30.0, 1e-3);
    EXPECT_NEAR(end["Z"].get<double>(), 100.0, 1e-3);
    EXPECT_NEAR(end["B"].get<double>(), 0.0, 1e-3);
    EXPECT_NEAR(end["C"].get<double>(), 0.0, 1e-3);
    EXPECT_NEAR(report["final_machine_position"]["Z"].get<double>(), -300.0, 1e-6);
}

// Cylinder surface (tests/golden/klartext/cycle_27_cylinder_slot_mill4): F300 is the feed on the
// surface of radius 20, so the A table alone turns at 300 / 20 rad/min = 14.3239 deg/s.
TEST_F(RotaryMotion, CylinderSurfaceFeedIsTheSurfaceSpeed) {
    const fs::path golden = fs::path(KERF_SOURCE_DIR) / "tests/golden/klartext";
    fs::copy_file(golden / "cycle_27_cylinder_slot_mill4/program.H", dir / "C27.H");
    nlohmann::json report;
    ASSERT_EQ(run("C27.H", report, "mill4"), 0) << readText(dir / "errors");
    ASSERT_TRUE(report["ok"].get<bool>());
    EXPECT_FALSE(report["motion"]["refused"].get<bool>());
    const nlohmann::json& a = report["motion"]["axes"]["A"];
    EXPECT_NEAR(a["max_velocity"].get<double>(), 300.0 / 20.0 / 60.0 * 180.0 / M_PI, 0.15);
    EXPECT_LE(a["max_accel"].get<double>(), 1440.0 * 1.01);
    EXPECT_NEAR(report["motion"]["final_position"]["A"].get<double>(), 90.0, 1e-3);
}

// The seed's cycle 28 example on mill5 (B at +90, the slot milled with C, X and Y) stays within
// every joint's limits.
TEST_F(RotaryMotion, CylinderSlotOnTheTiltedTableKeepsTheJointLimits) {
    const fs::path golden = fs::path(KERF_SOURCE_DIR) / "tests/golden/klartext";
    fs::copy_file(golden / "cycle_28_seed_c28_mill5/program.H", dir / "C28.H");
    fs::copy_file(golden / "cycle_28_seed_c28_mill5/TOOL.T", dir / "TOOL.T",
                  fs::copy_options::overwrite_existing);
    nlohmann::json report;
    ASSERT_EQ(run("C28.H", report), 0) << readText(dir / "errors");
    ASSERT_TRUE(report["ok"].get<bool>());
    EXPECT_FALSE(report["motion"]["refused"].get<bool>());
    const nlohmann::json& axes = report["motion"]["axes"];
    EXPECT_LE(axes["B"]["max_velocity"].get<double>(), 90.0 * 1.01);
    EXPECT_LE(axes["C"]["max_velocity"].get<double>(), 180.0 * 1.01);
    EXPECT_LE(axes["C"]["max_accel"].get<double>(), 1440.0 * 1.01);
    EXPECT_LE(axes["X"]["max_velocity"].get<double>(), 500.0 * 1.01);
    EXPECT_NEAR(report["motion"]["final_position"]["C"].get<double>(), 0.0, 1e-3);
}

TEST_F(RotaryMotion, RotaryBeyondItsSoftLimitIsRefused) {
    std::ofstream(dir / "LIMIT.H") << "0 BEGIN PGM LIMIT MM\n1 L B+100 FMAX\n2 L B+115 FMAX\n"
                                      "3 END PGM LIMIT MM\n";
    nlohmann::json report;
    EXPECT_NE(run("LIMIT.H", report), 0);
    EXPECT_FALSE(report["ok"].get<bool>());
    EXPECT_NE(readText(dir / "errors")
                  .find("LIMIT.H:3:1: error: the move would take axis B to 115.000 deg (machine "
                        "coordinates), beyond its soft limit 110.000"),
              std::string::npos)
        << readText(dir / "errors");
}

// TCPM on mill5 (the workpiece origin at the pivot, tool 4): the tip stays at (r, 0, 50) on the
// part while the C table turns two full turns (C+720), so the axes, (r cos C, -r sin C, 50), run
// twice round a circle of radius r. Both ends stand at (r, 0, 50). With r = 250 the circle stays
// inside X +-400 and Y +-300 and Y reaches -250 (at C = 90); with r = 350 Y reaches -350 at
// C = 90, beyond its limit -300, and the program is refused at block 4 before anything moves.
// (The pieces used to be tested at their middles only, where a 720 degree turn brings the tip
// back onto the unmoved axes: one piece, X and Y standing while the tip circled the part.)
TEST_F(RotaryMotion, TcpmTableTurnBeyondAnAxisLimitInMidBlockIsRefused) {
    auto program = [](int r) {
        return "0 BEGIN PGM TURN MM\n1 TOOL CALL 4 Z S1000\n2 L X+" + std::to_string(r) +
               " Y+0 Z+50 R0 FMAX\n3 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
               "4 L C+720 F3000\n5 FUNCTION RESET TCPM\n6 END PGM TURN MM\n";
    };
    std::ofstream(dir / "INSIDE.H") << program(250);
    nlohmann::json report;
    ASSERT_EQ(run("INSIDE.H", report), 0) << readText(dir / "errors");
    EXPECT_NEAR(report["feed_bounds"]["min"]["Y"].get<double>(), -250.0, 0.005);
    EXPECT_NEAR(report["feed_bounds"]["max"]["Y"].get<double>(), 250.0, 0.005);
    EXPECT_NEAR(report["feed_bounds"]["min"]["X"].get<double>(), -250.0, 0.005);
    EXPECT_NEAR(report["final_position"]["C"].get<double>(), 720.0, 1e-6);
    std::ofstream(dir / "TURN.H") << program(350);
    EXPECT_NE(run("TURN.H", report), 0);
    EXPECT_FALSE(report["ok"].get<bool>());
    EXPECT_TRUE(report["motion"]["refused"].get<bool>());
    const std::string errors = readText(dir / "errors");
    EXPECT_NE(errors.find("TURN.H:5:1: error: Block 4: the move would take axis Y to -30"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find("beyond its soft limit -300.000"), std::string::npos) << errors;
}

// mill5h (B head, pivot 200 mm above the spindle nose), tool 1 of length 80: PLANE ... B+90 MOVE
// keeps the tip, so the axes make up for the head by (200 + 80)(+1, 0, -1): from X+300 the X axis
// goes to 580 (inside its +600), from X+350 to 630, which the soft limit refuses, naming the
// PLANE block (block 3, line 4), although the programmed X never leaves the work area.
TEST_F(RotaryMotion, HeadPivotBeyondTheXLimitIsRefused) {
    auto program = [](int x) {
        return "0 BEGIN PGM HEADLIM MM\n1 TOOL CALL 1 Z S1000\n2 L X+" + std::to_string(x) +
               " Y+0 Z+50 R0 FMAX\n3 PLANE SPATIAL SPA+0 SPB+90 SPC+0 MOVE FMAX SEQ+\n"
               "4 L Z+10 R0 F500\n5 PLANE RESET MOVE FMAX\n6 END PGM HEADLIM MM\n";
    };
    std::ofstream(dir / "INSIDE.H") << program(300);
    nlohmann::json report;
    ASSERT_EQ(run("INSIDE.H", report, "mill5h"), 0) << readText(dir / "errors");
    EXPECT_NEAR(report["feed_bounds"]["max"]["X"].get<double>(), 580.0, 1e-6);
    std::ofstream(dir / "HEADLIM.H") << program(350);
    EXPECT_NE(run("HEADLIM.H", report, "mill5h"), 0);
    EXPECT_FALSE(report["ok"].get<bool>());
    const std::string errors = readText(dir / "errors");
    EXPECT_NE(errors.find("HEADLIM.H:4:1: error: Block 3: the move would take axis X to 630.000 "
                          "(machine coordinates), beyond its soft limit 600.000"),
              std::string::npos)
        << errors;
}

}  // namespace

namespace {

// Distance from p to the segment a-b.
double toSegment(const double p[3], const double a[3], const double b[3]) {
    double ab[3], ap[3], t = 0.0, len2 = 0.0;
    for (int i = 0; i < 3; ++i) {
        ab[i] = b[i] - a[i];
        ap[i] = p[i] - a[i];
        t += ab[i] * ap[i];
        len2 += ab[i] * ab[i];
    }
    t = len2 > 0.0 ? std::clamp(t / len2, 0.0, 1.0) : 0.0;
    double d2 = 0.0;
    for (int i = 0; i < 3; ++i)
        d2 += (ap[i] - t * ab[i]) * (ap[i] - t * ab[i]);
    return std::sqrt(d2);
}

// TCPM on mill5 (origin at the pivot): the tip stays at (0, 0, 50) while B turns to 90, goes
// along X to (10, 0, 50) while B turns back, then stays while C turns 90. Every servo cycle's
// axes, turned back to the part (tip = Rz(C) Ry(B) axes), lie on the programmed path within the
// machine's path tolerance (0.01 mm).
TEST_F(RotaryMotion, TcpmKeepsTheTipOnTheProgrammedLine) {
    std::ofstream(dir / "TCPM.H") << "0 BEGIN PGM TCPM MM\n1 TOOL CALL 4 Z S1000\n"
                                     "2 L X+0 Y+0 Z+50 R0 FMAX\n"
                                     "3 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
                                     "4 L B+90 F3000\n5 L X+10 B+0 F1000\n6 L C+90 F3000\n"
                                     "7 FUNCTION RESET TCPM\n8 END PGM TCPM MM\n";
    const std::string samples = (dir / "samples.csv").string();
    const std::string command =
        std::string("\"") + KERF_BINARY + "\" run --machine mill5 --tool-table \"" +
        (dir / "TOOL.T").string() + "\" --motion --samples \"" + samples + "\" \"" +
        (dir / "TCPM.H").string() + "\" 2> \"" + (dir / "errors").string() + "\"";
    ASSERT_EQ(std::system(command.c_str()), 0) << readText(dir / "errors");
    std::istringstream csv(readText(samples));
    std::string line;
    std::getline(csv, line);
    ASSERT_EQ(line, "t_s,X,Y,Z,B,C,spindle_deg,path_velocity,move");
    // The start: the tip of the 60 mm tool below the untooled start point.
    const double origin[3] = {0, 0, -60}, above[3] = {0, 0, 50}, end[3] = {10, 0, 50};
    double worst = 0.0, lastB = 0.0, lastC = 0.0;
    int rows = 0;
    while (std::getline(csv, line)) {
        double v[6];
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3],
                              &v[4], &v[5]),
                  6);
        const double b = v[4] * M_PI / 180.0, c = v[5] * M_PI / 180.0;
        // Ry(B), then Rz(C).
        const double x1 = std::cos(b) * v[1] + std::sin(b) * v[3];
        const double z1 = -std::sin(b) * v[1] + std::cos(b) * v[3];
        const double tip[3] = {std::cos(c) * x1 - std::sin(c) * v[2],
                               std::sin(c) * x1 + std::cos(c) * v[2], z1};
        worst =
            std::max(worst, std::min(toSegment(tip, origin, above), toSegment(tip, above, end)));
        lastB = v[4];
        lastC = v[5];
        ++rows;
    }
    EXPECT_GT(rows, 1000);
    EXPECT_LE(worst, 0.01);
    EXPECT_NEAR(lastB, 0.0, 1e-6);
    EXPECT_NEAR(lastC, 90.0, 1e-6);
}

}  // namespace

namespace {

// TCPM on mill5h (B head, pivot 200 mm above the spindle nose; tool 1, L 80): the tip stays at
// (0, 0, 50) while the head turns to B+90, goes to (10, 0, 50) while it turns back, and stays while
// the C table turns 90. The part's tip of every servo cycle: take the head's offset
// (Ry(B) - I)(0, 0, 280) = (280 sin B, 0, 280 (cos B - 1)) off the axes, then turn back by the
// table, Rz(C). From the first cycle it reaches (0, 0, 50) on, it stays within the path tolerance.
TEST_F(RotaryMotion, TcpmOnTheSwivelHeadKeepsTheTipOnTheProgrammedLine) {
    std::ofstream(dir / "TCPMH.H") << "0 BEGIN PGM TCPMH MM\n1 TOOL CALL 1 Z S1000\n"
                                      "2 L X+0 Y+0 Z+50 R0 FMAX\n"
                                      "3 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
                                      "4 L B+90 F3000\n5 L X+10 B+0 F1000\n6 L C+90 F3000\n"
                                      "7 FUNCTION RESET TCPM\n8 END PGM TCPMH MM\n";
    const std::string samples = (dir / "samples.csv").string();
    const std::string command =
        std::string("\"") + KERF_BINARY + "\" run --machine mill5h --tool-table \"" +
        (dir / "TOOL.T").string() + "\" --motion --samples \"" + samples + "\" \"" +
        (dir / "TCPMH.H").string() + "\" 2> \"" + (dir / "errors").string() + "\"";
    ASSERT_EQ(std::system(command.c_str()), 0) << readText(dir / "errors");
    std::istringstream csv(readText(samples));
    std::string line;
    std::getline(csv, line);
    ASSERT_EQ(line, "t_s,X,Y,Z,B,C,spindle_deg,path_velocity,move");
    const double above[3] = {0, 0, 50}, end[3] = {10, 0, 50};
    const double h = 200.0 + 80.0;
    double worst = 0.0, maxB = 0.0;
    bool reached = false;
    int rows = 0;
    while (std::getline(csv, line)) {
        double v[6];
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3],
                              &v[4], &v[5]),
                  6);
        const double b = v[4] * M_PI / 180.0, c = v[5] * M_PI / 180.0;
        const double s[3] = {v[1] - h * std::sin(b), v[2], v[3] - h * (std::cos(b) - 1.0)};
        const double tip[3] = {std::cos(c) * s[0] - std::sin(c) * s[1],
                               std::sin(c) * s[0] + std::cos(c) * s[1], s[2]};
        if (!reached && toSegment(tip, above, above) < 1e-6) reached = true;
        if (reached) worst = std::max(worst, toSegment(tip, above, end));
        maxB = std::max(maxB, v[4]);
        ++rows;
    }
    EXPECT_TRUE(reached);
    EXPECT_GT(rows, 1000);
    EXPECT_NEAR(maxB, 90.0, 1e-6);
    EXPECT_LE(worst, 0.01);
}

}  // namespace

namespace {

// The motion samples of `program` on mill5 (tool 4: L 60, R 4), each turned back onto the part
// (origin at the pivot: tip = Rz(C) Ry(B) axes), and the last C.
std::vector<std::array<double, 3>> tipsOnThePart(const fs::path& dir, const std::string& name,
                                                 const std::string& program, double& lastC) {
    std::ofstream(dir / name) << program;
    const std::string samples = (dir / "samples.csv").string();
    const std::string command =
        std::string("\"") + KERF_BINARY + "\" run --machine mill5 --tool-table \"" +
        (dir / "TOOL.T").string() + "\" --motion --samples \"" + samples + "\" \"" +
        (dir / name).string() + "\" 2> \"" + (dir / "errors").string() + "\"";
    std::vector<std::array<double, 3>> tips;
    if (std::system(command.c_str()) != 0) {
        ADD_FAILURE() << readText(dir / "errors");
        return tips;
    }
    std::istringstream csv(readText(samples));
    std::string line;
    std::getline(csv, line);
    while (std::getline(csv, line)) {
        double v[6];
        if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4],
                        &v[5]) != 6)
            continue;
        const double b = v[4] * M_PI / 180.0, c = v[5] * M_PI / 180.0;
        const double x1 = std::cos(b) * v[1] + std::sin(b) * v[3];
        const double z1 = -std::sin(b) * v[1] + std::cos(b) * v[3];
        tips.push_back(
            {std::cos(c) * x1 - std::sin(c) * v[2], std::sin(c) * x1 + std::cos(c) * v[2], z1});
        lastC = v[5];
    }
    return tips;
}

// TCPM with a circle: from (20, 0, 50) a quarter circle about (10, 0) to (10, 10, 50) while the
// C table turns 90. Every servo cycle's tip on the part lies on the rapids (up to (0, 0, 50), then
// to (20, 0, 50)) or on the circle of radius 10 about (10, 0) at Z 50 within the path tolerance
// (0.01 mm).
TEST_F(RotaryMotion, TcpmArcKeepsTheTipOnTheProgrammedCircle) {
    double lastC = 0.0;
    const auto tips = tipsOnThePart(dir, "TCPMC.H",
                                    "0 BEGIN PGM TCPMC MM\n1 TOOL CALL 4 Z S1000\n"
                                    "2 L X+0 Y+0 Z+50 R0 FMAX\n3 L X+20 FMAX\n4 M128\n"
                                    "5 CC X+10 Y+0\n6 C X+10 Y+10 C+90 DR+ F1000\n7 M129\n"
                                    "8 END PGM TCPMC MM\n",
                                    lastC);
    // The 60 mm tool's tip starts below the untooled start point, as in the test above.
    const double origin[3] = {0, 0, -60}, above[3] = {0, 0, 50}, start[3] = {20, 0, 50};
    double worst = 0.0;
    int onArc = 0;
    for (const auto& t : tips) {
        double d = std::min(toSegment(t.data(), origin, above), toSegment(t.data(), above, start));
        if (t[0] >= 10.0 - 1e-6 && t[1] >= -1e-6) {
            const double arc = std::hypot(std::hypot(t[0] - 10.0, t[1]) - 10.0, t[2] - 50.0);
            if (arc < d) {
                d = arc;
                if (t[1] > 1.0) ++onArc;
            }
        }
        worst = std::max(worst, d);
    }
    EXPECT_GT(onArc, 100);
    EXPECT_LE(worst, 0.01);
    EXPECT_NEAR(lastC, 90.0, 1e-6);
}

// TCPM with radius compensation: RL along +X at Y 0 (tool R 4) puts the tool's centre at Y +4 on
// the part while the C table turns 90; every servo cycle whose tip lies between X -19 and 19 on
// the part (only the compensated line gets there) is on that line within the path tolerance.
TEST_F(RotaryMotion, TcpmRadiusCompensationOffsetsTheToolOnThePart) {
    double lastC = 0.0;
    const auto tips = tipsOnThePart(dir, "TCPMR.H",
                                    "0 BEGIN PGM TCPMR MM\n1 TOOL CALL 4 Z S1000\n"
                                    "2 L X-30 Y-10 Z+50 R0 FMAX\n3 M128\n"
                                    "4 L X-20 Y+0 RL F1000\n5 L X+20 C+90\n"
                                    "6 L X+30 Y+10 R0\n7 M129\n8 END PGM TCPMR MM\n",
                                    lastC);
    double worst = 0.0;
    int along = 0;
    for (const auto& t : tips) {
        if (t[0] < -19.0 || t[0] > 19.0 || t[2] < 49.0) continue;
        worst = std::max(worst, std::hypot(t[1] - 4.0, t[2] - 50.0));
        ++along;
    }
    EXPECT_GT(along, 100);
    EXPECT_LE(worst, 0.01);
    EXPECT_NEAR(lastC, 90.0, 1e-6);
}

}  // namespace

namespace {

// TCPM in a tilted plane on mill5 (tool 4, L 60): PLANE SPATIAL SPB+90 TURN turns B to 90; the
// program's (0, 0, 50) in the plane is Ry(90) (0, 0, 50) = (50, 0, 0) on the part, where the tip
// stays while B turns to 60; X+20 in the plane takes it along the part's -Z to (50, 0, -20) while
// B turns back to 90. From the first servo cycle whose tip (Rz(C) Ry(B) axes) reaches (50, 0, 0),
// every one lies on that line within the path tolerance (0.01 mm).
TEST_F(RotaryMotion, TcpmInTheTiltedPlaneKeepsTheTipOnTheProgrammedLine) {
    double lastC = 0.0;
    const auto tips = tipsOnThePart(dir, "TCPMT.H",
                                    "0 BEGIN PGM TCPMT MM\n1 TOOL CALL 4 Z S1000\n"
                                    "2 L X+0 Y+0 Z+100 R0 FMAX\n"
                                    "3 PLANE SPATIAL SPA+0 SPB+90 SPC+0 TURN FMAX SEQ+\n"
                                    "4 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
                                    "5 L X+0 Y+0 Z+50 FMAX\n6 L B+60 F3000\n"
                                    "7 L X+20 B+90 F1000\n8 FUNCTION RESET TCPM\n"
                                    "9 END PGM TCPMT MM\n",
                                    lastC);
    const double start[3] = {50, 0, 0}, end[3] = {50, 0, -20};
    bool reached = false;
    double worst = 0.0, lowest = 0.0;
    int rows = 0;
    for (const auto& t : tips) {
        if (!reached && toSegment(t.data(), start, start) < 1e-6) reached = true;
        if (!reached) continue;
        worst = std::max(worst, toSegment(t.data(), start, end));
        lowest = std::min(lowest, t[2]);
        ++rows;
    }
    EXPECT_TRUE(reached);
    EXPECT_GT(rows, 1000);
    EXPECT_LE(worst, 0.01);
    EXPECT_NEAR(lowest, -20.0, 1e-6);
    EXPECT_NEAR(lastC, 0.0, 1e-9);
}

}  // namespace

namespace {

// A program as a CAM post-processor writes it for a TNC (3+2 in PLANE SPATIAL SPB+30 TURN, then
// M128/FUNCTION TCPM in that plane with B and C moving, AXIS SPAT with PATHCTRL VECTOR and F CONT,
// LN with tool vectors) runs with --motion on mill5. From block 14 on (B beyond 34.9 deg, so not
// the 3+2 pass of the same rectangle) until block 17 has lifted the tool, the tip, turned back into
// the plane (Ry(-30) Rz(C) Ry(B) axes), lies on the rectangle's sides at Z -1 or on the plunge
// within the path tolerance: TCPM keeps the plane's coordinates whatever angles the tables take.
TEST_F(RotaryMotion, CamStyleFiveAxisProgramInTheTiltedPlaneKeepsTheTip) {
    std::ofstream(dir / "CAM5X.H")
        << "0 BEGIN PGM CAM5X MM\n1 TOOL CALL 4 Z S8000\n2 PLANE RESET STAY\n"
           "3 L B+0 C+0 R0 FMAX M126\n4 L X+0 Y+0 Z+100 R0 FMAX M3\n"
           "5 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN MB MAX FMAX SEQ+ TABLE ROT\n"
           "6 L X-20 Y-10 Z+20 R0 FMAX\n7 L Z-1 F300\n8 L X+20 F800\n9 L Y+10\n"
           "10 L Z+20 FMAX\n11 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
           "12 L X-20 Y-10 Z+5 B+Q121 C+Q122 FMAX\n13 L Z-1 F300\n"
           "14 L X+0 Y-10 Z-1 B+35 C+5 F800\n15 L X+20 Y-10 Z-1 B+40 C+10\n"
           "16 L X+20 Y+10 Z-1 B+35 C+0\n17 L Z+30 FMAX\n18 FUNCTION RESET TCPM\n"
           "19 FUNCTION TCPM F CONT AXIS SPAT PATHCTRL VECTOR\n"
           "20 L X+0 Y+0 Z+10 A+0 B+0 C+0 FMAX\n21 L Z+0 F500\n22 L X+10 B+10\n"
           "23 L Z+30 FMAX\n24 FUNCTION RESET TCPM\n25 M128\n"
           "26 LN X+0 Y+0 Z+5 NX+0 NY+0 NZ+1 TX+0 TY+0 TZ+1 F500\n"
           "27 LN X+5 Y+0 Z+5 NX+0 NY+0 NZ+1 TX+0.1736482 TY+0 TZ+0.9848078\n"
           "28 L Z+30 FMAX\n29 M129\n30 PLANE RESET TURN MB MAX FMAX\n31 END PGM CAM5X MM\n";
    nlohmann::json report;
    ASSERT_EQ(run("CAM5X.H", report), 0) << readText(dir / "errors");
    EXPECT_TRUE(report["ok"].get<bool>());
    const std::string samples = (dir / "samples.csv").string();
    const std::string command =
        std::string("\"") + KERF_BINARY + "\" run --machine mill5 --tool-table \"" +
        (dir / "TOOL.T").string() + "\" --motion --samples \"" + samples + "\" \"" +
        (dir / "CAM5X.H").string() + "\" 2> \"" + (dir / "errors").string() + "\"";
    ASSERT_EQ(std::system(command.c_str()), 0) << readText(dir / "errors");
    const double corners[4][3] = {{-20, -10, -1}, {0, -10, -1}, {20, -10, -1}, {20, 10, -1}};
    const double plunge[3] = {-20, -10, 5}, lift[3] = {20, 10, 30};
    const double c30 = std::cos(M_PI / 6), s30 = std::sin(M_PI / 6);
    std::istringstream csv(readText(samples));
    std::string line;
    std::getline(csv, line);
    double worst = 0.0, highestB = 0.0;
    int rows = 0;
    bool lifted = false;  // the end of block 17: the AXIS SPAT and LN blocks turn B again
    while (!lifted && std::getline(csv, line)) {
        double v[6];
        if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4],
                        &v[5]) != 6)
            continue;
        if (v[4] < 34.9 && rows == 0) continue;
        const double b = v[4] * M_PI / 180.0, c = v[5] * M_PI / 180.0;
        const double x1 = std::cos(b) * v[1] + std::sin(b) * v[3];
        const double z1 = -std::sin(b) * v[1] + std::cos(b) * v[3];
        const double t[3] = {std::cos(c) * x1 - std::sin(c) * v[2],
                             std::sin(c) * x1 + std::cos(c) * v[2], z1};
        const double p[3] = {c30 * t[0] - s30 * t[2], t[1], s30 * t[0] + c30 * t[2]};
        double d = std::min(toSegment(p, plunge, corners[0]), toSegment(p, corners[3], lift));
        for (int i = 0; i < 3; ++i)
            d = std::min(d, toSegment(p, corners[i], corners[i + 1]));
        worst = std::max(worst, d);
        highestB = std::max(highestB, v[4]);
        lifted = p[2] > 30.0 - 1e-6;
        ++rows;
    }
    EXPECT_TRUE(lifted);
    EXPECT_GT(rows, 100);
    EXPECT_NEAR(highestB, 40.0, 1e-6);
    EXPECT_LE(worst, 0.01);
}

}  // namespace
