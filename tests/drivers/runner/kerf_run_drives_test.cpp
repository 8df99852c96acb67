// `kerf run --drives can-sim`: the whole chain from the command line. A program ends where it
// ends without drives (within the drives' resolution), every injected fault stops the run with
// ok: false, exit code 1 and a diagnostic naming node and fault, and the CAN trace is a candump
// log with the boot and the cyclic traffic.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

namespace {

namespace fs = std::filesystem;

// Starts at X0 Y0 Z0; about 6 s of motion: long enough for faults injected in the middle.
constexpr const char* kProgram =
    "0 BEGIN PGM DRIVES MM\n"
    "1 L X+10 Y+5 Z+2 R0 FMAX\n"
    "2 L Z-2 F600\n"
    "3 L X+40 F1200\n"
    "4 CC X+40 Y+15\n"
    "5 C X+40 Y+25 DR+ F1200\n"
    "6 L X+30 Y-20 Z-5 F1500\n"
    "7 L Z+10 FMAX\n"
    "8 END PGM DRIVES MM\n";

// One count of the built-in mill's drives is 1e-4 mm; the chain stops within 1.5 counts.
constexpr double kResolutionMm = 2e-4;

struct KerfResult {
    int exitCode = -1;
    nlohmann::json report;
    std::string errors;
};

class KerfRunDrives : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::path(testing::TempDir()) /
                ("kerf_drives_" +
                 std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(m_dir);
        std::ofstream(m_dir / "drives.H") << kProgram;
    }
    void TearDown() override { fs::remove_all(m_dir); }

    KerfResult run(const std::string& arguments, const char* program = "drives.H") const {
        const fs::path report = m_dir / "report.json";
        const fs::path errors = m_dir / "errors.txt";
        fs::remove(report);
        const std::string command = std::string("\"") + KERF_BINARY + "\" run \"" +
                                    (m_dir / program).string() + "\" --report \"" +
                                    report.string() + "\" " + arguments + " 2> \"" +
                                    errors.string() + "\"";
        KerfResult r;
        const int status = std::system(command.c_str());
        r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        std::ifstream in(report);
        if (in) r.report = nlohmann::json::parse(in, nullptr, false);
        std::stringstream text;
        text << std::ifstream(errors).rdbuf();
        r.errors = text.str();
        return r;
    }

    fs::path m_dir;
};

TEST_F(KerfRunDrives, EndsWhereTheProgramEndsWithoutDrives) {
    KerfResult plain = run("");
    KerfResult can = run("--drives can-sim");
    ASSERT_EQ(plain.exitCode, 0) << plain.errors;
    ASSERT_EQ(can.exitCode, 0) << can.errors;
    EXPECT_TRUE(can.report["ok"].get<bool>());
    // The program's last point is X+30 Y-20 Z+10.
    const nlohmann::json& end = can.report["final_position"];
    EXPECT_NEAR(end["X"].get<double>(), 30.0, kResolutionMm);
    EXPECT_NEAR(end["Y"].get<double>(), -20.0, kResolutionMm);
    EXPECT_NEAR(end["Z"].get<double>(), 10.0, kResolutionMm);
    for (const char* axis : {"X", "Y", "Z"}) {
        EXPECT_NEAR(end[axis].get<double>(), plain.report["final_position"][axis].get<double>(),
                    kResolutionMm)
            << axis;
    }
    const nlohmann::json& drives = can.report["drives"];
    EXPECT_EQ(drives["kind"], "can-sim");
    EXPECT_FALSE(drives["stopped"].get<bool>());
    EXPECT_EQ(drives["programmed_final_position"], plain.report["final_position"]);
    // Rapids at 500 mm/s behind a few ms of bus dead time: a few mm at most.
    EXPECT_GT(drives["max_following_error_mm"].get<double>(), 0.0);
    EXPECT_LT(drives["max_following_error_mm"].get<double>(), 3.0);
    // 4 nodes at 1 Mbit/s and 2 ms carry 40-49 % (docs/machine-config.md); boot SDOs add little.
    EXPECT_GT(drives["bus_load_percent"].get<double>(), 30.0);
    EXPECT_LT(drives["bus_load_percent"].get<double>(), 60.0);
    EXPECT_EQ(can.report["blocks_executed"], plain.report["blocks_executed"]);
}

