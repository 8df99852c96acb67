// One parse of a plain program, shared by the check that follows the run and the run
// (core/interp/klartext/program_check.h).
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/canon/trace_format.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class SharedParseTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_shared_parse_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        machine = *machine::loadMachine("mill");
    }
    void TearDown() override { fs::remove_all(dir); }

    std::unique_ptr<KlartextInterpreter> make() {
        KlartextSettings settings;
        settings.machine = &machine;
        settings.ncRoot = dir;
        return std::make_unique<KlartextInterpreter>(sources, settings);
    }

    // The trace of a run, and its end status.
    struct Run {
        std::string trace;
        interp::RunStatus status = interp::RunStatus::Failed;
        bool checkFailed = false;
        DiagnosticList diagnostics;
    };
    Run run(const fs::path& path, KlartextInterpreter::CheckMode mode) {
        class Printer final : public canon::Sink {
        public:
            void consume(const canon::Command& c) override {
                canon::appendCommand(text, c, format);
                text.push_back('\n');
            }
            std::string text;
            canon::TraceFormat format;
        } printer;
        Run result;
        auto k = make();
        if (!k->load(path, mode)) {
            result.diagnostics = k->diagnostics();
            return result;
        }
        do {
            result.status = k->run(printer, 1000);
        } while (result.status == interp::RunStatus::BudgetUsed);
        result.trace = std::move(printer.text);
        result.checkFailed = k->checkFailed();
        result.diagnostics = k->diagnostics();
        return result;
    }

    // A zigzag of `count` literal L blocks, with a circle centre now and then.
    static std::string plainBlocks(int first, int count) {
        std::string text;
        for (int i = 0; i < count; ++i) {
            const int n = first + i;
            if (i % 500 == 250) {
                text += std::to_string(n) + " CC X+0 Y+0\n";
                continue;
            }
            text += std::to_string(n) + " L X+" + std::to_string(n % 50) + ".25 Y" +
                    (n % 2 ? "+1" : "-1") + " Z-1 F" + std::to_string(100 + n % 7) + "\n";
        }
        return text;
    }

    // The 1-based line of `text` in `program`.
    static uint32_t lineOf(const std::string& program, const std::string& text) {
        const size_t at = program.find(text);
        EXPECT_NE(at, std::string::npos);
        return 1 + static_cast<uint32_t>(
                       std::count(program.begin(), program.begin() + static_cast<long>(at), '\n'));
    }

    static std::vector<std::string> formatted(const DiagnosticList& diagnostics) {
        std::vector<std::string> lines;
        for (const Diagnostic& d : diagnostics)
            lines.push_back(d.format());
        return lines;
    }

    fs::path dir;
    machine::MachineConfig machine;
    program::SourceRegistry sources;
};

TEST_F(SharedParseTest, ABlockTheCheckParsedRunsAsIfTheRunHadParsedIt) {
    const std::string program = "0 BEGIN PGM P MM\n1 TOOL CALL 1 Z S1000\n2 L Z+5 R0 FMAX M3\n" +
                                plainBlocks(3, 6000) + "9001 L X+Q1 FMAX\n9002 END PGM P MM\n";
    writeFileAtomically(dir / "P.H", program);
    const Run inline_ = run(dir / "P.H", KlartextInterpreter::CheckMode::Inline);
    const Run shared = run(dir / "P.H", KlartextInterpreter::CheckMode::Background);
    ASSERT_EQ(inline_.status, interp::RunStatus::Finished);
    EXPECT_EQ(shared.status, interp::RunStatus::Finished);
    EXPECT_FALSE(shared.checkFailed);
    // Every command with its line, column and block number, in the same order.
    EXPECT_GT(inline_.trace.size(), 100000u);
    EXPECT_EQ(shared.trace, inline_.trace);
}

TEST_F(SharedParseTest, AnErrorInTheLastBlockStopsTheRunBeforeItWrites) {
    // Thousands of handed-over blocks, then FN 16 (the first side effect), then an error in the
    // last block: the check must have finished and refused the program before the FN 16 writes.
    writeFileAtomically(dir / "MASK.A", "\"X\";\n");
    const std::string program = "0 BEGIN PGM P MM\n1 L Z+5 R0 FMAX\n" + plainBlocks(2, 6000) +
                                "9000 FN 16: F-PRINT MASK.A / OUT.TXT\n" + plainBlocks(9001, 100) +
                                "9101 BOGUS\n9102 END PGM P MM\n";
    writeFileAtomically(dir / "P.H", program);
    const Run r = run(dir / "P.H", KlartextInterpreter::CheckMode::Background);
    EXPECT_TRUE(r.checkFailed);
    EXPECT_FALSE(fs::exists(dir / "OUT.TXT"));
    ASSERT_TRUE(hasErrors(r.diagnostics));
    EXPECT_EQ(r.diagnostics.front().line, lineOf(program, "9101 BOGUS"));
    // The same findings as the check on load, which refuses the program.
    const Run alone = run(dir / "P.H", KlartextInterpreter::CheckMode::Inline);
    EXPECT_EQ(formatted(r.diagnostics), formatted(alone.diagnostics));
}

TEST_F(SharedParseTest, TheCheckFindsInTheBlocksItTookWhatItFindsAlone) {
    // A feed move without a feed (a literal L the run hands over), a block number out of order
    // and a label defined twice far down: the check following the run reports what the check on
    // load reports, at the same lines.
    const std::string program = "0 BEGIN PGM P MM\n1 L Z+5 R0 FMAX\n2 L X+1 Y+1\n" +
                                plainBlocks(3, 3000) + "5 L X+2 F100\n3100 LBL 7\n" +
                                plainBlocks(3101, 100) + "3201 LBL 7\n3202 END PGM P MM\n";
    writeFileAtomically(dir / "P.H", program);
    const Run alone = run(dir / "P.H", KlartextInterpreter::CheckMode::Inline);
    const Run following = run(dir / "P.H", KlartextInterpreter::CheckMode::Background);
    EXPECT_TRUE(following.checkFailed);
    const std::vector<std::string> expected = formatted(alone.diagnostics);
    ASSERT_EQ(expected.size(), 3u);
    EXPECT_NE(expected[0].find(":3:1: error: feed rate is missing"), std::string::npos);
    EXPECT_NE(expected[1].find(":" + std::to_string(lineOf(program, "5 L X+2 F100")) +
                               ":1: warning: block number 5 is out of order"),
              std::string::npos);
    EXPECT_NE(expected[2].find(":" + std::to_string(lineOf(program, "3201 LBL 7")) +
                               ":1: error: label 7 is defined twice"),
              std::string::npos);
    EXPECT_EQ(formatted(following.diagnostics), expected);
}

}  // namespace
}  // namespace kerf::klartext
