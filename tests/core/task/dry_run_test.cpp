#include "core/task/dry_run.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/machine/machine_loader.h"

// The run of `kerf check` and the HMI's "Check program": what only a run finds, its block limit
// and its cancel (the HMI cancels a check whose text was edited).
namespace kerf::task {
namespace {

namespace fs = std::filesystem;

ProgramRequest requestFor(const std::string& text) {
    ProgramRequest request;
    request.path =
        fs::temp_directory_path() / ("kerf_dry_run_" + std::to_string(::getpid())) / "P.H";
    request.ncRoot = request.path.parent_path();
    request.text = text;
    return request;
}

// Q1 is 0 when the division runs; the static check cannot know it.
const char* const kDivisionByZero =
    "0 BEGIN PGM P MM\n"
    "1 Q1 = 0\n"
    "2 Q2 = 5 / Q1\n"
    "3 END PGM P MM\n";

// Jumps back to LBL 1 forever: two blocks per pass.
const char* const kEndless =
    "0 BEGIN PGM P MM\n"
    "1 LBL 1\n"
    "2 FN 9: IF +0 EQU +0 GOTO LBL 1\n"
    "3 END PGM P MM\n";

TEST(DryRun, FindsWhatOnlyTheRunFindsAtItsOperator) {
    const auto mill = *machine::loadMachine("mill");
    const ProgramRequest request = requestFor(kDivisionByZero);
    EXPECT_FALSE(hasErrors(loadProgram(mill, request).diagnostics()));
    const RunCheck check = checkByRunning(mill, request);
    ASSERT_TRUE(hasErrors(check.diagnostics));
    const Diagnostic& error = check.diagnostics.back();
    // "2 Q2 = 5 / Q1": line 3 of the text, the '/' at column 10.
    EXPECT_EQ(error.line, 3u);
    EXPECT_EQ(error.column, 10u);
    EXPECT_EQ(error.format().substr(error.format().find("error: ")), "error: division by zero");
    EXPECT_FALSE(check.cancelled);
}

TEST(DryRun, AnEndlessLoopStopsAtTheBlockLimit) {
    const auto mill = *machine::loadMachine("mill");
    DryRunOptions options;
    options.maxBlocks = 1000;
    const RunCheck check = checkByRunning(mill, requestFor(kEndless), options);
    ASSERT_FALSE(check.diagnostics.empty());
    EXPECT_EQ(check.diagnostics.back().code, "block-limit");
    // The HMI's Check program has no --max-blocks: its message names no command-line option.
    EXPECT_EQ(check.diagnostics.back().message(),
              "the program check stopped after 1000 blocks: endless loop?");
    // kerf check and kerf run say how to raise the limit.
    EXPECT_EQ(blockLimitError("E.H", 1000, BlockLimitSource::CommandLine).message(),
              "stopped after 1000 blocks: endless loop? (--max-blocks)");

    LoadedProgram program = loadProgram(mill, requestFor(kEndless));
    ASSERT_TRUE(program.ready);
    EXPECT_EQ(runDry(*program.interpreter, options).end, DryRunEnd::BlockLimit);
    EXPECT_EQ(program.interpreter->blocksExecuted(), 1000u);
}

TEST(DryRun, ACancelledRunStopsBeforeItsNextSlice) {
    const auto mill = *machine::loadMachine("mill");
    std::atomic<bool> cancel{true};
    DryRunOptions options;
    options.cancel = &cancel;
    LoadedProgram program = loadProgram(mill, requestFor(kEndless));
    ASSERT_TRUE(program.ready);
    EXPECT_EQ(runDry(*program.interpreter, options).end, DryRunEnd::Cancelled);
    EXPECT_EQ(program.interpreter->blocksExecuted(), 0u);
    EXPECT_TRUE(checkByRunning(mill, requestFor(kEndless), options).cancelled);
}

// A machine whose X travel ends at +100 (workpiece coordinates).
class ShortX final : public MoveCheck {
public:
    void start(const Pose& tip) override { m_at = tip; }
    bool accept(const canon::Command& command) override {
        if (const auto* rapid = std::get_if<canon::RapidMove>(&command.body)) {
            if (rapid->target[Axis::X] > 100.0) m_refusal = command.location;
        }
        return !m_refusal;
    }
    void resumeAt(const Pose& tip) override { m_at = tip; }
    Pose position() const override { return m_at; }
    bool refused() const override { return m_refusal.has_value(); }
    DiagnosticList refusal() const override {
        return {Diagnostic::make(Severity::Error, "motion.soft-limit", "", m_refusal->line,
                                 m_refusal->column, "beyond X")};
    }

private:
    Pose m_at;
    std::optional<SourceLocation> m_refusal;
};

// `kerf check` judges the run's commands as the machine would: the first one refused ends the
// run, and its refusal names the block in its file.
TEST(DryRun, AMoveTheMachineRefusesEndsTheRunAtItsBlock) {
    const auto mill = *machine::loadMachine("mill");
    ShortX shortX;
    DryRunOptions options;
    options.moves = &shortX;
    const ProgramRequest request = requestFor(
        "0 BEGIN PGM P MM\n1 L X+50 R0 FMAX\n2 L X+150 R0 FMAX\n3 L X+0 R0 FMAX\n"
        "4 END PGM P MM\n");
    const RunCheck check = checkByRunning(mill, request, options);
    ASSERT_EQ(check.diagnostics.size(), 1u);
    EXPECT_EQ(check.diagnostics[0].format(), request.path.string() + ":3:1: error: beyond X");

    LoadedProgram program = loadProgram(mill, request);
    ShortX again;
    options.moves = &again;
    const DryRunResult end = runDry(*program.interpreter, options);
    EXPECT_EQ(end.end, DryRunEnd::Refused);
    EXPECT_EQ(end.refusedAt.line, 3u);
}

}  // namespace
}  // namespace kerf::task
