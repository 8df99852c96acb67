// `kerf run --motion` on mill5 with rotary moves: the B and C joints keep their limits in deg/s,
// deg/s^2 and deg/s^3 (core/machine/presets/mill5.toml), the machine ends where the golden case
// computed by hand (tests/golden/klartext/plane_spatial_stay_q121_mill5), and a rotary axis beyond
// its soft limit stops the program with the block named.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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
    int run(const std::string& program, nlohmann::json& report) {
        const std::string command =
            std::string("\"") + KERF_BINARY + "\" run --machine mill5 --tool-table \"" +
            (dir / "TOOL.T").string() + "\" --motion \"" + (dir / program).string() +
            "\" --report \"" + (dir / "report.json").string() + "\" 2> \"" +
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

}  // namespace
