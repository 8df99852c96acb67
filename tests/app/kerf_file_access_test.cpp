// The NC-root file-access layer seen from the command line (docs/files.md): links out of the root,
// FIFOs, outputs named like inputs, writes of a program that fails its check, and a program file
// truncated while it runs. Each case is a reproducer of ../shared/repro/reliability/; each also
// checks that the same program without the trick does what it should, so it cannot pass by
// doing nothing.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test_paths.h"

namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
    std::stringstream text;
    text << std::ifstream(path, std::ios::binary).rdbuf();
    return text.str();
}

void writeFile(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// The kerf under test: this build's, or $KERF_UNDER_TEST (to show a fault on an older build).
const char* kerfBinary() {
    const char* other = std::getenv("KERF_UNDER_TEST");
    return other != nullptr && *other != '\0' ? other : KERF_BINARY;
}

struct Result {
    int exitCode = -1;  // -1: killed by a signal (a crash, or the 10 s guard against a hang)
    std::string out;
    std::string errors;
};

class KerfFileAccess : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = kerf::test::uniqueTempDir(
            std::string("files_") + testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(root());
        fs::create_directories(outside());
    }
    void TearDown() override { fs::remove_all(m_dir); }

    fs::path root() const { return m_dir / "root"; }
    fs::path outside() const { return m_dir / "outside"; }

    // `kerf <arguments>` in the test folder, killed after 10 s so that a hang fails the test.
    Result kerf(const std::string& arguments) const {
        const fs::path out = m_dir / "stdout.txt";
        const fs::path errors = m_dir / "stderr.txt";
        const std::string command = "cd \"" + m_dir.string() + "\" && timeout -s KILL 10 \"" +
                                    kerfBinary() + "\" " + arguments + " > \"" + out.string() +
                                    "\" 2> \"" + errors.string() + "\"";
        const int status = std::system(command.c_str());
        Result r;
        r.exitCode = WIFEXITED(status) && WEXITSTATUS(status) < 128 ? WEXITSTATUS(status) : -1;
        r.out = readFile(out);
        r.errors = readFile(errors);
        return r;
    }

    fs::path m_dir;
};

// ---- links that lead out of the NC root (sandbox_symlink.sh) ---------------------------------

TEST_F(KerfFileAccess, FagorOpenDoesNotWriteThroughLinksOut) {
    const std::string secret = "SECRET ORIGINAL CONTENT\n";
    writeFile(outside() / "victim.txt", secret);
    writeFile(outside() / "victim2.txt", secret);
    fs::create_symlink("../outside/victim.txt", root() / "P000777.PIM");
    fs::create_symlink("../outside/victim2.txt", root() / "P000778.PIM");
    fs::create_symlink("../outside/created_by_kerf.txt", root() / "P000779.PIM");
    writeFile(root() / "append.pim", "G00 X0 Z0\n(OPEN P777, A)\n(WRITE G01 X1 Z1)\nM30\n");
    writeFile(root() / "delete.pim", "G00 X0 Z0\n(OPEN P778, D, \"PWNED\")\n(WRITE M30)\nM30\n");
    writeFile(root() / "create.pim", "G00 X0 Z0\n(OPEN P779, \"NEW\")\n(WRITE G01 X2 Z2)\nM30\n");
    for (const char* program : {"append.pim", "delete.pim", "create.pim"}) {
        Result r = kerf(std::string("run root/") + program + " --machine lathe");
        EXPECT_EQ(r.exitCode, 1) << program << "\n" << r.errors;
        // The error is at the OPEN block, line 2.
        EXPECT_NE(r.errors.find(std::string(program) + ":2:"), std::string::npos) << r.errors;
    }
    EXPECT_EQ(readFile(outside() / "victim.txt"), secret);
    EXPECT_EQ(readFile(outside() / "victim2.txt"), secret);
    EXPECT_FALSE(fs::exists(outside() / "created_by_kerf.txt"));

    // Inside the root the same OPEN writes the program, once the run is over.
    writeFile(root() / "P000780.PIM", "%OLD,,\nG00 X0 Z0\n");
    writeFile(root() / "inside.pim", "G00 X0 Z0\n(OPEN P780, A)\n(WRITE G01 X1 Z1)\nM30\n");
    Result inside = kerf("run root/inside.pim --machine lathe");
    EXPECT_EQ(inside.exitCode, 0) << inside.errors;
    EXPECT_EQ(readFile(root() / "P000780.PIM"), "%OLD,,\nG00 X0 Z0\nG01 X1 Z1\n");
}