struct FaultCase {
    const char* spec;
    const char* node;   // "CAN node N"
    const char* cause;  // a word of the cause in the diagnostic
};

TEST_F(KerfRunDrives, EveryInjectedFaultStopsTheRunNamingNodeAndFault) {
    // The boot ends about 50 ms after power-on; the program then runs for about 6 s.
    for (const FaultCase& f :
         {FaultCase{"2:heartbeat@3", "CAN node 2 (axis Y)", "heartbeat"},
          FaultCase{"1:emcy@3", "CAN node 1 (axis X)", "EMCY"},
          FaultCase{"3:following-error@3", "CAN node 3 (axis Z)", "following error"},
          FaultCase{"4:heartbeat@3", "CAN node 4 (spindle)", "heartbeat"}}) {
        SCOPED_TRACE(f.spec);
        KerfResult r = run(std::string("--drives can-sim --inject-fault ") + f.spec);
        EXPECT_EQ(r.exitCode, 1);
        ASSERT_TRUE(r.report.is_object()) << r.errors;
        EXPECT_FALSE(r.report["ok"].get<bool>());
        EXPECT_TRUE(r.report["drives"]["stopped"].get<bool>());
        // file:line: error: CAN node ... at the block that was running.
        const std::string expected = "drives.H:";
        EXPECT_NE(r.errors.find(expected), std::string::npos) << r.errors;
        EXPECT_NE(r.errors.find(std::string("error: ") + f.node), std::string::npos) << r.errors;
        EXPECT_NE(r.errors.find(f.cause), std::string::npos) << r.errors;
        EXPECT_NE(r.errors.find("every drive was quick-stopped"), std::string::npos) << r.errors;
        // Stopped on the way: not at the end point X+30 Y-20 Z+10.
        const nlohmann::json& end = r.report["final_position"];
        const double dx = end["X"].get<double>() - 30.0;
        const double dy = end["Y"].get<double>() + 20.0;
        const double dz = end["Z"].get<double>() - 10.0;
        EXPECT_GT(dx * dx + dy * dy + dz * dz, 1.0);
        // Every drive came to rest under its quick stop, and the report says where.
        const nlohmann::json& stop = r.report["drives"]["stop"];
        ASSERT_TRUE(stop.is_object()) << r.report.dump(2);
        EXPECT_TRUE(stop["all_at_rest"].get<bool>()) << stop.dump(2);
        for (const char* drive : {"X", "Y", "Z", "S"})
            EXPECT_EQ(stop["drives"][drive]["state"], "at rest") << drive;
        // The tip moved on from where the stop went out by the stopping distance.
        double squared = 0.0;
        for (const char* axis : {"X", "Y", "Z"}) {
            const double d = end[axis].get<double>() - stop["position_at_stop"][axis].get<double>();
            squared += d * d;
        }
        EXPECT_NEAR(std::sqrt(squared), stop["stopping_distance_mm"].get<double>(), 1e-5);
        // At most 25 mm/s here (feeds of 1500 mm/min, a 1 mm following error): v^2 / 2a with
        // 2000 mm/s^2 is 0.16 mm per axis.
        EXPECT_LT(stop["stopping_distance_mm"].get<double>(), 0.5);
        EXPECT_GT(stop["rest_after_s"].get<double>(), 0.0);
        EXPECT_LT(stop["rest_after_s"].get<double>(), stop["limit_s"].get<double>());
    }
}

// During the first rapid (X+10 Y+5 Z+2 from the origin, about 20 ms after the boot) a rapid
// cannot stop at once: the stop is in the report, the final position is where the axes came to
// rest, beyond the point where the stop went out.
TEST_F(KerfRunDrives, FaultDuringARapidReportsWhereTheAxesCameToRest) {
    KerfResult r = run("--drives can-sim --inject-fault 3:emcy@0.075");
    EXPECT_EQ(r.exitCode, 1);
    ASSERT_TRUE(r.report.is_object()) << r.errors;
    const nlohmann::json& stop = r.report["drives"]["stop"];
    ASSERT_TRUE(stop.is_object()) << r.report.dump(2);
    EXPECT_TRUE(stop["all_at_rest"].get<bool>());
    EXPECT_GT(stop["stopping_distance_mm"].get<double>(), 0.01);
    const nlohmann::json& end = r.report["final_position"];
    EXPECT_NE(end["X"].get<double>(), stop["position_at_stop"]["X"].get<double>());
    EXPECT_GT(stop["drives"]["X"]["travel"].get<double>(), 0.0);
}

