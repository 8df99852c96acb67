// `kerf run` on examples/probing: the machine file misplaces the blank by 1.5 / -0.8 / -0.2 mm and
// 0.7 degrees; the probing cycles find it (docs/probing.md).
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

class ProbingExamples : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_probing_examples_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::copy(fs::path(KERF_SOURCE_DIR) / "examples/probing", dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    std::string read(const fs::path& file) {
        std::stringstream text;
        text << std::ifstream(file, std::ios::binary).rdbuf();
        return text.str();
    }
    // kerf run on the example with its machine file (`program` without an extension: .H); the
    // report as JSON.
    nlohmann::json run(const std::string& program, const std::string& options = "",
                       const std::string& machine = "machine.toml") {
        const fs::path report = dir / (program + ".json");
        const std::string command =
            std::string("\"") + KERF_BINARY + "\" run --machine \"" + (dir / machine).string() +
            "\" " + options + " \"" +
            (dir / (program.find('.') == std::string::npos ? program + ".H" : program)).string() +
            "\" --report \"" + report.string() + "\" 2> \"" + (dir / "errors").string() + "\"";
        EXPECT_EQ(std::system(command.c_str()), 0) << read(dir / "errors");
        EXPECT_EQ(read(dir / "errors"), "");
        return nlohmann::json::parse(read(report));
    }

    fs::path dir;
};

TEST_F(ProbingExamples, Stud413MovesToTheRealCentreAboveTheRealTop) {
    const nlohmann::json report = run("STUD413");
    EXPECT_TRUE(report["ok"].get<bool>());
    // L X+0 Y+0 Z+5 after the datum: the stud's real centre, 5 mm above its real top.
    EXPECT_NEAR(report["final_position"]["X"].get<double>(), 1.5, 1e-6);
    EXPECT_NEAR(report["final_position"]["Y"].get<double>(), -0.8, 1e-6);
    EXPECT_NEAR(report["final_position"]["Z"].get<double>(), 4.8, 1e-6);
}

TEST_F(ProbingExamples, SetupFindsTheCornerWritesThePresetAndTheLog) {
    for (const char* options : {"", "--motion"}) {
        const nlohmann::json report = run("SETUP", options);
        // After the basic rotation and the datums, X0 Y0 is the real corner, Z0 the real top.
        EXPECT_NEAR(report["final_position"]["X"].get<double>(), 1.5, 1e-6) << options;
        EXPECT_NEAR(report["final_position"]["Y"].get<double>(), -0.8, 1e-6) << options;
        EXPECT_NEAR(report["final_position"]["Z"].get<double>(), 9.8, 1e-6) << options;
    }
    // Preset row 0 in machine coordinates: the built-in mill's workpiece origin is at Z -400.
    const std::string presets = read(dir / "PRESET.PR");
    EXPECT_NE(presets.find("+1.50000      -0.80000      -400.2"), std::string::npos) << presets;
    const std::string log = read(dir / "TCHPR426.TXT");
    EXPECT_NE(log.find("  length                    +100.0000\n"), std::string::npos) << log;
    EXPECT_NE(log.find("  centre line               +50.0000\n"), std::string::npos) << log;
}

TEST_F(ProbingExamples, Intersection1416OfSeed004MakesTheRealCornerTheDatum) {
    // Q1120 = 1 and Q1121 = 1: the active preset moves to the measured corner and turns with the
    // edge. The ball touches the faces turned by 0.7 degrees axis-parallel, so each measured
    // line lies 2 (1 / cos 0.7deg - 1) = 0.15 um in front of its face: the corner is that close.
    const nlohmann::json report = run("INTERSECT");
    EXPECT_TRUE(report["ok"].get<bool>());
    EXPECT_NEAR(report["final_position"]["X"].get<double>(), 1.5, 0.0002);
    EXPECT_NEAR(report["final_position"]["Y"].get<double>(), -0.8, 0.0002);
    EXPECT_NEAR(report["final_position"]["Z"].get<double>(), 10.0, 1e-9);
}

