// The machining cycles of older TNCs (1, 2, 3, 4, 5, 17) that shop programs still contain: each
// must do what the modern cycle it became does from the same start (docs/cycles.md), and the
// pockets' extent and depths are checked by hand.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/canon/trace_format.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"
#include "test_paths.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class Recorder : public canon::Sink {
public:
    void consume(const canon::Command& c) override { commands.push_back(c); }
    std::vector<canon::Command> commands;
};

class LegacyCycles : public testing::Test {
protected:
    void SetUp() override {
        dir = test::uniqueTempDir("legacy_cycles");
        machine = *machine::loadMachine("mill");
    }
    void TearDown() override { fs::remove_all(dir); }

    // Runs `body` after a tool of radius 3 at X50 Y40 Z+2 (the legacy cycles' start); the
    // commands of its CYCL CALL block (block number `callBlock`).
    std::vector<canon::Command> run(const std::string& body, int64_t callBlock,
                                    std::string* error = nullptr) {
        const std::string text =
            "0 BEGIN PGM P MM\n1 TOOL DEF 1 L+0 R+3\n2 TOOL CALL 1 Z S3000\n"
            "3 L X+50 Y+40 Z+2 R0 FMAX M3\n" +
            body + "99 END PGM P MM\n";
        writeFileAtomically(dir / "P.H", text);
        program::SourceRegistry sources;
        KlartextSettings settings;
        settings.machine = &machine;
        settings.ncRoot = dir;
        settings.remanentFile = dir / "qr.txt";
        KlartextInterpreter k(sources, settings);
        Recorder out;
        if (k.load(dir / "P.H")) {
            for (;;) {
                auto status = k.run(out, 1000);
                if (status == interp::RunStatus::NeedsSync) {
                    interp::WorldSnapshot w;
                    w.position = k.nominalPosition();
                    k.resume(w);
                    continue;
                }
                if (status != interp::RunStatus::BudgetUsed) break;
            }
        }
        if (error && hasErrors(k.diagnostics())) *error = k.diagnostics().front().format();
        std::vector<canon::Command> called;
        for (const canon::Command& c : out.commands) {
            if (c.location.blockNumber == callBlock) called.push_back(c);
        }
        return called;
    }
    // The commands as trace text without their block positions.
    static std::string trace(const std::vector<canon::Command>& commands) {
        std::string all;
        for (const canon::Command& c : commands) {
            std::string line;
            canon::appendCommand(line, c, canon::TraceFormat{});
            const size_t second = line.find(' ', line.find(' ') + 1);
            all += line.substr(second + 1) + "\n";
        }
        return all;
    }

    fs::path dir;
    machine::MachineConfig machine;
};

// Extent of the feed moves' end points and arcs around the start X50 Y40.
struct Extent {
    double minZ = 1e9, maxRadius = 0.0;
};
Extent extentOf(const std::vector<canon::Command>& commands) {
    Extent e;
    for (const canon::Command& c : commands) {
        const Pose* target = nullptr;
        if (const auto* l = std::get_if<canon::LinearMove>(&c.body)) target = &l->target;
        if (const auto* a = std::get_if<canon::ArcMove>(&c.body)) target = &a->target;
        if (target == nullptr) continue;
        e.minZ = std::min(e.minZ, target->values[2]);
        e.maxRadius =
            std::max(e.maxRadius, std::hypot(target->values[0] - 50.0, target->values[1] - 40.0));
    }
    return e;
}

TEST_F(LegacyCycles, CircularPocketRoughsLikeCycle252FromTheStart) {
    // German keywords, decimal comma, negative set-up clearance and infeed as old programs
    // write them: surface Z0 (2 below the start), 6 deep in infeeds of 2.5, radius 15, DR+.
    const auto legacy =
        run("4 CYCL DEF 5.0 KREISTASCHE\n5 CYCL DEF 5.1 ABST-2\n"
            "6 CYCL DEF 5.2 TIEFE-6\n7 CYCL DEF 5.3 ZUSTLG-2,5 F80\n"
            "8 CYCL DEF 5.4 RADIUS15\n9 CYCL DEF 5.5 F400 DR+\n10 CYCL CALL\n",
            10);
    const auto modern =
        run("4 CYCL DEF 252 CIRCULAR POCKET\n  Q215=1\n  Q223=30\n  Q368=0\n  Q207=400\n"
            "  Q351=+1\n  Q201=-6\n  Q202=2.5\n  Q369=0\n  Q206=80\n  Q338=0\n  Q200=2\n"
            "  Q203=+0\n  Q204=0\n  Q370=1\n  Q366=0\n  Q385=400\n  Q439=0\n5 CYCL CALL\n",
            5);
    ASSERT_FALSE(legacy.empty());
    EXPECT_EQ(trace(legacy), trace(modern));
    // By hand: the bottom at Z-6, the wall reached by the tool's centre at 15 - 3 = 12.
    const Extent e = extentOf(legacy);
    EXPECT_NEAR(e.minZ, -6.0, 1e-9);
    EXPECT_NEAR(e.maxRadius, 12.0, 1e-6);
}

