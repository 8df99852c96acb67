// `kerf run` reports a rapid that runs into the blank as a collision warning at its block, and
// runs on (docs/probing.md, "A rapid that takes material is reported as a collision").
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

class RapidCollisionRun : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_rapid_collision_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        // Tool 5: a D10 end mill, 80 long.
        fs::copy_file(fs::path(KERF_SOURCE_DIR) / "examples/probing/TOOL.T", dir / "TOOL.T");
    }
    void TearDown() override { fs::remove_all(dir); }

    std::string read(const fs::path& file) {
        std::stringstream text;
        text << std::ifstream(file, std::ios::binary).rdbuf();
        return text.str();
    }
    // kerf run on the built-in mill (no setup error); the report as JSON, stderr in `errors`.
    nlohmann::json run(const std::string& program) {
        std::ofstream(dir / "P.H") << program;
        const std::string command = std::string("\"") + KERF_BINARY + "\" run \"" +
                                    (dir / "P.H").string() + "\" --report \"" +
                                    (dir / "r.json").string() + "\" 2> \"" +
                                    (dir / "errors").string() + "\"";
        EXPECT_EQ(std::system(command.c_str()), 0) << read(dir / "errors");
        errors = read(dir / "errors");
        return nlohmann::json::parse(read(dir / "r.json"));
    }

    fs::path dir;
    std::string errors;
};

const char* const kBlank =
    "0 BEGIN PGM P MM\n"
    "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n"
    "2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
    "3 TOOL CALL 5 Z S3000\n";

TEST_F(RapidCollisionRun, PlungeAtFmaxIntoTheTopIsAWarningAtItsBlock) {
    // Tool 5 at FMAX 3 into the top (block 5, line 6); out again (line 7).
    const nlohmann::json report = run(std::string(kBlank) +
                                      "4 L X+50 Y+30 Z+10 R0 FMAX M3\n"
                                      "5 L Z-3 R0 FMAX\n"
                                      "6 L Z+50 R0 FMAX\n"
                                      "7 END PGM P MM\n");
    EXPECT_TRUE(report["ok"].get<bool>());
    const std::string file = (dir / "P.H").string();
    EXPECT_NE(errors.find(file + ":6:1: warning: collision: a rapid move runs into the material"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find(file + ":7:1: warning: collision"), std::string::npos) << errors;
    int collisions = 0;
    for (const nlohmann::json& d : report["diagnostics"])
        collisions += d["code"] == "collision" ? 1 : 0;
    EXPECT_EQ(collisions, 2);
}

TEST_F(RapidCollisionRun, CyclesThatPositionInTheAirAndCutAtFeedAreNoCollision) {
    // 200 retracts at FMAX out of its hole and goes back down at FMAX to above the depth it
    // drilled; the rapids of a side-on approach end 1 short of the left face (x -6 + 5).
    const nlohmann::json report = run(std::string(kBlank) +
                                      "4 CYCL DEF 200 DRILLING\n  Q200=2\n  Q201=-20\n  Q206=250\n"
                                      "  Q202=5\n  Q210=0\n  Q203=+0\n  Q204=20\n  Q211=0\n"
                                      "  Q395=0\n"
                                      "5 L X+30 Y+20 Z+50 R0 FMAX M3\n"
                                      "6 L X+60 Y+20 R0 FMAX M99\n"
                                      "7 L X-20 Y+30 Z+10 R0 FMAX\n"
                                      "8 L Z-5 R0 FMAX\n"
                                      "9 L X-6 R0 FMAX\n"
                                      "10 L X+20 F500\n"
                                      "11 L X-6 R0 FMAX\n"
                                      "12 L Z+50 R0 FMAX\n"
                                      "13 END PGM P MM\n");
    EXPECT_TRUE(report["ok"].get<bool>());
    EXPECT_EQ(errors.find("collision"), std::string::npos) << errors;
}

}  // namespace