TEST_F(ProbingExamples, Intersection1416InTheYzPlaneMakesTheTopFrontEdgeTheDatum) {
    // Q1139 = 1 at X 50: the top face (found at Z -0.2) and the front face, which the 0.7 degree
    // turn about the programmed origin puts at Y = 48.5 tan 0.7deg - 0.8 there; the ball stops
    // 2 (1 / cos 0.7deg - 1) in front of it. Q1120 = 1 makes that edge Y 0 Z 0; X keeps its
    // datum. L X+50 Y+0 Z+10 then stands 10 mm above the real edge.
    const double a = 0.7 * std::numbers::pi / 180.0;
    const double front = 48.5 * std::tan(a) - 0.8 - 2.0 * (1.0 / std::cos(a) - 1.0);
    for (const char* options : {"", "--motion"}) {
        const nlohmann::json report = run("EDGEYZ", options);
        EXPECT_TRUE(report["ok"].get<bool>()) << options;
        EXPECT_NEAR(report["final_position"]["X"].get<double>(), 50.0, 1e-6) << options;
        EXPECT_NEAR(report["final_position"]["Y"].get<double>(), front, 1e-6) << options;
        EXPECT_NEAR(report["final_position"]["Z"].get<double>(), 9.8, 1e-6) << options;
    }
}

TEST_F(ProbingExamples, Intersection1416TakesTheLeftFaceAsItsActualPosition) {
    // ACTUAL.H: Q1100 = +0@+1.5, the left face is known to lie at X 1.5 and is not probed; the
    // front face is, and meets X 1.5 at Y -0.8 less the ball's cosine error. Q1120 = 1 makes
    // that point X 0 Y 0.
    const double a = 0.7 * std::numbers::pi / 180.0;
    // ACTISO.I is the same in TNC ISO (G1416), whose parameters reach the same parser.
    for (const char* program : {"ACTUAL", "ACTISO.I"}) {
        const nlohmann::json report = run(program);
        EXPECT_TRUE(report["ok"].get<bool>()) << program;
        EXPECT_NEAR(report["final_position"]["X"].get<double>(), 1.5, 1e-6) << program;
        EXPECT_NEAR(report["final_position"]["Y"].get<double>(),
                    -0.8 - 2.0 * (1.0 / std::cos(a) - 1.0), 1e-6)
            << program;
    }
}

TEST_F(ProbingExamples, Extrusion1493FindsHowTheFrontFaceRunsAwayAlongTheEdge) {
    // EXTRUDE.H: 1493 repeats 1416's touches on the top-front edge (YZ plane at X 50) at X 70 and
    // X 90. The front face turned by 0.7 degrees lies 0.8 - (x - 1.5) tan a + e from nominal
    // along its normal (e: the ball's cosine error), largest at X 90: 0.8 - 88.5 tan a + e =
    // -0.281 (Q972), below QS401's -0.25, scrap (Q183 = 2). The program moves to X Q972, Z Q183.
    const double a = 0.7 * std::numbers::pi / 180.0;
    const double e = 2.0 * (1.0 / std::cos(a) - 1.0);
    for (const char* options : {"", "--motion"}) {
        const nlohmann::json report = run("EXTRUDE", options);
        EXPECT_TRUE(report["ok"].get<bool>()) << options;
        EXPECT_NEAR(report["final_position"]["X"].get<double>(), 0.8 - 88.5 * std::tan(a) + e, 1e-6)
            << options;
        EXPECT_NEAR(report["final_position"]["Z"].get<double>(), 2.0, 1e-9) << options;
    }
}

TEST_F(ProbingExamples, Datum417OnACylinderLyingOnTheATable) {
    // CYLX.H on mill4: BLK FORM CYLINDER X R25 (the A table's part), 417 over X 30 Y 0. The axis
    // really runs through (1.5, -0.8, -0.2) turned by 0.7 degrees about Z: at X 30 Y 0 it lies
    // h = -28.5 sin a + 0.8 cos a to the side, so the ball (radius 2) stops where its centre is
    // 27 from the axis, z = -0.2 + sqrt(27^2 - h^2), and the surface point is 2 below. Q333 =
    // +25 makes that Z 25: L Z+35 ends 10 above it.
    const double a = 0.7 * std::numbers::pi / 180.0;
    const double h = -28.5 * std::sin(a) + 0.8 * std::cos(a);
    const double top = -0.2 + std::sqrt(27.0 * 27.0 - h * h) - 2.0;
    for (const char* options : {"", "--motion"}) {
        const nlohmann::json report = run("CYLX", options, "machine4.toml");
        EXPECT_TRUE(report["ok"].get<bool>()) << options;
        EXPECT_NEAR(report["final_position"]["Z"].get<double>(), top + 10.0, 1e-6) << options;
    }
}