TEST_F(LegacyCycles, PocketMillingRoughsLikeCycle251CentredOnTheStart) {
    const auto legacy =
        run("4 CYCL DEF 4.0 POCKET MILLING\n5 CYCL DEF 4.1 SET UP 2\n"
            "6 CYCL DEF 4.2 DEPTH -5\n7 CYCL DEF 4.3 PECKG 5 F100\n"
            "8 CYCL DEF 4.4 X+40\n9 CYCL DEF 4.5 Y+20\n"
            "10 CYCL DEF 4.6 F300 DR- RADIUS 4\n11 CYCL CALL\n",
            11);
    const auto modern =
        run("4 CYCL DEF 251 RECTANGULAR POCKET\n  Q215=1\n  Q218=40\n  Q219=20\n  Q220=4\n"
            "  Q368=0\n  Q224=0\n  Q367=0\n  Q207=300\n  Q351=-1\n  Q201=-5\n  Q202=5\n  Q369=0\n"
            "  Q206=100\n  Q338=0\n  Q200=2\n  Q203=+0\n  Q204=0\n  Q370=1\n  Q366=0\n  Q385=300\n"
            "  Q439=0\n5 CYCL CALL\n",
            5);
    ASSERT_FALSE(legacy.empty());
    EXPECT_EQ(trace(legacy), trace(modern));
    // By hand: the tool's centre stays within X50±17, Y40±7 (sides minus the radius 3).
    for (const canon::Command& c : legacy) {
        if (const auto* l = std::get_if<canon::LinearMove>(&c.body)) {
            EXPECT_LE(std::fabs(l->target.values[0] - 50.0), 17.0 + 1e-9);
            EXPECT_LE(std::fabs(l->target.values[1] - 40.0), 7.0 + 1e-9);
        }
    }
    EXPECT_NEAR(extentOf(legacy).minZ, -5.0, 1e-9);
}

TEST_F(LegacyCycles, TappingCyclesRunAsTheirModernForms) {
    const auto tapping =
        run("4 CYCL DEF 2.0 TAPPING\n5 CYCL DEF 2.1 SET UP 2\n"
            "6 CYCL DEF 2.2 DEPTH -15\n7 CYCL DEF 2.3 DWELL 0.4\n"
            "8 CYCL DEF 2.4 F150\n9 CYCL CALL\n",
            9);
    const auto tapping206 =
        run("4 CYCL DEF 206 TAPPING\n  Q200=2\n  Q201=-15\n  Q206=150\n"
            "  Q211=0.4\n  Q203=+0\n  Q204=0\n5 CYCL CALL\n",
            5);
    ASSERT_FALSE(tapping.empty());
    EXPECT_EQ(trace(tapping), trace(tapping206));
    const auto rigid =
        run("4 CYCL DEF 17.0 RIGID TAPPING\n5 CYCL DEF 17.1 SET UP 2\n"
            "6 CYCL DEF 17.2 DEPTH -15\n7 CYCL DEF 17.3 PITCH +1,25\n"
            "8 CYCL CALL\n",
            8);
    const auto rigid207 =
        run("4 CYCL DEF 207 RIGID TAPPING\n  Q200=2\n  Q201=-15\n"
            "  Q239=+1.25\n  Q203=+0\n  Q204=0\n5 CYCL CALL\n",
            5);
    ASSERT_FALSE(rigid.empty());
    EXPECT_EQ(trace(rigid), trace(rigid207));
}