TEST_F(KerfFileAccess, FagorExecDoesNotRunAProgramOutside) {
    writeFile(outside() / "secret_prog.txt", "G01 X55 Z-5 F100\nM30\n");
    fs::create_symlink("../outside/secret_prog.txt", root() / "P000900.PIM");
    writeFile(root() / "exec.pim", "G00 X0 Z0\n(EXEC P900)\nM30\n");
    Result r = kerf("run root/exec.pim --machine lathe --trace -");
    EXPECT_EQ(r.exitCode, 1) << r.errors;
    EXPECT_EQ(r.out.find("Z-5"), std::string::npos) << r.out;
    EXPECT_NE(r.errors.find("exec.pim:2:"), std::string::npos) << r.errors;

    // The same program as a plain file in the root runs.
    fs::remove(root() / "P000900.PIM");
    writeFile(root() / "P000900.PIM", "G01 X55 Z-5 F100\nM30\n");
    Result plain = kerf("run root/exec.pim --machine lathe --trace -");
    EXPECT_EQ(plain.exitCode, 0) << plain.errors;
    EXPECT_NE(plain.out.find("Z-5"), std::string::npos) << plain.out;
}

TEST_F(KerfFileAccess, CallPgmChecksTheNameAfterAddingTheExtension) {
    writeFile(outside() / "outside.H",
              "0 BEGIN PGM OUTSIDE MM\n1 L X+77 Y+77 FMAX\n"
              "2 END PGM OUTSIDE MM\n");
    fs::create_symlink("../outside/outside.H", root() / "noext.H");
    fs::create_symlink("../outside/outside.H", root() / "direct.H");
    writeFile(root() / "c1.H", "0 BEGIN PGM A MM\n1 CALL PGM direct.H\n2 END PGM A MM\n");
    writeFile(root() / "c2.H", "0 BEGIN PGM A MM\n1 CALL PGM noext\n2 END PGM A MM\n");
    for (const char* program : {"c1.H", "c2.H"}) {
        Result r = kerf(std::string("run root/") + program + " --trace -");
        EXPECT_EQ(r.exitCode, 1) << program;
        EXPECT_EQ(r.out.find("77"), std::string::npos) << program << "\n" << r.out;
        // Block 1 is on the file's line 2.
        EXPECT_NE(r.errors.find(std::string(program) + ":2:"), std::string::npos) << r.errors;
        EXPECT_NE(r.errors.find("outside the NC root"), std::string::npos) << r.errors;
    }
    // A real file of that name is called.
    fs::remove(root() / "noext.H");
    fs::copy_file(outside() / "outside.H", root() / "noext.H");
    Result plain = kerf("run root/c2.H --trace -");
    EXPECT_EQ(plain.exitCode, 0) << plain.errors;
    EXPECT_NE(plain.out.find("77"), std::string::npos) << plain.out;
}

TEST_F(KerfFileAccess, SelTableAndSelPatternCheckTheNameAfterAddingTheExtension) {
    writeFile(outside() / "evil.D",
              "BEGIN DATUMS.D MM\nD   X        Y        Z\n"
              "0   +0       +0       +0\n1   +55      +55      +0\n[END]\n");
    writeFile(outside() / "evil.PNT",
              "BEGIN POINTS.PNT MM\nNR  X        Y        Z\n"
              "0   +55      +55      +0\n[END]\n");
    fs::create_symlink("../outside/evil.D", root() / "dat.D");
    fs::create_symlink("../outside/evil.PNT", root() / "pat.PNT");
    writeFile(root() / "d1.H",
              "0 BEGIN PGM A MM\n1 SEL TABLE \"dat\"\n2 CYCL DEF 7.0 DATUM SHIFT\n"
              "3 CYCL DEF 7.1 #1\n4 L X+0 Y+0 FMAX\n5 END PGM A MM\n");
    writeFile(root() / "p1.H", "0 BEGIN PGM A MM\n1 SEL PATTERN \"pat\"\n2 END PGM A MM\n");
    for (const char* program : {"d1.H", "p1.H"}) {
        Result r = kerf(std::string("run root/") + program + " --trace -");
        EXPECT_EQ(r.exitCode, 1) << program;
        // Block 1 is on the file's line 2.
        EXPECT_NE(r.errors.find(std::string(program) + ":2:"), std::string::npos) << r.errors;
        EXPECT_NE(r.errors.find("outside the NC root"), std::string::npos) << r.errors;
    }
    // The same datum table as a file in the root shifts X and Y by 55.
    fs::remove(root() / "dat.D");
    fs::copy_file(outside() / "evil.D", root() / "dat.D");
    Result plain = kerf("run root/d1.H --trace -");
    EXPECT_EQ(plain.exitCode, 0) << plain.errors;
}