TEST_F(ProbingExamples, ToolMeasurementWritesTheRealToolsDeltasIntoTheToolTable) {
    // The machine file makes tool 5 really 0.05 longer and 0.012 thinner than TOOL.T says; 483
    // with Q340 = 1 writes exactly that into DL and DR, plain and under --motion, where the
    // simulated servo cycle latches both touches (a probe move each in the trace).
    for (const bool motion : {false, true}) {
        fs::copy_file(fs::path(KERF_SOURCE_DIR) / "examples/probing/TOOL.T", dir / "TOOL.T",
                      fs::copy_options::overwrite_existing);
        fs::remove(dir / "SIMTOOLS.TXT");
        const std::string trace = (dir / "trace.txt").string();
        const std::string options = (motion ? "--motion --trace \"" : "--trace \"") + trace + "\"";
        EXPECT_TRUE(run("TOOLMEAS", options)["ok"].get<bool>()) << options;
        const std::string tools = read(dir / "TOOL.T");
        EXPECT_NE(tools.find("MILL_D10    +80       +5        +0.05     -0.012"), std::string::npos)
            << options << "\n"
            << tools;
        std::istringstream lines(read(trace));
        int probeMoves = 0;
        for (std::string line; std::getline(lines, line);)
            probeMoves += line.find(" PROBE X") != std::string::npos;
        EXPECT_EQ(probeMoves, motion ? 2 : 0) << options;
    }
}

TEST_F(ProbingExamples, Rotation403TurnsTheCTableOfMill5) {
    // The front edge is turned by the setup's 0.7 degrees: 403 turns C by +0.7 (a table at
    // angle t turns the part by -t), also under --motion.
    for (const char* options : {"", "--motion"}) {
        const nlohmann::json report = run("ROT403", options, "machine5.toml");
        EXPECT_TRUE(report["ok"].get<bool>()) << options;
        EXPECT_NEAR(report["final_position"]["C"].get<double>(), 0.7, 1e-6) << options;
    }
}

// The three numbers after "Actual values:" in a measuring log (centre main, secondary, diameter).
std::array<double, 3> actualValues(const std::string& log) {
    std::array<double, 3> values{};
    std::istringstream lines(log.substr(log.find("Actual values:")));
    std::string line;
    std::getline(lines, line);
    for (double& value : values) {
        std::getline(lines, line);
        value = std::stod(line.substr(28));
    }
    return values;
}

TEST_F(ProbingExamples, LatchedSetUpAndMeasureFindTheRealPartAndThePocket) {
    // LATCH.H: tool 5 (really 0.012 thinner) cuts a pocket of diameter 30 at (70, 30), so its
    // wall has the diameter 29.976; 400 turns the system by the front face's 0.7 degrees, 411
    // puts the origin on the real blank's centre R(0.7)(50, 30) + (1.5, -0.8), and 421 finds the
    // pocket at R(-0.7)((70, 30) - that centre). The same plain and with the touches latched by
    // the simulated servo cycle under --motion.
    const double a = 0.7 * std::numbers::pi / 180.0;
    const double cx = 50.0 * std::cos(a) - 30.0 * std::sin(a) + 1.5;
    const double cy = 50.0 * std::sin(a) + 30.0 * std::cos(a) - 0.8;
    const double px = std::cos(a) * (70.0 - cx) + std::sin(a) * (30.0 - cy);
    const double py = -std::sin(a) * (70.0 - cx) + std::cos(a) * (30.0 - cy);
    for (const char* options : {"", "--motion"}) {
        fs::remove(dir / "PRESET.PR");
        const nlohmann::json report = run("LATCH", options);
        EXPECT_TRUE(report["ok"].get<bool>()) << options;
        EXPECT_NEAR(report["final_position"]["X"].get<double>(), cx, 0.002) << options;
        EXPECT_NEAR(report["final_position"]["Y"].get<double>(), cy, 0.002) << options;
        EXPECT_NEAR(report["final_position"]["Z"].get<double>(), 10.0, 1e-6) << options;
        const std::array<double, 3> hole = actualValues(read(dir / "TCHPR421.TXT"));
        EXPECT_NEAR(hole[0], px, 0.002) << options;
        EXPECT_NEAR(hole[1], py, 0.002) << options;
        EXPECT_NEAR(hole[2], 29.976, 0.002) << options;
        // Preset row 0: the real centre in machine coordinates (the built-in mill's workpiece
        // origin is at machine X 0 Y 0 Z -400), SPC the basic rotation 0.7.
        char row[160];
        std::snprintf(row, sizeof row, "%+.5f     %+.5f     -400", cx, cy);
        const std::string presets = read(dir / "PRESET.PR");
        EXPECT_NE(presets.find(row), std::string::npos) << options << "\n"
                                                        << row << "\n"
                                                        << presets;
        EXPECT_NE(presets.find("+0.7  "), std::string::npos) << options << presets;
    }
}

