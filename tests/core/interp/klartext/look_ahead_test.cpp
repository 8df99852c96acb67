// M120 LA n in conversational programs: a notch narrower than the tool, which stops the run
// with "tool radius too large" without M120, is left out with it (expected paths by hand).
#include <filesystem>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class Recorder : public canon::Sink {
public:
    void consume(const canon::Command& c) override { commands.push_back(c); }
    std::vector<canon::Command> commands;
};

class LookAheadTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_m120_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        machine = *machine::loadMachine("mill");
    }
    void TearDown() override { fs::remove_all(dir); }

    // Runs the program to its end; the status, and the diagnostics in `k`.
    interp::RunStatus run(const std::string& text) {
        KlartextSettings settings;
        settings.machine = &machine;
        settings.ncRoot = dir;
        k = std::make_unique<KlartextInterpreter>(sources, settings);
        writeFileAtomically(dir / "P.H", text);
        if (!k->load(dir / "P.H")) return interp::RunStatus::Failed;
        interp::RunStatus status;
        while ((status = k->run(out, 1000)) == interp::RunStatus::BudgetUsed) {
        }
        return status;
    }
    uint32_t errorLine() const {
        return k->diagnostics().empty() ? 0 : k->diagnostics().back().line;
    }
    // In-plane targets of the feed moves.
    std::vector<Vec2> feedTargets() const {
        std::vector<Vec2> points;
        for (const canon::Command& c : out.commands) {
            if (const auto* l = std::get_if<canon::LinearMove>(&c.body)) {
                points.emplace_back(l->target[Axis::X], l->target[Axis::Y]);
            }
            EXPECT_FALSE(std::holds_alternative<canon::ArcMove>(c.body));
        }
        return points;
    }

    fs::path dir;
    program::SourceRegistry sources;
    machine::MachineConfig machine;
    std::unique_ptr<KlartextInterpreter> k;
    Recorder out;
};

// Tool R5 on the left (RL) of an edge y=0 with a notch 2 wide and 3 deep at x=20..22; `m120` is
// written in the block that switches the compensation on. The notch's first side is on line 7.
std::string notch(const std::string& m120) {
    return "0 BEGIN PGM N MM\n1 TOOL DEF 1 L+0 R+5\n2 TOOL CALL 1 Z S1000\n"
           "3 L X-10 Y+0 Z-5 R0 FMAX\n4 L X+0 Y+0 RL F100" +
           m120 +
           "\n5 L X+20\n6 L Y-3\n7 L X+22\n8 L Y+0\n9 L X+40\n10 L X+50 Y+10 R0\n"
           "11 END PGM N MM\n";
}

TEST_F(LookAheadTest, WithoutM120TheNotchIsRadiusTooLarge) {
    EXPECT_EQ(run(notch("")), interp::RunStatus::Failed);
    EXPECT_EQ(errorLine(), 7u);
    EXPECT_EQ(k->diagnostics().back().code, "radius-too-large");
}

TEST_F(LookAheadTest, M120LA3LeavesOutTheNotch) {
    ASSERT_EQ(run(notch(" M120 LA3")), interp::RunStatus::Finished);
    // The tool centre stays 5 above the edge across the notch: the offsets of the edges before
    // and after it lie on one line y=5.
    const std::vector<Vec2> expected = {{0, 5}, {22, 5}, {40, 5}, {50, 10}};
    const std::vector<Vec2> moves = feedTargets();
    ASSERT_EQ(moves.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(moves[i].x(), expected[i].x(), 1e-9) << i;
        EXPECT_NEAR(moves[i].y(), expected[i].y(), 1e-9) << i;
    }
    // M120 is not passed on as a machine function.
    for (const canon::Command& c : out.commands) {
        EXPECT_FALSE(std::holds_alternative<canon::MachineFunction>(c.body));
    }
}

TEST_F(LookAheadTest, TooFewBlocksAheadForTheNotchIsAnError) {
    // The notch has three elements: LA2 cannot see past it.
    EXPECT_EQ(run(notch(" M120 LA2")), interp::RunStatus::Failed);
    EXPECT_EQ(errorLine(), 7u);
}

TEST_F(LookAheadTest, R0AndM120WithoutLAEndTheLookAhead) {
    // The same notch again after R0 and a new RL: without M120 in force it is an error again.
    const std::string again =
        "0 BEGIN PGM N MM\n1 TOOL DEF 1 L+0 R+5\n2 TOOL CALL 1 Z S1000\n"
        "3 L X-10 Y+0 Z-5 R0 FMAX\n4 L X+0 Y+0 RL F100 M120 LA3\n5 L X+20\n6 L Y-3\n"
        "7 L X+22\n8 L Y+0\n9 L X+40\n10 L X+50 Y+10 R0\n"
        "11 L X-10 Y+0 FMAX\n12 L X+0 Y+0 RL F100\n13 L X+20\n14 L Y-3\n15 L X+22\n16 L Y+0\n"
        "17 L X+40\n18 L X+50 Y+10 R0\n19 END PGM N MM\n";
    EXPECT_EQ(run(again), interp::RunStatus::Failed);
    EXPECT_EQ(errorLine(), 15u);

    // M120 without LA in the block before the notch.
    EXPECT_EQ(run("0 BEGIN PGM N MM\n1 TOOL DEF 1 L+0 R+5\n2 TOOL CALL 1 Z S1000\n"
                  "3 L X-10 Y+0 Z-5 R0 FMAX\n4 L X+0 Y+0 RL F100 M120 LA3\n5 L X+20 M120\n"
                  "6 L Y-3\n7 L X+22\n8 L Y+0\n9 L X+40\n10 L X+50 Y+10 R0\n11 END PGM N MM\n"),
              interp::RunStatus::Failed);
    EXPECT_EQ(errorLine(), 7u);
}

}  // namespace
}  // namespace kerf::klartext