TEST_F(KerfFileAccess, FixedTableNamesMayNotLeadOutside) {
    writeFile(outside() / "TOOL.T",
              "BEGIN TOOL.T MM\nT    NAME   L       R\n"
              "1    MILL   +50     +5\n[END]\n");
    fs::create_symlink("../outside/TOOL.T", root() / "TOOL.T");
    writeFile(root() / "plain.H", "0 BEGIN PGM A MM\n1 L X+1 FMAX\n2 END PGM A MM\n");
    Result r = kerf("run root/plain.H");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.errors.find("outside the NC root"), std::string::npos) << r.errors;
    // Named on the command line it is the operator's choice, and is read.
    Result named = kerf("run root/plain.H --tool-table outside/TOOL.T");
    EXPECT_EQ(named.exitCode, 0) << named.errors;
}

// ---- nothing is written before the program has passed its check ------------------------------

TEST_F(KerfFileAccess, FagorOpenOfAProgramWithASyntaxErrorWritesNothing) {
    const std::string original = "%KEEP,,\nG01 X1 Z1\nM30\n";
    writeFile(root() / "P000123.PIM", original);
    const std::string body = "G00 X0 Z0\n(OPEN P123, D, \"GONE\")\n(WRITE M30)\nG01 X1 Z1 F100\n";
    writeFile(root() / "side.pim", body + "G01 X1 Z1 F100 QQQ\nM30\n");
    Result r = kerf("run root/side.pim --machine lathe");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(readFile(root() / "P000123.PIM"), original);
    // Without the error the program is replaced.
    writeFile(root() / "side.pim", body + "M30\n");
    Result good = kerf("run root/side.pim --machine lathe");
    EXPECT_EQ(good.exitCode, 0) << good.errors;
    EXPECT_EQ(readFile(root() / "P000123.PIM"), "%GONE,,\nM30\n");
}

TEST_F(KerfFileAccess, FPrintAndTabWriteOfAProgramWithASyntaxErrorWriteNothing) {
    writeFile(root() / "M.A", "\"VAL %5.2F\", Q1;\n");
    writeFile(root() / "out.txt", "ORIGINAL\n");
    const std::string table = "BEGIN T.TAB MM\nNR   X\n0    +0\n[END]\n";
    writeFile(root() / "T.TAB", table);
    auto program = [](const std::string& last) {
        return "0 BEGIN PGM A MM\n1 Q1 = 5\n2 FN 16: F-PRINT M.A / out.txt\n"
               "3 FN 26: TABOPEN T.TAB\n4 FN 27: TABWRITE 0 /\"X\" = Q1\n" +
               last + "6 END PGM A MM\n";
    };
    writeFile(root() / "side.H", program("5 L X+1 QQQ\n"));
    Result r = kerf("run root/side.H");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(readFile(root() / "out.txt"), "ORIGINAL\n");
    EXPECT_EQ(readFile(root() / "T.TAB"), table);
    // Without the error both files are written.
    writeFile(root() / "side.H", program("5 L X+1 FMAX\n"));
    Result good = kerf("run root/side.H");
    EXPECT_EQ(good.exitCode, 0) << good.errors;
    EXPECT_EQ(readFile(root() / "out.txt"), "VAL  5.00\n");
    EXPECT_NE(readFile(root() / "T.TAB"), table);
}

// ---- the running program (sigbus_truncate.sh) -----------------------------------------------