TEST_F(ProbingExamples, Seed14_14DatumOnAStudTurnedInTheSameProgram) {
    // 257 turns a stud of diameter 30 at (25, 25) out of the blank with tool 5, really 0.012
    // thinner and 0.05 longer than TOOL.T says (machine.toml): the stud stays 30.024 thick, its
    // centre where the tool went (the setup error moves the blank, not the cut). Its top is the
    // blank's, really at 25 - 0.2. 413 sets X 0 at the centre, Y +10 there, Z 0 on the top, so
    // L X+0 Y+0 Z+50 ends at (25, 15, 24.8 + 50) of the start preset.
    for (const char* options : {"", "--motion"}) {
        const nlohmann::json report = run("CYC413", options);
        EXPECT_TRUE(report["ok"].get<bool>()) << options;
        EXPECT_NEAR(report["final_position"]["X"].get<double>(), 25.0, 0.002) << options;
        EXPECT_NEAR(report["final_position"]["Y"].get<double>(), 15.0, 0.002) << options;
        EXPECT_NEAR(report["final_position"]["Z"].get<double>(), 74.8, 0.002) << options;
    }
}

TEST_F(ProbingExamples, Seed14_15DatumAtABoltCircleDrilledInTheSameProgram) {
    // Three holes drilled on a circle of diameter 50 about (35, 35); 417 writes the real top
    // (25 - 0.2) into preset row 1 and 416 then the circle's centre into the same row, leaving
    // its Z (machine coordinates: the built-in mill's origin at Z -400); 247 activates the row:
    // L X+0 Y+0 Z+50 ends at (35, 35, 24.8 + 50) of the start preset.
    for (const char* options : {"", "--motion"}) {
        fs::remove(dir / "PRESET.PR");
        const nlohmann::json report = run("CYC416", options);
        EXPECT_TRUE(report["ok"].get<bool>()) << options;
        EXPECT_NEAR(report["final_position"]["X"].get<double>(), 35.0, 0.002) << options;
        EXPECT_NEAR(report["final_position"]["Y"].get<double>(), 35.0, 0.002) << options;
        EXPECT_NEAR(report["final_position"]["Z"].get<double>(), 74.8, 0.002) << options;
        std::istringstream presets(read(dir / "PRESET.PR"));
        std::string line;
        bool found = false;
        while (std::getline(presets, line)) {
            std::istringstream fields(line);
            std::string number;
            double x = 0.0, y = 0.0, z = 0.0;
            if (!(fields >> number) || number != "1" || !(fields >> x >> y >> z)) continue;
            found = true;
            EXPECT_NEAR(x, 35.0, 0.002) << options;
            EXPECT_NEAR(y, 35.0, 0.002) << options;
            EXPECT_NEAR(z, -375.2, 0.002) << options;
        }
        EXPECT_TRUE(found) << options;
    }
}

TEST_F(ProbingExamples, Seed13_8TwoDrilledHolesTurnTheCTableAndZeroItsDisplay) {
    // The holes are drilled where the tool went, (25, 15) and (80, 35): the line between them
    // lies at atan2(20, 55) = 19.98311 degrees whatever the setup error, and Q307 = 0. 401 with
    // Q402 = 1 turns mill5's C table by that; Q337 = 1 zeroes its display through C of preset
    // row 0 (Q305 = 0), so the program's L C+0 afterwards leaves the table standing there.
    const double line = std::atan2(20.0, 55.0) * 180.0 / std::numbers::pi;
    for (const char* options : {"", "--motion"}) {
        fs::remove(dir / "PRESET.PR");
        const nlohmann::json report = run("CYC401", options, "machine5.toml");
        EXPECT_TRUE(report["ok"].get<bool>()) << options;
        EXPECT_NEAR(report["final_machine_position"]["C"].get<double>(), line, 1e-5) << options;
        std::istringstream presets(read(dir / "PRESET.PR"));
        std::string line0;
        bool found = false;
        while (std::getline(presets, line0)) {
            std::istringstream fields(line0);
            std::string number;
            double x = 0.0, y = 0.0, z = 0.0, a = 0.0, b = 0.0, c = 0.0;
            if (!(fields >> number) || number != "0" || !(fields >> x >> y >> z >> a >> b >> c))
                continue;
            found = true;
            EXPECT_NEAR(c, line, 1e-5) << options;
        }
        EXPECT_TRUE(found) << options << read(dir / "PRESET.PR");
    }
}

