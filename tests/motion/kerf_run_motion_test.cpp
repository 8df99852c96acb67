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
    // 100 mm along X at F6000 (100 mm/s) on the built-in mill: A 2000 mm/s^2, J 50000 mm/s^3.
    // Ramp: 2000 / 50000 = 0.04 s gives 40 mm/s, so 0.01 s at 2000 mm/s^2 adds the last 20:
    // 0.09 s and 4.5 mm to reach 100 mm/s, the same to stop, 91 mm at 100 mm/s: 1.09 s.
    const double bound = sCurveTime(100.0, 100.0, 2000.0, 50000.0);
    EXPECT_NEAR(bound, 1.09, 1e-12);
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
    // acceleration and jerk at 90 % of the axis limits, and the setpoint filter adds 17 ms).
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
    EXPECT_LE(x["max_jerk"].get<double>(), 50000.0 * 1.01);
    EXPECT_EQ(motion["axes"]["Y"]["max_velocity"].get<double>(), 0.0);
    EXPECT_LE(motion["max_path_deviation_mm"].get<double>(), 1e-9);

    // The samples: a header and one row per servo cycle (1 ms), X rising to 100.
    std::ifstream csv(samples);
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "t_s,X,Y,Z,spindle_deg,path_velocity,move");
    size_t rows = 0;
    double lastX = 0.0;
    while (std::getline(csv, line)) {
        ++rows;
        const double sampleX = std::stod(line.substr(line.find(',') + 1));
        EXPECT_GE(sampleX, lastX - 1e-12);
        lastX = sampleX;
    }
    EXPECT_NEAR(static_cast<double>(rows), motion["duration_s"].get<double>() / 1e-3, 1.0);
    EXPECT_NEAR(lastX, 100.0, 1e-9);
}

TEST(KerfRunMotion, ASoftLimitRefusesTheProgramBeforeAnythingMoves) {
    // The mill's X ends at +400 mm: block 2 would reach 500. Block 1 is fine but must not move.
    const fs::path program = writeProgram("limit.H",
                                          "0 BEGIN PGM LIMIT MM\n"
                                          "1 L X+100 R0 F6000\n"
                                          "2 L X+500 R0 F6000\n"
                                          "3 END PGM LIMIT MM\n");
    KerfRun run = runKerf(program, "");
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
    std::ifstream csv(samples);
    std::string line;
    std::getline(csv, line);
    ASSERT_EQ(line, "t_s,X,Z,spindle_deg,path_velocity,move");
    std::vector<std::pair<double, double>> thread;  // Z and spindle angle on the thread
    while (std::getline(csv, line)) {
        double t = 0.0, x = 0.0, z = 0.0, angle = 0.0;
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &t, &x, &z, &angle), 4);
        if (std::fabs(x - 20.0) < 1e-9 && z < 10.0 - 1e-6 && z > -30.0 + 1e-6)
            thread.emplace_back(z, angle);
    }
    ASSERT_GT(thread.size(), 1000u);  // 40 mm at 1000 mm/min: about 2.4 s
    const double start = thread.front().second - (10.0 - thread.front().first) / 2.0 * 360.0;
    EXPECT_NEAR(std::remainder(start, 360.0), 0.0, 1e-4);
    for (const auto& [z, angle] : thread)
        EXPECT_NEAR(angle, start + (10.0 - z) / 2.0 * 360.0, 1e-4) << "Z " << z;
    const nlohmann::json& motion = run.report["motion"];
    EXPECT_NEAR(motion["final_position"]["Z"].get<double>(), 20.0, 1e-6);
}

}  // namespace