TEST_F(KerfFileAccess, OutputsRefuseToOverwriteWhatTheRunReads) {
    const std::string program = "0 BEGIN PGM A MM\n1 L X+10 Y+10 Z+0 R0 F1000\n2 END PGM A MM\n";
    writeFile(root() / "prog.H", program);
    const std::string tools =
        "BEGIN TOOL.T MM\nT    NAME   L       R\n1    MILL   +50     +5\n[END]\n";
    writeFile(root() / "TOOL.T", tools);
    for (const char* option : {"--trace root/prog.H", "--samples root/prog.H",
                               "--report root/../root/prog.H", "--png root/TOOL.T"}) {
        Result r = kerf(std::string("run root/prog.H ") + option);
        EXPECT_EQ(r.exitCode, 1) << option << "\n" << r.errors;
        EXPECT_NE(r.errors.find("which the run reads"), std::string::npos) << r.errors;
    }
    EXPECT_EQ(readFile(root() / "prog.H"), program);
    EXPECT_EQ(readFile(root() / "TOOL.T"), tools);
    Result ok = kerf("run root/prog.H --trace root/trace.txt");
    EXPECT_EQ(ok.exitCode, 0) << ok.errors;
    EXPECT_NE(readFile(root() / "trace.txt").find("X10"), std::string::npos);
}

// A program named only when the run reaches it (cycle 12) is not known when the outputs are
// checked; the run refuses to read a file it is writing instead of running it.
TEST_F(KerfFileAccess, AProgramCalledDuringTheRunUnderAnOutputsNameIsRefused) {
    writeFile(root() / "main.H",
              "0 BEGIN PGM MAIN MM\n1 CYCL DEF 12.0 PGM CALL\n2 CYCL DEF 12.1 PGM SUB.H\n"
              "3 L X+0 Y+0 Z+0 R0 FMAX\n4 CYCL CALL\n5 END PGM MAIN MM\n");
    const std::string sub = "0 BEGIN PGM SUB MM\n1 L X+7 R0 FMAX\n2 END PGM SUB MM\n";
    writeFile(root() / "SUB.H", sub);
    Result refused = kerf("run root/main.H --report root/SUB.H");
    EXPECT_EQ(refused.exitCode, 1) << refused.errors;
    EXPECT_NE(refused.errors.find("is an output of this run"), std::string::npos) << refused.errors;
    EXPECT_EQ(refused.errors.find("X+7"), std::string::npos);
    writeFile(root() / "SUB.H", sub);
    Result ok = kerf("run root/main.H --report root/report.json");
    EXPECT_EQ(ok.exitCode, 0) << ok.errors;
    EXPECT_NE(readFile(root() / "report.json").find("7"), std::string::npos);
}