// Error passive still delivers every frame: a warning, the program runs to its end.
TEST_F(KerfRunDrives, ErrorPassiveNodeWarnsAndTheRunGoesOn) {
    KerfResult r = run("--drives can-sim --inject-fault 2:error-passive@3");
    EXPECT_EQ(r.exitCode, 0) << r.errors;
    ASSERT_TRUE(r.report.is_object()) << r.errors;
    EXPECT_TRUE(r.report["ok"].get<bool>());
    EXPECT_FALSE(r.report["drives"]["stopped"].get<bool>());
    EXPECT_NE(r.errors.find("warning: CAN node 2 (axis Y): warning: EMCY 0x8120"),
              std::string::npos)
        << r.errors;
    EXPECT_NEAR(r.report["final_position"]["Y"].get<double>(), -20.0, kResolutionMm);
}

// The soft-limit check runs over the whole program before anything moves, as with --motion.
TEST_F(KerfRunDrives, RefusedBlockStopsTheRunBeforeAnythingMoves) {
    // The mill's Z ends at +50 (machine coordinates): block 2 is refused, nothing moves.
    std::ofstream(m_dir / "refused.H") << "0 BEGIN PGM REFUSED MM\n"
                                          "1 L X+10 Y+5 Z+2 R0 FMAX\n"
                                          "2 L Z+500 FMAX\n"
                                          "3 L X+20 F500\n"
                                          "4 END PGM REFUSED MM\n";
    KerfResult r = run("--drives can-sim", "refused.H");
    EXPECT_EQ(r.exitCode, 1);
    ASSERT_TRUE(r.report.is_object()) << r.errors;
    EXPECT_FALSE(r.report["ok"].get<bool>());
    EXPECT_TRUE(r.report["drives"]["refused"].get<bool>());
    EXPECT_FALSE(r.report["drives"]["stopped"].get<bool>());
    EXPECT_NE(r.errors.find("refused.H:3:"), std::string::npos) << r.errors;
    EXPECT_NE(r.errors.find("soft limit"), std::string::npos) << r.errors;
    const nlohmann::json& end = r.report["final_position"];
    for (const char* axis : {"X", "Y", "Z"})
        EXPECT_NEAR(end[axis].get<double>(), 0.0, kResolutionMm) << axis;
    EXPECT_LT(r.report["drives"]["simulated_time_s"].get<double>(), 0.01);
}

// The reproducer: 30 s of slow feed to Z-498, then a move to Z-550 below the mill's Z limit
// (-500). Refused at once, not after the feed has run. --work-offset Z0: the workpiece origin at
// the machine origin (the mill's own preset is Z-400), so the program's Z is the machine's.
TEST_F(KerfRunDrives, SoftLimitIsCheckedBeforeALongFeedRuns) {
    std::ofstream(m_dir / "deep.H") << "0 BEGIN PGM DEEP MM\n"
                                       "1 L Z-498 R0 F1000\n"
                                       "2 L Z-550\n"
                                       "3 END PGM DEEP MM\n";
    KerfResult r = run("--drives can-sim --work-offset Z0", "deep.H");
    EXPECT_EQ(r.exitCode, 1);
    ASSERT_TRUE(r.report.is_object()) << r.errors;
    EXPECT_TRUE(r.report["drives"]["refused"].get<bool>());
    EXPECT_NE(r.errors.find("deep.H:3:"), std::string::npos) << r.errors;
    EXPECT_LT(r.report["drives"]["simulated_time_s"].get<double>(), 0.01);
    EXPECT_NEAR(r.report["final_position"]["Z"].get<double>(), 0.0, kResolutionMm);
}

// Issue 13 part 4: the drive simulation has a simulated-time limit (--max-drive-time).
TEST_F(KerfRunDrives, SimulatedTimeLimitEndsALongRun) {
    std::ofstream(m_dir / "slow.H") << "0 BEGIN PGM SLOW MM\n"
                                       "1 L X+300 R0 F60\n"
                                       "2 END PGM SLOW MM\n";
    KerfResult r = run("--drives can-sim --max-drive-time 2", "slow.H");
    EXPECT_EQ(r.exitCode, 1);
    ASSERT_TRUE(r.report.is_object()) << r.errors;
    EXPECT_TRUE(r.report["drives"]["time_limit"].get<bool>());
    EXPECT_NE(r.errors.find("limit of 2 s of simulated time"), std::string::npos) << r.errors;
    // 2 s at 1 mm/s.
    EXPECT_NEAR(r.report["final_position"]["X"].get<double>(), 2.0, 0.1);
    EXPECT_EQ(run("--drives can-sim --max-drive-time 0", "slow.H").exitCode, 2);
}

