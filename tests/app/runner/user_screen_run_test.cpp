// `kerf run --user-screen MODE` on the seed's customisation examples (examples/fagor_user_screen):
// the operator's answers come from --operator-input (docs/headless.md).
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

class UserScreenRun : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_user_screen_run_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::copy(fs::path(KERF_SOURCE_DIR) / "examples/fagor_user_screen", dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    static std::string read(const fs::path& file) {
        std::stringstream text;
        text << std::ifstream(file, std::ios::binary).rdbuf();
        return text.str();
    }
    // kerf run with `options`; the exit code, the report, standard output and errors.
    int run(const std::string& program, const std::string& options) {
        const std::string command =
            std::string("\"") + KERF_BINARY + "\" run --machine lathe " + options + " \"" +
            (dir / program).string() + "\" --report \"" + (dir / "report.json").string() +
            "\" > \"" + (dir / "out").string() + "\" 2> \"" + (dir / "errors").string() + "\"";
        const int status = std::system(command.c_str());
        report = nlohmann::json::parse(read(dir / "report.json"));
        out = read(dir / "out");
        errors = read(dir / "errors");
        return WEXITSTATUS(status);
    }

    fs::path dir;
    nlohmann::json report;
    std::string out;
    std::string errors;
};

TEST_F(UserScreenRun, Ex12_19WritesTwoCycleCallsAndLeavesWithF7) {
    // F3 is no option (asked again); F1 cycle 1 with X2 Y-3.5; F2 cycle 2 with A3 B1 C3; F7.
    EXPECT_EQ(run("P000019.PIM",
                  "--user-screen edit --operator-input F3,F1,2,-3.5 "
                  "--operator-input F2,3,1,3,F7"),
              0)
        << errors;
    EXPECT_EQ(errors, "");
    EXPECT_TRUE(report["ok"].get<bool>());
    const nlohmann::json& screen = report["user_screen"];
    EXPECT_EQ(screen["inserted_blocks"],
              nlohmann::json::array({"( PCALL 1,X2,Y-3.5)", "( PCALL 2,A3,B1,C3)"}));
    EXPECT_TRUE(screen["left"].get<bool>());
    EXPECT_EQ(screen["operator_inputs_used"].get<int>(), 9);
    EXPECT_EQ(screen["inputs"][1].get<double>(), 3.0);  // the last cycle's A
    EXPECT_NE(out.find("inserted block: ( PCALL 2,A3,B1,C3)\n"), std::string::npos) << out;
}

TEST_F(UserScreenRun, Ex12_15EndsWithANoteWhenNoInputIsGiven) {
    EXPECT_EQ(run("P000015.PIM", "--user-screen execution"), 0) << errors;
    EXPECT_EQ(errors, (dir / "P000015.PIM").string() +
                          ": note: the user screen waits for IB1 and no --operator-input is "
                          "left: the run ends here\n");
    EXPECT_EQ(report["user_screen"]["input_prompt"], "Avanço dos eixos: ");
    EXPECT_EQ(run("P000015.PIM", "--user-screen execution --operator-input 1500.25"), 0);
    EXPECT_EQ(report["user_screen"]["windows"][0]["window"].get<int>(), 3);
    EXPECT_EQ(report["user_screen"]["windows"][0]["text"], "1500.25");
    // A negative feed does not fit the format 5.4.
    EXPECT_EQ(run("P000015.PIM", "--user-screen execution --operator-input -3"), 1);
    EXPECT_EQ(errors, (dir / "P000015.PIM").string() +
                          ": error: operator input '-3' for IB1: only positive values are "
                          "accepted here\n");
}

TEST_F(UserScreenRun, Ex12_13RefreshesUntilTheBlockLimit) {
    EXPECT_EQ(run("P000013.PIM", "--user-screen execution --max-blocks 2000"), 0) << errors;
    EXPECT_NE(errors.find("note: the customisation program ran 2000 blocks"), std::string::npos)
        << errors;
    EXPECT_EQ(report["user_screen"]["windows"].size(), 2u);
    EXPECT_EQ(report["user_screen"]["windows"][0]["text"].get<std::string>().size(), 6u);  // yymmdd
}

TEST_F(UserScreenRun, ACustomisationProgramOutsideTheUserChannelFailsItsCheck) {
    EXPECT_EQ(run("P000015.PIM", ""), 1);
    EXPECT_NE(errors.find(":3:2: error: ODW is a screen customisation instruction"),
              std::string::npos)
        << errors;
}

// IBn=value inputs reach an ordinary program (no user screen): X IB3 = 40, then X IB3 - IB1 =
// 27.5 (diameters); anything else without --user-screen is refused before the run.
TEST_F(UserScreenRun, InputAssignmentsReachAnOrdinaryProgram) {
    std::ofstream(dir / "P000021.PIM") << "(P100=IB3)\n(P101=IB3 - IB1)\nG90 G00 XP100 Z0\n"
                                          "G00 XP101\nM30\n";
    ASSERT_EQ(run("P000021.PIM",
                  "--operator-input IB3=40,IB1=12.5 --trace \"" + (dir / "t.txt").string() + "\""),
              0)
        << errors;
    const std::string trace = read(dir / "t.txt");
    EXPECT_NE(trace.find("RAPID X20.0000 Z0.0000"), std::string::npos) << trace;
    EXPECT_NE(trace.find("RAPID X13.7500 Z0.0000"), std::string::npos) << trace;
    EXPECT_EQ(run("P000021.PIM", "--operator-input 2.5"), 1);
    EXPECT_NE(errors.find("--operator-input '2.5': IBn=value expected"), std::string::npos)
        << errors;
}

TEST_F(UserScreenRun, OnlyFagorProgramsRunOnTheUserScreen) {
    { std::ofstream(dir / "A.H") << "BEGIN PGM A MM\nEND PGM A MM\n"; }
    const std::string command = std::string("\"") + KERF_BINARY + "\" run --user-screen edit \"" +
                                (dir / "A.H").string() + "\" 2> \"" + (dir / "errors").string() +
                                "\"";
    EXPECT_EQ(WEXITSTATUS(std::system(command.c_str())), 1);
    EXPECT_EQ(read(dir / "errors"), (dir / "A.H").string() +
                                        ": error: --user-screen runs FAGOR customisation "
                                        "programs only\n");
}

}  // namespace