TEST_F(KerfFileAccess, ProgramTruncatedWhileItRunsDoesNotCrash) {
    writeFile(root() / "loop.H",
              "0 BEGIN PGM L MM\n1 LBL 1\n2 L IX+0 FMAX\n"
              "3 FN 9: IF +0 EQU +0 GOTO LBL 1\n4 END PGM L MM\n");
    const fs::path trace = m_dir / "trace.txt";
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        const std::string program = (root() / "loop.H").string();
        ::execl(kerfBinary(), kerfBinary(), "run", program.c_str(), "--max-blocks", "100000000",
                "--trace", trace.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Truncate once the program runs: its trace has begun.
    auto traceBegun = [&] {
        std::error_code missing;
        const auto size = fs::file_size(trace, missing);
        return !missing && size > 0;
    };
    for (int i = 0; i < 1000 && !traceBegun(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(traceBegun());
    fs::resize_file(root() / "loop.H", 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    int status = 0;
    pid_t done = ::waitpid(child, &status, WNOHANG);
    if (done == 0) {
        // Still looping, as it should: the copy in memory is intact. Stop it.
        ::kill(child, SIGTERM);
        ::waitpid(child, &status, 0);
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
    } else {
        ADD_FAILURE() << "kerf ended early: "
                      << (WIFSIGNALED(status) ? "signal " + std::to_string(WTERMSIG(status))
                                              : "exit " + std::to_string(WEXITSTATUS(status)));
    }
}

TEST_F(KerfFileAccess, FagorProgramCannotOpenItselfUnderAnotherName) {
    fs::create_directories(root() / "fr");
    const std::string program =
        "G00 X0 Z0\n(OPEN P100, D, \"SELF\")\n(WRITE M30)\n"
        "G01 X10 Z-10 F100\nM30\n";
    writeFile(root() / "fr" / "P000100.PIM", program);
    Result r = kerf("run ./root/fr/../fr/P000100.PIM --machine lathe");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.errors.find("is running"), std::string::npos) << r.errors;
    EXPECT_EQ(readFile(root() / "fr" / "P000100.PIM"), program);
}

// ---- FIFOs, devices and folders (fifo_hang.sh) -----------------------------------------------

TEST_F(KerfFileAccess, FifosAreRefusedWithoutBlocking) {
    ASSERT_EQ(::mkfifo((root() / "fifo.H").c_str(), 0600), 0);
    Result check = kerf("check root/fifo.H");
    EXPECT_EQ(check.exitCode, 1);
    EXPECT_NE(check.errors.find("not a regular file"), std::string::npos) << check.errors;

    writeFile(root() / "call.H", "0 BEGIN PGM A MM\n1 CALL PGM fifo.H\n2 END PGM A MM\n");
    Result call = kerf("run root/call.H");
    EXPECT_EQ(call.exitCode, 1);
    EXPECT_NE(call.errors.find("call.H:2:"), std::string::npos) << call.errors;

    ASSERT_EQ(::mkfifo((root() / "TOOL.T").c_str(), 0600), 0);
    writeFile(root() / "plain.H", "0 BEGIN PGM A MM\n1 L X+1 FMAX\n2 END PGM A MM\n");
    Result tools = kerf("run root/plain.H");
    EXPECT_EQ(tools.exitCode, 1);
    EXPECT_NE(tools.errors.find("not a regular file"), std::string::npos) << tools.errors;

    fs::remove(root() / "TOOL.T");
    Result plain = kerf("run root/plain.H");
    EXPECT_EQ(plain.exitCode, 0) << plain.errors;
}

// Adversarial pass 2026-11-28: the touch-probe table was read as "no table, use the defaults"
// whenever reading failed, so a TCHPROBE.TP that is a link out of the root (or a FIFO) was
// silently replaced by default feeds and paths and the probing program ran to its end.
TEST_F(KerfFileAccess, AProbeTableThatCannotBeReadIsAnErrorNotTheDefaults) {
    fs::copy(fs::path(KERF_SOURCE_DIR) / "examples/probing", root());
    const std::string table = readFile(root() / "tchprobe.tp");
    fs::rename(root() / "tchprobe.tp", outside() / "tchprobe.tp");
    fs::create_symlink("../outside/tchprobe.tp", root() / "tchprobe.tp");
    const std::string preset = readFile(root() / "PRESET.PR");
    Result linked = kerf("run root/SETUP.H --machine root/machine.toml");
    EXPECT_EQ(linked.exitCode, 1) << linked.errors;
    // At the first probing cycle (block 5, line 6), naming the table.
    EXPECT_NE(linked.errors.find("SETUP.H:6:1: error: "), std::string::npos) << linked.errors;
    EXPECT_NE(linked.errors.find("tchprobe.tp' is outside the NC root"), std::string::npos)
        << linked.errors;
    EXPECT_EQ(readFile(root() / "PRESET.PR"), preset);  // the cycle wrote nothing
    EXPECT_EQ(readFile(outside() / "tchprobe.tp"), table);

    fs::remove(root() / "tchprobe.tp");
    ASSERT_EQ(::mkfifo((root() / "tchprobe.tp").c_str(), 0600), 0);
    Result fifo = kerf("run root/SETUP.H --machine root/machine.toml");
    EXPECT_EQ(fifo.exitCode, 1) << fifo.errors;
    EXPECT_NE(fifo.errors.find("not a regular file"), std::string::npos) << fifo.errors;

    // No table at all is the defaults of a new row, and the table itself is read as before.
    fs::remove(root() / "tchprobe.tp");
    Result none = kerf("run root/SETUP.H --machine root/machine.toml");
    EXPECT_EQ(none.exitCode, 0) << none.errors;
    writeFile(root() / "tchprobe.tp", table);
    Result plain = kerf("run root/SETUP.H --machine root/machine.toml");
    EXPECT_EQ(plain.exitCode, 0) << plain.errors;
    EXPECT_NE(readFile(root() / "PRESET.PR"), preset);  // the probed preset was written
}

}  // namespace