TEST_F(ProbingExamples, Seed15_14StudMeasuredBy424IsFinishedToSize) {
    // 213 mills the stud 81 x 61 about (50, 50) with tool 5, really 0.012 thinner than TOOL.T
    // says (machine.toml): it stands 81.024 x 61.024. 424 measures that against 80 x 60:
    // Q164 = Q165 = 1.024, so the finishing pass is programmed 79.976 x 59.976 and, with the
    // same thin tool, leaves exactly 80 x 60, which the second 424 logs.
    for (const char* options : {"", "--motion"}) {
        fs::remove(dir / "TCHPR424.TXT");
        const nlohmann::json report = run("BEAMS", options);
        EXPECT_TRUE(report["ok"].get<bool>()) << options;
        EXPECT_NEAR(report["final_position"]["X"].get<double>(), 79.976, 0.002) << options;
        EXPECT_NEAR(report["final_position"]["Y"].get<double>(), 59.976, 0.002) << options;
        const std::string log = read(dir / "TCHPR424.TXT");
        const size_t actual = log.find("Actual values:");
        ASSERT_NE(actual, std::string::npos) << log;
        EXPECT_NE(log.find("  side length main axis     +80.0000\n", actual), std::string::npos)
            << log;
        EXPECT_NE(log.find("  side length secondary     +60.0000\n", actual), std::string::npos)
            << log;
        EXPECT_NE(log.find("  centre main axis          +50.0000\n", actual), std::string::npos)
            << log;
    }
}

TEST_F(ProbingExamples, RemovalBenchmarkMeasuresThePocketItsThousandMovesCleared) {
    // The tool's centre covers X 25..75, Y 15..45 down to Z-25; tool 5 is really 4.988 in
    // radius and 0.05 longer (machine.toml): the pocket is 59.976 x 39.976 about (50, 30), its
    // floor at -25.05. 417 makes that floor Z 0, so L X+0 Y+0 Z+10 ends at Z -15.05.
    const nlohmann::json report = run("REMOVAL");
    EXPECT_TRUE(report["ok"].get<bool>());
    EXPECT_NEAR(report["final_position"]["Z"].get<double>(), -15.05, 0.002);
    const std::string log = read(dir / "TCHPR423.TXT");
    const size_t actual = log.find("Actual values:");
    ASSERT_NE(actual, std::string::npos) << log;
    EXPECT_NE(log.find("  side length main axis     +59.9760\n", actual), std::string::npos) << log;
    EXPECT_NE(log.find("  side length secondary     +39.9760\n", actual), std::string::npos) << log;
}

TEST_F(ProbingExamples, BasicRotationFromTheManualsExampleRuns) {
    EXPECT_TRUE(run("ROT400")["ok"].get<bool>());
}

TEST_F(ProbingExamples, SetupWithoutBlankThenTheNextProgramRunsInItsBasicRotation) {
    // SETUPNB probes the machine's default simulated blank (no BLK FORM) and leaves preset row 0
    // at the real corner with the basic rotation 0.7 (SPC). ROTNEXT, run from that preset
    // (--preset 0), ends at X+100 Y+0 Z+10: 100 mm along the turned front edge from the real
    // corner (1.5, -0.8), 10 above the real top (-400.2), in machine coordinates.
    const double a = 0.7 * std::numbers::pi / 180.0;
    for (const char* options : {"", "--motion"}) {
        EXPECT_TRUE(run("SETUPNB", options)["ok"].get<bool>()) << options;
        const nlohmann::json report = run("ROTNEXT", std::string("--preset 0 ") + options);
        EXPECT_TRUE(report["ok"].get<bool>()) << options;
        const nlohmann::json& end = report["final_machine_position"];
        EXPECT_NEAR(end["X"].get<double>(), 1.5 + 100.0 * std::cos(a), 1e-4) << options;
        EXPECT_NEAR(end["Y"].get<double>(), -0.8 + 100.0 * std::sin(a), 1e-4) << options;
        EXPECT_NEAR(end["Z"].get<double>(), -400.2 + 10.0, 1e-4) << options;
    }
}

TEST_F(ProbingExamples, PresetRowThatDoesNotExistIsRefused) {
    const std::string command = std::string("\"") + KERF_BINARY + "\" run --machine \"" +
                                (dir / "machine.toml").string() + "\" --preset 7 \"" +
                                (dir / "ROTNEXT.H").string() + "\" 2> \"" +
                                (dir / "errors").string() + "\"";
    EXPECT_NE(std::system(command.c_str()), 0);
    EXPECT_NE(read(dir / "errors").find("PRESET.PR"), std::string::npos) << read(dir / "errors");
}

}  // namespace
