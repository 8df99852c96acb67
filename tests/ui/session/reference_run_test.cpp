// The reference run through the session, as on a real control: at power-on the axes are not
// referenced, programs and MDI are refused, jog is allowed; Home all takes Z up to its home first
// and leaves every axis at its home in machine coordinates; then programs run.
#include <QSignalSpy>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/session/machine_session.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;

constexpr const char* kProgram =
    "0 BEGIN PGM P MM\n"
    "1 L X+10 Y+10 Z+250 R0 FMAX\n"
    "2 END PGM P MM\n";

bool serviceUntil(MachineSession& session, const std::function<bool()>& done,
                  std::chrono::milliseconds limit = 60s) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        session.service();
        if (done()) return true;
        std::this_thread::sleep_for(2ms);
    }
    return false;
}

bool anyMessageContains(const QSignalSpy& messages, const QString& part) {
    for (const QList<QVariant>& m : messages)
        if (m.at(1).toString().contains(part)) return true;
    return false;
}

const task::AxisStatus& axis(const MachineSession& session, Axis a) {
    return session.status().axes[static_cast<size_t>(axisIndex(a))];
}

TEST(ReferenceRun, ProgramsWaitForHomeAllWhichLeavesTheAxesAtTheirHomes) {
    test::testApp();
    const machine::MachineConfig config = *machine::loadMachine("mill");
    MachineSession session(config, test::connectSimulatedMachine(config, test::Reference::Required),
                           "");
    QSignalSpy messages(&session, &MachineSession::message);
    // The servo thread's first status.
    ASSERT_TRUE(serviceUntil(session, [&] { return session.status().servoTimeS > 0.01; }));
    EXPECT_FALSE(session.referenced());
    // Power-on: the axes stand at their homes, machine 0 0 0; the mill's preset puts the
    // workpiece origin 400 mm below, so the tip shows Z+400.
    EXPECT_NEAR(axis(session, Axis::Z).machineActual, 0.0, 1e-6);
    EXPECT_NEAR(axis(session, Axis::Z).actual, 400.0, 1e-6);

    EXPECT_FALSE(session.startProgram(kProgram, "P.H"));
    EXPECT_FALSE(session.executeMdi("L X+10 FMAX"));
    EXPECT_TRUE(anyMessageContains(messages, "not referenced"));

    // Jog works before homing (down 2 mm; Home all brings it back up).
    session.setIncrementMm(2.0);
    ASSERT_TRUE(session.jogIncrement(Axis::Z, -1));
    ASSERT_TRUE(serviceUntil(session, [&] {
        return axis(session, Axis::Z).machineNominal < -1.9999 &&
               session.status().state == task::MachineState::Idle;
    }));

    ASSERT_TRUE(session.homeAll());
    ASSERT_TRUE(serviceUntil(
        session, [&] { return session.referenced(); }, 20s));
    ASSERT_TRUE(serviceUntil(
        session, [&] { return session.status().state == task::MachineState::Idle; }, 5s));
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
        // home = 0 on every axis of the built-in mill: the switch is read once per period.
        EXPECT_NEAR(axis(session, a).machineActual, 0.0, 0.05) << axisLetter(a);
    }

    ASSERT_TRUE(session.startProgram(kProgram, "P.H"));
    ASSERT_TRUE(serviceUntil(session, [&] { return !session.busy(); }));
    EXPECT_EQ(session.runState(), task::RunState::Finished);
    EXPECT_NEAR(axis(session, Axis::Z).nominal, 250.0, 1e-6);
}

TEST(ReferenceRun, TheCycle200SeedRunsAfterHomeAllOnTheBuiltInMill) {
    // The seed's L Z+250 clearance with its 80 mm drill is machine Z -70 with the mill's preset
    // Z-400 (inside -500 ... +50); before, it was refused as machine Z 330.
    test::testApp();
    namespace fs = std::filesystem;
    const fs::path seed =
        fs::path(KERF_SOURCE_DIR) / "tests/golden/klartext/cycle_200_drilling_m99";
    const fs::path root = kerf::test::uniqueTempDir("hmi_c200");
    fs::copy_file(seed / "TOOL.T", root / "TOOL.T", fs::copy_options::overwrite_existing);
    std::stringstream program;
    program << std::ifstream(seed / "program.H").rdbuf();
    const machine::MachineConfig config = *machine::loadMachine("mill");
    MachineSession session(config, test::connectSimulatedMachine(config, test::Reference::Required),
                           root);
    ASSERT_TRUE(serviceUntil(session, [&] { return session.status().servoTimeS > 0.01; }));
    ASSERT_TRUE(session.homeAll());
    ASSERT_TRUE(serviceUntil(
        session, [&] { return session.referenced(); }, 20s));
    ASSERT_TRUE(serviceUntil(
        session, [&] { return session.status().state == task::MachineState::Idle; }, 5s));
    ASSERT_TRUE(session.startProgram(QString::fromStdString(program.str()), root / "C200.H"));
    // Four holes of 15 mm at 250 mm/min and the rapids: about 20 s.
    ASSERT_TRUE(serviceUntil(
        session, [&] { return !session.busy(); }, 120s));
    EXPECT_EQ(session.runState(), task::RunState::Finished);
    EXPECT_NEAR(axis(session, Axis::Z).nominal, 250.0, 1e-6);
    EXPECT_NEAR(axis(session, Axis::Z).machineNominal, -70.0, 1e-6);
}

TEST(ReferenceRun, AMachineFileMayRunWithoutHoming) {
    test::testApp();
    auto config = machine::parseMachine("base = \"mill\"\nreference_required = false\n", "m.toml");
    ASSERT_TRUE(config) << "the option parses";
    MachineSession session(*config,
                           test::connectSimulatedMachine(*config, test::Reference::Required), "");
    ASSERT_TRUE(serviceUntil(session, [&] { return session.status().servoTimeS > 0.01; }));
    EXPECT_TRUE(session.referenced());
    ASSERT_TRUE(session.startProgram(kProgram, "P.H"));
    ASSERT_TRUE(serviceUntil(session, [&] { return !session.busy(); }));
    EXPECT_EQ(session.runState(), task::RunState::Finished);
}

}  // namespace
}  // namespace kerf::ui
