#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

// `kerf run --motion` end to end: small programs whose motion is computed by hand here.
namespace {

namespace fs = std::filesystem;

fs::path outputDir() {
    const fs::path dir =
        fs::temp_directory_path() / ("kerf_motion_run_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

fs::path writeProgram(const std::string& name, const std::string& text) {
    const fs::path file = outputDir() / name;
    std::ofstream(file) << text;
    return file;
}

struct KerfRun {
    int exitCode = -1;
    nlohmann::json report;
    std::string errors;
};

KerfRun runKerf(const fs::path& program, const std::string& arguments) {
    const fs::path report = program.string() + ".json";
    const fs::path errors = program.string() + ".err";
    fs::remove(report);
    const std::string command = std::string("\"") + KERF_BINARY + "\" run \"" + program.string() +
                                "\" --motion --report \"" + report.string() + "\" " + arguments +
                                " 2> \"" + errors.string() + "\"";
    const int status = std::system(command.c_str());
    KerfRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(report);
    if (in) run.report = nlohmann::json::parse(in, nullptr, false);
    std::stringstream text;
    text << std::ifstream(errors).rdbuf();
    run.errors = text.str();
    return run;
}

// The --samples file: its header and one row of numbers per servo cycle, read by column name.
struct Samples {
    std::string header;
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;

    size_t column(const std::string& name) const {
        const auto it = std::find(columns.begin(), columns.end(), name);
        EXPECT_NE(it, columns.end()) << "no column " << name << " in " << header;
        return static_cast<size_t>(it - columns.begin());
    }
};

Samples readSamples(const fs::path& file) {
    Samples samples;
    std::ifstream csv(file);
    std::string line;
    if (!std::getline(csv, samples.header)) return samples;
    std::stringstream names(samples.header);
    for (std::string name; std::getline(names, name, ',');)
        samples.columns.push_back(name);
    while (std::getline(csv, line)) {
        std::vector<double> row;
        std::stringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');)
            row.push_back(std::stod(cell));
        EXPECT_EQ(row.size(), samples.columns.size()) << line;
        samples.rows.push_back(std::move(row));
    }
    return samples;
}

// Rest-to-rest time of a straight move of `length` at velocity `v` with acceleration `a` and
// jerk `j` (time-optimal S-curve): no planner can be faster within these limits.
double sCurveTime(double length, double v, double a, double j) {
    // Reaching v: with a constant-acceleration phase when v > a^2 / j.
    const double peak = std::min(a, std::sqrt(v * j));
    const double accelTime = peak / j + v / peak;  // 2 peak / j + (v - peak^2 / j) / peak
    const double accelLength = v / 2.0 * accelTime;
    EXPECT_LT(2.0 * accelLength, length) << "the moves below reach their feed";
    return 2.0 * accelTime + (length - 2.0 * accelLength) / v;
}

TEST(KerfRunMotion, OneLineOnTheMillTakesTheJerkLimitedTime) {
    // 100 mm along X at F6000 (100 mm/s) on the built-in mill: A 2000 mm/s^2, J 10^6 mm/s^3.
    // Ramp: 2000 / 10^6 = 2 ms gives 2 mm/s, so 0.048 s at 2000 mm/s^2 adds 96, the last ramp
    // the last 2: 0.052 s and 2.6 mm to reach 100 mm/s, the same to stop, 94.8 mm at 100 mm/s:
    // 1.052 s.
    const double bound = sCurveTime(100.0, 100.0, 2000.0, 1000000.0);
    EXPECT_NEAR(bound, 1.052, 1e-12);
    const fs::path program = writeProgram("line.H",
                                          "0 BEGIN PGM LINE MM\n"
                                          "1 L X+100 R0 F6000\n"
                                          "2 END PGM LINE MM\n");
    const fs::path samples = outputDir() / "line.csv";
    KerfRun run = runKerf(program, "--samples \"" + samples.string() + "\"");
    ASSERT_EQ(run.exitCode, 0) << run.errors;
    const nlohmann::json& motion = run.report["motion"];
    ASSERT_TRUE(motion.is_object()) << run.report.dump(2);
    EXPECT_FALSE(motion["refused"].get<bool>());
    // Not faster than the bound; within 5 % of it (the planner plans the tangential
    // acceleration and jerk at 90 % of the axis limits, and the setpoint filter adds 6 ms).
    const double feedTime = motion["feed_time_s"].get<double>();
    EXPECT_GE(feedTime, bound);
    EXPECT_LE(feedTime, bound * 1.05);
    EXPECT_GE(motion["duration_s"].get<double>(), feedTime);
    EXPECT_NEAR(motion["final_position"]["X"].get<double>(), 100.0, 1e-6);
    EXPECT_EQ(motion["final_position"]["Y"].get<double>(), 0.0);
    EXPECT_EQ(motion["final_position"]["Z"].get<double>(), 0.0);
    const nlohmann::json& x = motion["axes"]["X"];
    EXPECT_NEAR(x["max_velocity"].get<double>(), 100.0, 1e-6);
    EXPECT_LE(x["max_accel"].get<double>(), 2000.0 * 1.01);
    EXPECT_LE(x["max_jerk"].get<double>(), 1000000.0 * 1.01);
    EXPECT_EQ(motion["axes"]["Y"]["max_velocity"].get<double>(), 0.0);
    EXPECT_LE(motion["max_path_deviation_mm"].get<double>(), 1e-9);

    // The samples: a header and one row per servo cycle (1 ms), X rising to 100.
    const Samples table = readSamples(samples);
    EXPECT_EQ(table.header, "t_s,X,Y,Z,spindle_deg,path_velocity,move");
    const size_t X = table.column("X");
    double lastX = 0.0;
    for (const auto& row : table.rows) {
        EXPECT_GE(row[X], lastX - 1e-12);
        lastX = row[X];
    }
    EXPECT_NEAR(static_cast<double>(table.rows.size()), motion["duration_s"].get<double>() / 1e-3,
                1.0);
    EXPECT_NEAR(lastX, 100.0, 1e-9);
}

TEST(KerfRunMotion, TheEmergencyStopButtonEndsTheRunWhereTheAxesStopped) {
    // X at 600 mm/min = 10 mm/s from X0: after 3 s about 30 mm (less the ramp, a few ms, and
    // the 6 ms setpoint filter); the drives stop from 10 mm/s within 10^2 / (2 * 5000) = 0.01 mm.
    const fs::path program = writeProgram("estop.H",
                                          "0 BEGIN PGM ESTOP MM\n"
                                          "1 L X+100 R0 F600\n"
                                          "2 L Y+50\n"
                                          "3 END PGM ESTOP MM\n");
    KerfRun run = runKerf(program, "--emergency-stop-at 3");
    EXPECT_EQ(run.exitCode, 1) << run.errors;
    EXPECT_FALSE(run.report["ok"].get<bool>());
    const double x = run.report["motion"]["final_position"]["X"].get<double>();
    EXPECT_GT(x, 29.8);
    EXPECT_LT(x, 30.01);
    EXPECT_EQ(run.report["motion"]["final_position"]["Y"].get<double>(), 0.0);
    // Named at the block that was running (file line 2), with the time after the start.
    EXPECT_NE(run.errors.find("estop.H:2:1: error: Emergency stop at 3.00"), std::string::npos)
        << run.errors;
    // Without --motion there is no machine whose button could be pressed.
    const std::string usage = std::string("\"") + KERF_BINARY + "\" run \"" + program.string() +
                              "\" --emergency-stop-at 1 2>/dev/null";
    const int status = std::system(usage.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2);
}

TEST(KerfRunMotion, ASoftLimitRefusesTheProgramBeforeAnythingMoves) {
    // The mill's X ends at +400 mm: block 2 would reach 500. Block 1 is fine but must not move.
    // --work-offset Z0 puts the workpiece origin at the machine origin (the mill's own preset is
    // Z-400), which the note then names as a likely cause.
    const fs::path program = writeProgram("limit.H",
                                          "0 BEGIN PGM LIMIT MM\n"
                                          "1 L X+100 R0 F6000\n"
                                          "2 L X+500 R0 F6000\n"
                                          "3 END PGM LIMIT MM\n");
    KerfRun run = runKerf(program, "--work-offset Z0");
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.errors.find("limit.H:3:"), std::string::npos) << run.errors;
    EXPECT_NE(run.errors.find("error: Block 2"), std::string::npos) << run.errors;
    EXPECT_NE(run.errors.find("soft limit"), std::string::npos) << run.errors;
    EXPECT_NE(run.errors.find("note: the workpiece origin is at the machine origin"),
              std::string::npos)
        << run.errors;
    const nlohmann::json& motion = run.report["motion"];
    ASSERT_TRUE(motion.is_object()) << run.report.dump(2);
    EXPECT_TRUE(motion["refused"].get<bool>());
    EXPECT_EQ(motion["final_position"]["X"].get<double>(), 0.0);
    EXPECT_EQ(motion["axes"]["X"]["max_velocity"].get<double>(), 0.0);
    EXPECT_FALSE(run.report["ok"].get<bool>());

    // With the workpiece origin at machine X -200, X+500 is machine X 300: inside, and it runs.
    KerfRun shifted = runKerf(program, "--work-offset X-200");
    EXPECT_EQ(shifted.exitCode, 0) << shifted.errors;
    EXPECT_EQ(shifted.errors.find("--work-offset"), std::string::npos) << shifted.errors;
    EXPECT_NEAR(shifted.report["motion"]["final_position"]["X"].get<double>(), 500.0, 1e-6);
}

TEST(KerfRunMotion, LatheTurningPassEndsExactlyWithinTheLimits) {
    // FAGOR on the built-in lathe (X in diameter; A 1500 mm/s^2, J 30000 mm/s^3): one turning
    // pass of 50 mm along Z at F3000 (50 mm/s). sqrt(50 * 30000) = 1224.7 < 1500: no constant
    // acceleration phase, 2 sqrt(50 / 30000) = 0.0816 s and 2.04 mm to reach 50 mm/s.
    const double bound = sCurveTime(50.0, 50.0, 1500.0, 30000.0);
    EXPECT_NEAR(bound, 1.0816497, 1e-6);
    const fs::path program = writeProgram("turn.pim",
                                          "N10 G90 G94 G00 X100 Z10\n"
                                          "N20 G01 Z-40 F3000\n"
                                          "N30 G00 X120\n"
                                          "N40 Z20\n"
                                          "N50 M30\n");
    KerfRun run = runKerf(program, "--machine lathe");
    ASSERT_EQ(run.exitCode, 0) << run.errors;
    const nlohmann::json& motion = run.report["motion"];
    ASSERT_TRUE(motion.is_object()) << run.report.dump(2);
    const double feedTime = motion["feed_time_s"].get<double>();
    EXPECT_GE(feedTime, bound);
    EXPECT_LE(feedTime, bound * 1.05);
    // X in diameter, like the report's final_position.
    EXPECT_NEAR(motion["final_position"]["X"].get<double>(), 120.0, 1e-6);
    EXPECT_NEAR(motion["final_position"]["Z"].get<double>(), 20.0, 1e-6);
    for (const char* axis : {"X", "Z"}) {
        const nlohmann::json& a = motion["axes"][axis];
        EXPECT_LE(a["max_velocity"].get<double>(), 300.0 * 1.01) << axis;
        EXPECT_LE(a["max_accel"].get<double>(), 1500.0 * 1.01) << axis;
        EXPECT_LE(a["max_jerk"].get<double>(), 30000.0 * 1.01) << axis;
    }
}

TEST(KerfRunMotion, FagorThreadKeepsTheLeadPerSpindleRevolution) {
    // G33 with a 2 mm lead from Z10 to Z-30 at diameter 40 (radius 20), spindle at 500 rpm:
    // on every sample of the thread the spindle has turned (10 - Z) / 2 revolutions since Z10,
    // starting at angle 0.
    const fs::path program = writeProgram("thread.pim",
                                          "N10 G90 G94 S500 M3\n"
                                          "N20 G00 X40 Z10\n"
                                          "N30 G33 Z-30 L2\n"
                                          "N40 G00 X60\n"
                                          "N50 Z20\n"
                                          "N60 M30\n");
    const fs::path samples = outputDir() / "thread.csv";
    KerfRun run = runKerf(program, "--machine lathe --samples \"" + samples.string() + "\"");
    ASSERT_EQ(run.exitCode, 0) << run.errors;
    const Samples table = readSamples(samples);
    ASSERT_EQ(table.header, "t_s,X,Z,spindle_deg,path_velocity,move");
    const size_t X = table.column("X"), Z = table.column("Z"), A = table.column("spindle_deg");
    std::vector<std::pair<double, double>> thread;  // Z and spindle angle on the thread
    for (const auto& row : table.rows) {
        if (std::fabs(row[X] - 20.0) < 1e-9 && row[Z] < 10.0 - 1e-6 && row[Z] > -30.0 + 1e-6)
            thread.emplace_back(row[Z], row[A]);
    }
    ASSERT_GT(thread.size(), 1000u);  // 40 mm at 1000 mm/min: about 2.4 s
    const double start = thread.front().second - (10.0 - thread.front().first) / 2.0 * 360.0;
    EXPECT_NEAR(std::remainder(start, 360.0), 0.0, 1e-4);
    for (const auto& [z, angle] : thread)
        EXPECT_NEAR(angle, start + (10.0 - z) / 2.0 * 360.0, 1e-4) << "Z " << z;
    const nlohmann::json& motion = run.report["motion"];
    EXPECT_NEAR(motion["final_position"]["Z"].get<double>(), 20.0, 1e-6);
}

TEST(KerfRunMotion, FagorG86PassesStayOnOneHelix) {
    // G86 with a 2 mm pitch from Z5 to Z-10 at radius 20, infeed angle A30, depths 0.3 and 0.6
    // (B-0.3) and the spring pass at 0.6 (L0): the second pass starts 0.6 tan 30 = 0.3464 mm
    // further along, the others 0.1732 mm. Every sample on every pass must lie on the helix that
    // passes Z5 at spindle angle 0: angle = 360 (5 - Z) / 2 (mod 360).
    const fs::path program = writeProgram("g86.pim",
                                          "N10 G90 G95 S500 M3\n"
                                          "N20 G00 X50 Z10\n"
                                          "N30 G86 X40 Z5 Q40 R-10 I0.6 B-0.3 D2 L0 C2 A30\n"
                                          "N40 M30\n");
    const fs::path samples = outputDir() / "g86.csv";
    KerfRun run = runKerf(program, "--machine lathe --samples \"" + samples.string() + "\"");
    ASSERT_EQ(run.exitCode, 0) << run.errors;
    const Samples table = readSamples(samples);
    ASSERT_EQ(table.header, "t_s,X,Z,spindle_deg,path_velocity,move");
    const size_t X = table.column("X"), Z = table.column("Z"), A = table.column("spindle_deg"),
                 V = table.column("path_velocity");
    size_t onThread = 0;
    for (const auto& row : table.rows) {
        const double x = row[X], z = row[Z], angle = row[A], velocity = row[V];
        // On a pass: at its depth, moving (at the start point the tool waits for the spindle
        // angle), past every pass's start point (Z 4.65 at the latest) and before the end.
        const bool atDepth = std::fabs(x - 19.7) < 1e-9 || std::fabs(x - 19.4) < 1e-9;
        if (!atDepth || velocity <= 0.0 || z > 4.6 || z < -10.0 + 1e-6) continue;
        ++onThread;
        EXPECT_NEAR(std::remainder(angle - 360.0 * (5.0 - z) / 2.0, 360.0), 0.0, 1e-3)
            << "X " << x << " Z " << z;
    }
    EXPECT_GT(onThread, 1000u);  // 3 passes of about 15 mm at 1000 mm/min
}

TEST(KerfRunMotion, TncTappingCyclesKeepTheSpindleLockedToZ) {
    // Cycle 207 (rigid tapping, pitch 1, from set-up clearance Z2 to Z-10 and back) at X10 and
    // cycle 18 (thread cutting, pitch 1, from Z2 to Z-10) at X30: on every sample of their
    // spindle-synchronised moves the spindle has turned (2 - Z) revolutions from its start angle
    // 0, down and (207) back up. The programmed moves, numbered as in the samples' move column:
    // 1 rapid to Z50, 2 rapid to Z2, 3 and 4 the tap down and up, 5 rapid to Z20, 6 rapid to X30
    // Z2, 7 the thread down, 8 rapid to Z50.
    const fs::path tools =
        fs::path(KERF_SOURCE_DIR) / "tests/golden/klartext/cycle_207_rigid_tapping/TOOL.T";
    const fs::path program = writeProgram("taps.H",
                                          "0 BEGIN PGM TAPS MM\n"
                                          "1 TOOL CALL 3 Z S1000\n"
                                          "2 L X+10 Y+20 Z+50 R0 FMAX M3\n"
                                          "3 CYCL DEF 207 RIGID TAPPING\n"
                                          "  Q200=2\n"
                                          "  Q201=-10\n"
                                          "  Q239=+1\n"
                                          "  Q203=+0\n"
                                          "  Q204=20\n"
                                          "4 CYCL CALL\n"
                                          "5 L X+30 Y+20 Z+2 R0 FMAX M3\n"
                                          "6 CYCL DEF 18.0 ROSCAGEM A LAMINA\n"
                                          "7 CYCL DEF 18.1 PROFUNDIDADE = -12\n"
                                          "8 CYCL DEF 18.2 PASSO = +1\n"
                                          "9 CYCL CALL\n"
                                          "10 L Z+50 R0 FMAX\n"
                                          "11 END PGM TAPS MM\n");
    const fs::path samples = outputDir() / "taps.csv";
    // The 70 mm tap needs room below the mill's Z +50 end: the workpiece origin at machine Z -300.
    KerfRun run =
        runKerf(program, "--tool-table \"" + tools.string() +
                             "\" --work-offset Z-300 --samples \"" + samples.string() + "\"");
    ASSERT_EQ(run.exitCode, 0) << run.errors;
    const Samples table = readSamples(samples);
    ASSERT_EQ(table.header, "t_s,X,Y,Z,spindle_deg,path_velocity,move");
    const size_t X = table.column("X"), Z = table.column("Z"), A = table.column("spindle_deg"),
                 M = table.column("move");
    std::vector<std::pair<double, double>> tapping, thread;  // Z and spindle angle
    for (const auto& row : table.rows) {
        const double x = row[X], z = row[Z], angle = row[A];
        const int move = static_cast<int>(row[M]);
        if (move == 3 || move == 4) {
            EXPECT_NEAR(x, 10.0, 1e-9);
            tapping.emplace_back(z, angle);
        }
        if (move == 7) {
            EXPECT_NEAR(x, 30.0, 1e-9);
            thread.emplace_back(z, angle);
        }
    }
    for (const auto* cut : {&tapping, &thread}) {
        ASSERT_GT(cut->size(), 100u);
        const double start = cut->front().second - (2.0 - cut->front().first) * 360.0;
        EXPECT_NEAR(std::remainder(start, 360.0), 0.0, 1e-4);
        double deepest = 0.0;
        for (const auto& [z, angle] : *cut) {
            EXPECT_NEAR(angle, start + (2.0 - z) * 360.0, 1e-4) << "Z " << z;
            deepest = std::min(deepest, z);
        }
        EXPECT_NEAR(deepest, -10.0, 1e-6);
    }
    // Rigid tapping comes back up locked, to the set-up clearance.
    EXPECT_NEAR(tapping.back().first, 2.0, 1e-6);
}

// A lathe whose workpiece origin is at machine Z -100, with a bar for the simulated probe: radius
// up to 30 mm, its face at machine Z -102.5, i.e. workpiece Z -2.5.
fs::path probingLathe() {
    const fs::path file = outputDir() / "probing_lathe.toml";
    std::ofstream(file) << "base = \"lathe\"\n"
                           "[axes.Z]\n"
                           "preset = -100.0\n"
                           "[simulation.probe]\n"
                           "enabled = true\n"
                           "x_max = 30.0\n"
                           "z_max = -102.5\n";
    return file;
}

TEST(KerfRunMotion, FagorG75TouchesTheFaceAndTheProgramGoesOnFromWhereTheAxesStopped) {
    // G75 from Z5 towards Z-10 at X diameter 20 touches the face at workpiece Z -2.5: the drives
    // latch the crossing inside the servo period (their positions move linearly within it), so
    // the latch is exact to rounding. The axes stop a little beyond it: the trigger is seen one
    // period later (1 ms at 100 mm/min = 0.0017 mm), the setpoint filter (17 ms, half of it
    // ahead at constant speed: 0.014 mm) and the jerk-limited stop from 1.67 mm/s
    // (v sqrt(v / J) = 0.013 mm at 90 % of 30000 mm/s^3): less than 0.05 mm in all.
    // G76 back up to Z5 ends where the probe leaves the face, at -2.5 again. X80 then starts
    // from where G76 stopped.
    const fs::path program = writeProgram("probe.pim",
                                          "N10 G90 G94 G00 X20 Z5\n"
                                          "N20 G75 Z-10 F100\n"
                                          "N30 G76 Z5 F100\n"
                                          "N40 G00 X80\n"
                                          "N50 Z20\n"
                                          "N60 M30\n");
    const fs::path samples = outputDir() / "probe.csv";
    KerfRun run = runKerf(program, "--machine \"" + probingLathe().string() + "\" --samples \"" +
                                       samples.string() + "\"");
    ASSERT_EQ(run.exitCode, 0) << run.errors;
    const nlohmann::json& motion = run.report["motion"];
    ASSERT_TRUE(motion.is_object()) << run.report.dump(2);
    const nlohmann::json& probes = motion["probes"];
    ASSERT_EQ(probes.size(), 2u) << motion.dump(2);
    for (const nlohmann::json& probe : probes) {
        EXPECT_TRUE(probe["triggered"].get<bool>());
        EXPECT_NEAR(probe["position"]["Z"].get<double>(), -2.5, 1e-6);
        EXPECT_NEAR(probe["position"]["X"].get<double>(), 20.0, 1e-6);
    }
    // The X move runs at one Z: where G76 stopped, just above the face (the planner starts it
    // from the drives' actual position, which is within 1e-6 mm of the setpoint at rest).
    const Samples table = readSamples(samples);
    ASSERT_EQ(table.header, "t_s,X,Z,spindle_deg,path_velocity,move");
    const size_t X = table.column("X"), Z = table.column("Z");
    double lowest = 1e9;
    std::vector<double> zDuringX;
    for (const auto& row : table.rows) {
        const double x = row[X], z = row[Z];
        lowest = std::min(lowest, z);
        // Up to X 30 (radius): the corner to Z20 is blended within the last few mm.
        if (x > 10.0 + 1e-6 && x < 30.0) zDuringX.push_back(z);
    }
    EXPECT_LT(lowest, -2.5);
    EXPECT_GT(lowest, -2.55);
    ASSERT_FALSE(zDuringX.empty());
    for (double z : zDuringX) {
        EXPECT_NEAR(z, zDuringX.front(), 1e-6);
        EXPECT_GT(z, -2.5);
        EXPECT_LT(z, -2.45);
    }
    EXPECT_NEAR(motion["final_position"]["X"].get<double>(), 80.0, 1e-6);
    EXPECT_NEAR(motion["final_position"]["Z"].get<double>(), 20.0, 1e-6);
    for (const char* axis : {"X", "Z"}) {
        EXPECT_LE(motion["axes"][axis]["max_accel"].get<double>(), 1500.0 * 1.01) << axis;
        EXPECT_LE(motion["axes"][axis]["max_jerk"].get<double>(), 30000.0 * 1.01) << axis;
    }
}

TEST(KerfRunMotion, FagorG75ThatNeverTouchesFailsNamingTheBlock) {
    // Z-1 ends 1.5 mm above the face: nothing touches, and PROBERR makes that an error.
    const fs::path program = writeProgram("miss.pim",
                                          "N10 G90 G94 G00 X20 Z5\n"
                                          "N20 G75 Z-1 F100\n"
                                          "N30 G00 X80\n"
                                          "N40 M30\n");
    KerfRun run = runKerf(program, "--machine \"" + probingLathe().string() + "\"");
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.errors.find("miss.pim:2:5: error: G75 reached its end point without the probe "
                              "touching"),
              std::string::npos)
        << run.errors;
    const nlohmann::json& motion = run.report["motion"];
    ASSERT_TRUE(motion.is_object()) << run.report.dump(2);
    ASSERT_EQ(motion["probes"].size(), 1u);
    EXPECT_FALSE(motion["probes"][0]["triggered"].get<bool>());
    // The axes stopped at the programmed end point; X80 never ran.
    EXPECT_NEAR(motion["final_position"]["Z"].get<double>(), -1.0, 1e-6);
    EXPECT_NEAR(motion["final_position"]["X"].get<double>(), 20.0, 1e-6);
}

TEST(KerfRunMotion, TheCycle200SeedRunsOnTheBuiltInMill) {
    // The seed's clearance L Z+250 with its 80 mm drill: machine Z = 250 + 80 + preset. With the
    // mill's preset Z-400 that is -70, inside -500 ... +50; at the machine origin it was 330.
    const fs::path seed =
        fs::path(KERF_SOURCE_DIR) / "tests/golden/klartext/cycle_200_drilling_m99";
    const fs::path dir = outputDir() / "c200";
    fs::create_directories(dir);
    for (const char* name : {"program.H", "TOOL.T"})
        fs::copy_file(seed / name, dir / name, fs::copy_options::overwrite_existing);
    KerfRun run = runKerf(dir / "program.H", "");
    ASSERT_EQ(run.exitCode, 0) << run.errors;
    const nlohmann::json& motion = run.report["motion"];
    ASSERT_TRUE(motion.is_object()) << run.report.dump(2);
    EXPECT_FALSE(motion["refused"].get<bool>());
    EXPECT_NEAR(motion["final_position"]["Z"].get<double>(), 250.0, 1e-6);
}

TEST(KerfRunMotion, TheMachinesPresetPlacesTheWorkpieceAndWorkOffsetOverridesIt) {
    // Z+100 is machine Z 100 with the preset at the machine origin: beyond the mill's +50.
    // With axes.Z.preset = -300 it is machine Z -200 and runs without --work-offset; M91 then
    // takes machine Z -10, which the program sees as workpiece Z 290. --work-offset Z0 puts
    // the origin back at the machine origin: refused again.
    const fs::path machine = outputDir() / "preset_mill.toml";
    std::ofstream(machine) << "base = \"mill\"\n[axes.Z]\npreset = -300.0\n";
    const fs::path program = writeProgram("preset.H",
                                          "0 BEGIN PGM PRESET MM\n"
                                          "1 L X+10 Z+100 R0 FMAX\n"
                                          "2 L Z-10 R0 FMAX M91\n"
                                          "3 END PGM PRESET MM\n");
    KerfRun run = runKerf(program, "--machine \"" + machine.string() + "\"");
    ASSERT_EQ(run.exitCode, 0) << run.errors;
    EXPECT_NEAR(run.report["final_position"]["Z"].get<double>(), 290.0, 1e-6);
    EXPECT_NEAR(run.report["motion"]["final_position"]["Z"].get<double>(), 290.0, 1e-6);
    KerfRun overridden =
        runKerf(program, "--machine \"" + machine.string() + "\" --work-offset Z0");
    EXPECT_EQ(overridden.exitCode, 1);
    EXPECT_NE(overridden.errors.find("soft limit"), std::string::npos) << overridden.errors;
}

}  // namespace