// Cycle 3 from X50 Y40 Z+2 with R3: a slot 30 long (+X), 10 wide, 4 deep in one infeed.
// Allowance a = 5 - 3 = 2, tool-centre far end E = 30 - 6 = 24. By hand: rapid to X52; down
// to Z-4 at F50; to X72 (E - a) at F200; half circle CCW about X73 onto X74; X74 Y42, X50 Y42,
// X50 Y38, X74 Y38, X74 Y40; half circle back to X72; up to Z2; one infeed (odd): back to X50.
TEST_F(LegacyCycles, SlotMillingRoughsAlongTheMiddleThenFinishesRoundTheWall) {
    const auto slot =
        run("4 CYCL DEF 3.0 SLOT MILLING\n5 CYCL DEF 3.1 SET UP 2\n6 CYCL DEF 3.2 DEPTH -4\n"
            "7 CYCL DEF 3.3 PECKG 5 F50\n8 CYCL DEF 3.4 X+30\n9 CYCL DEF 3.5 Y+10\n"
            "10 CYCL DEF 3.6 F200\n11 CYCL CALL\n",
            11);
    EXPECT_EQ(
        trace(slot),
        "RAPID X52.0000 Y40.0000 Z2.0000\n"
        "LINE X52.0000 Y40.0000 Z-4.0000 F50.000\n"
        "LINE X72.0000 Y40.0000 Z-4.0000 F200.000\n"
        "ARC X74.0000 Y40.0000 Z-4.0000 CENTER X73.0000 Y40.0000 PLANE XY SWEEP 180.0000 F200.000\n"
        "LINE X74.0000 Y42.0000 Z-4.0000 F200.000\n"
        "LINE X50.0000 Y42.0000 Z-4.0000 F200.000\n"
        "LINE X50.0000 Y38.0000 Z-4.0000 F200.000\n"
        "LINE X74.0000 Y38.0000 Z-4.0000 F200.000\n"
        "LINE X74.0000 Y40.0000 Z-4.0000 F200.000\n"
        "ARC X72.0000 Y40.0000 Z-4.0000 CENTER X73.0000 Y40.0000 PLANE XY SWEEP 180.0000 F200.000\n"
        "RAPID X72.0000 Y40.0000 Z2.0000\n"
        "RAPID X50.0000 Y40.0000 Z2.0000\n");
    std::string error;
    run("4 CYCL DEF 3.0 SLOT MILLING\n5 CYCL DEF 3.1 SET UP 2\n6 CYCL DEF 3.2 DEPTH -4\n"
        "7 CYCL DEF 3.3 PECKG 5\n8 CYCL DEF 3.4 X+30\n9 CYCL DEF 3.5 Y+5\n"
        "10 CYCL DEF 3.6 F200\n11 CYCL CALL\n",
        11, &error);
    EXPECT_NE(error.find("cycle 3: the tool is too large"), std::string::npos) << error;
    error.clear();
    run("4 CYCL DEF 3.0 SLOT MILLING\n5 CYCL DEF 3.1 SET UP 2\n6 CYCL DEF 3.2 DEPTH -4\n"
        "7 CYCL DEF 3.3 PECKG 5\n8 CYCL DEF 3.4 X+30\n9 CYCL DEF 3.5 Y+13\n"
        "10 CYCL DEF 3.6 F200\n11 CYCL CALL\n",
        11, &error);
    EXPECT_NE(error.find("at least half the slot width"), std::string::npos) << error;
}

TEST_F(LegacyCycles, AMissingValueIsAnErrorAtItsSubBlock) {
    std::string error;
    run("4 CYCL DEF 1.0 PECKING\n5 CYCL DEF 1.1 SET UP 2\n6 CYCL DEF 1.2 DEPTH\n", 0, &error);
    EXPECT_NE(error.find(":7:"), std::string::npos) << error;  // file line 7 is block 6
    EXPECT_NE(error.find("cycle 1: DEPTH expected in 1.2"), std::string::npos) << error;

    // An error of the modern cycle names the cycle the program wrote.
    error.clear();
    run("4 TOOL DEF 2 L+0 R+0\n5 TOOL CALL 2 Z S3000\n6 CYCL DEF 5.0 CIRCULAR POCKET\n"
        "7 CYCL DEF 5.1 SET UP 2\n8 CYCL DEF 5.2 DEPTH -6\n9 CYCL DEF 5.3 PECKG 2\n"
        "10 CYCL DEF 5.4 RADIUS 15\n11 CYCL DEF 5.5 F400 DR+\n12 CYCL CALL\n",
        0, &error);
    EXPECT_NE(error.find("cycle 5 needs a tool"), std::string::npos) << error;
}

}  // namespace
}  // namespace kerf::klartext
