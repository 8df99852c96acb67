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

}  // namespace
}  // namespace kerf::task