// A drive scale so coarse (1 count = 1 m) that no axis can reach its end point: the run ends
// with an error at once instead of waiting for a simulated day.
TEST_F(KerfRunDrives, CoarseDriveScaleEndsWithAnInPositionError) {
    std::ofstream(m_dir / "coarse.toml") << "base = \"mill\"\n"
                                            "[axes.X]\n"
                                            "drive_scale = 0.001\n";
    KerfResult r = run("--drives can-sim --machine \"" + (m_dir / "coarse.toml").string() + "\"");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.errors.find("axis X did not reach its end point"), std::string::npos) << r.errors;
    ASSERT_TRUE(r.report.is_object()) << r.errors;
    EXPECT_LT(r.report["drives"]["simulated_time_s"].get<double>(), 10.0);
}

TEST_F(KerfRunDrives, BootFaultStopsBeforeTheFirstBlock) {
    KerfResult r = run("--drives can-sim --inject-fault 3:identity@0");
    EXPECT_EQ(r.exitCode, 1);
    ASSERT_TRUE(r.report.is_object()) << r.errors;
    EXPECT_FALSE(r.report["ok"].get<bool>());
    EXPECT_EQ(r.report["blocks_executed"], 0);
    EXPECT_NE(r.errors.find("CAN node 3"), std::string::npos) << r.errors;
    EXPECT_NE(r.errors.find("1018"), std::string::npos) << r.errors;
}

TEST_F(KerfRunDrives, TraceIsACandumpLogWithBootSyncAndPdos) {
    const fs::path trace = m_dir / "can.log";
    KerfResult r = run("--drives can-sim --can-trace \"" + trace.string() + "\"");
    ASSERT_EQ(r.exitCode, 0) << r.errors;
    std::ifstream in(trace);
    ASSERT_TRUE(in);
    const std::regex line(R"(\(\d+\.\d{6}\) can0 ([0-9A-F]{3})#([0-9A-F]{2})*)");
    std::string text;
    int lines = 0;
    bool nmtStart = false, sdoRequest = false, sdoResponse = false, sync = false, rpdo = false,
         tpdo = false, heartbeat = false;
    while (std::getline(in, text)) {
        std::smatch m;
        ASSERT_TRUE(std::regex_match(text, m, line)) << text;
        ++lines;
        const int id = std::stoi(m[1].str(), nullptr, 16);
        const std::string data = text.substr(text.find('#') + 1);
        nmtStart = nmtStart || (id == 0x000 && data.rfind("01", 0) == 0);  // start remote node
        sdoRequest = sdoRequest || (id >= 0x601 && id <= 0x67F);
        sdoResponse = sdoResponse || (id >= 0x581 && id <= 0x5FF);
        sync = sync || id == 0x080;
        rpdo = rpdo || (id >= 0x201 && id <= 0x27F);
        tpdo = tpdo || (id >= 0x181 && id <= 0x1FF);
        heartbeat = heartbeat || (id >= 0x701 && id <= 0x77F);
    }
    EXPECT_TRUE(nmtStart && sdoRequest && sdoResponse && sync && rpdo && tpdo && heartbeat);
    // At least one SYNC per 2 ms over the ~7 s of boot and program.
    EXPECT_GT(lines, 3000);
}

TEST_F(KerfRunDrives, BadDriveOptionsAreUsageErrors) {
    EXPECT_EQ(run("--drives can-sim --inject-fault 2:melt@1").exitCode, 2);
    EXPECT_EQ(run("--inject-fault 2:heartbeat@1").exitCode, 2);
    EXPECT_EQ(run("--drives socketcan").exitCode, 2);
    KerfResult unknownNode = run("--drives can-sim --inject-fault 9:heartbeat@1");
    EXPECT_EQ(unknownNode.exitCode, 1);
    EXPECT_NE(unknownNode.errors.find("node 9"), std::string::npos) << unknownNode.errors;
}

}  // namespace
