// Manual operation beyond jogging (set a preset by entry, the handwheel, coolant), the shifted
// workpiece origin under it, and the machine file's origin and probe box on the HMI's machine.
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "core/tables/preset_table.h"
#include "core/task/shifted_motion_port.h"
#include "qt_test_app.h"
#include "session_service.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/session/machine_session.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;
using task::RunState;

// Records what reaches the machine; reports a fixed position.
class RecordingPort : public task::MotionPort {
public:
    std::vector<canon::Command>* submitted = nullptr;
    interp::WorldSnapshot snapshot;

    bool submit(const canon::Command& command) override {
        submitted->push_back(command);
        return true;
    }
    bool hasRoom() const override { return true; }
    void flush() override {}
    void pump() override {}
    bool drained() const override { return true; }
    interp::WorldSnapshot world() const override { return snapshot; }
    Progress progress() const override { return {}; }
    void cycleStart() override {}
    void feedHold() override {}
    void quickStop() override {}
    void setSingleBlock(bool) override {}
};

TEST(ShiftedMotionPort, TargetsGainTheShiftAndPositionsLoseIt) {
    std::vector<canon::Command> submitted;
    auto recording = std::make_unique<RecordingPort>();
    recording->submitted = &submitted;
    recording->snapshot.position[Axis::X] = 13.0;
    recording->snapshot.position[Axis::Z] = -7.0;
    task::ShiftedMotionPort port(std::move(recording));
    // The operator's origin lies 3 mm further +X and 2 mm further -Z than the machine file's.
    Pose shift;
    shift[Axis::X] = 3.0;
    shift[Axis::Z] = -2.0;
    port.setShift(shift);

    canon::ArcMove arc;
    arc.target[Axis::X] = 10.0;
    arc.center = Vec3(5.0, 1.0, 0.0);
    port.submit({{}, arc});
    canon::ProbeMove probe;
    probe.target[Axis::Z] = -5.0;
    port.submit({{}, probe});
    ASSERT_EQ(submitted.size(), 2u);
    const auto& sentArc = std::get<canon::ArcMove>(submitted[0].body);
    EXPECT_DOUBLE_EQ(sentArc.target[Axis::X], 13.0);
    EXPECT_DOUBLE_EQ(sentArc.target[Axis::Z], -2.0);
    EXPECT_DOUBLE_EQ(sentArc.center.x(), 8.0);
    EXPECT_DOUBLE_EQ(sentArc.center.y(), 1.0);
    EXPECT_DOUBLE_EQ(sentArc.center.z(), -2.0);
    EXPECT_DOUBLE_EQ(std::get<canon::ProbeMove>(submitted[1].body).target[Axis::Z], -7.0);
    // The machine's X 13, Z -7 is the operator's X 10, Z -5.
    EXPECT_DOUBLE_EQ(port.world().position[Axis::X], 10.0);
    EXPECT_DOUBLE_EQ(port.world().position[Axis::Z], -5.0);
    EXPECT_DOUBLE_EQ(port.status().axes[0].nominal, 10.0);
    EXPECT_DOUBLE_EQ(port.status().axes[0].machineNominal, 13.0);
}

// A session on the real-time machine with simulated drives.
class ManualFunctionsTest : public testing::Test {
protected:
    void connect(const machine::MachineConfig& machine,
                 const std::filesystem::path& ncRoot = kerf::test::uniqueTempDir("hmi_manual")) {
        test::testApp();
        config = machine;
        session =
            std::make_unique<MachineSession>(config, test::connectSimulatedMachine(config), ncRoot);
    }
    bool serviceUntil(const std::function<bool()>& done, std::chrono::milliseconds limit = 10s) {
        return test::serviceUntil(*session, done, limit);
    }
    bool runToEnd() {
        return serviceUntil([this] {
            const RunState s = session->runState();
            return s == RunState::Finished || s == RunState::Failed || s == RunState::Aborted;
        });
    }
    // Setpoints and drives come to rest within a few filter lengths (17 ms).
    void settle() {
        serviceUntil([] { return false; }, 200ms);
    }
    const task::AxisStatus& axis(Axis a) const {
        return session->status().axes[static_cast<size_t>(axisIndex(a))];
    }

    machine::MachineConfig config;
    std::unique_ptr<MachineSession> session;
};

TEST_F(ManualFunctionsTest, APresetByEntryMovesTheOriginOfTheNextProgram) {
    connect(*machine::loadMachine("mill"));
    settle();
    // The tool tip stands at machine X 0; the operator says it is at X 25 here.
    ASSERT_TRUE(session->setPresetByEntry(Axis::X, 25.0));
    EXPECT_NEAR(axis(Axis::X).actual, 25.0, 1e-6);
    EXPECT_NEAR(axis(Axis::X).machineActual, 0.0, 1e-6);
    EXPECT_NEAR(session->presetInMachine()[Axis::X], -25.0, 1e-6);
    // X+30 from that origin is machine X 5; Y keeps the machine file's origin.
    ASSERT_TRUE(session->executeMdi("L X+30 Y+2 FMAX"));
    ASSERT_TRUE(runToEnd());
    ASSERT_EQ(session->runState(), RunState::Finished);
    settle();
    EXPECT_NEAR(axis(Axis::X).nominal, 30.0, 1e-6);
    EXPECT_NEAR(axis(Axis::X).machineNominal, 5.0, 1e-6);
    EXPECT_NEAR(axis(Axis::Y).machineNominal, 2.0, 1e-6);
}

TEST_F(ManualFunctionsTest, APresetByEntryIsWrittenToRowZeroOfThePresetTable) {
    const std::filesystem::path root = kerf::test::uniqueTempDir("hmi_preset_write");
    connect(*machine::loadMachine("mill"), root);
    settle();
    // Machine X 0 shown as X 25: the origin is machine X -25, kept in PRESET.PR row 0.
    ASSERT_TRUE(session->setPresetByEntry(Axis::X, 25.0));
    const auto table = tables::PresetTable::load(root / "PRESET.PR");
    ASSERT_TRUE(table) << table.error().format();
    ASSERT_NE(table->byNumber(0), nullptr);
    EXPECT_NEAR(table->byNumber(0)->axis('X').value_or(0.0), -25.0, 1e-9);
    // The other axes keep the origin they had (the built-in mill's: machine Y 0, Z -400).
    EXPECT_NEAR(table->byNumber(0)->axis('Y').value_or(1.0), 0.0, 1e-9);
    EXPECT_NEAR(table->byNumber(0)->axis('Z').value_or(1.0), -400.0, 1e-9);
}

TEST_F(ManualFunctionsTest, ThePresetTablesRowZeroPlacesTheNextProgram) {
    const std::filesystem::path root = kerf::test::uniqueTempDir("hmi_preset_read");
    std::ofstream(root / "PRESET.PR") << "BEGIN PRESET.PR MM\n"
                                         "NR   DOC  X        Y        Z\n"
                                         "0    -    +100     -20      -150\n"
                                         "[END]\n";
    connect(*machine::loadMachine("mill"), root);
    settle();
    EXPECT_NEAR(session->presetInMachine()[Axis::Z], -150.0, 1e-9);
    // The tip starts at the built-in preset's origin, machine X 0 Y 0 Z -400; seen from the
    // origin (100, -20, -150): X -100, Y 20, Z -250.
    EXPECT_NEAR(axis(Axis::X).actual, -100.0, 1e-6);
    EXPECT_NEAR(axis(Axis::Z).actual, -250.0, 1e-6);
    // L X+5 Y+5 Z+20 from that origin is machine X 105, Y -15, Z -130.
    ASSERT_TRUE(session->executeMdi("L X+5 Y+5 Z+20 FMAX"));
    ASSERT_TRUE(runToEnd());
    ASSERT_EQ(session->runState(), RunState::Finished);
    settle();
    EXPECT_NEAR(axis(Axis::X).machineNominal, 105.0, 1e-6);
    EXPECT_NEAR(axis(Axis::Y).machineNominal, -15.0, 1e-6);
    EXPECT_NEAR(axis(Axis::Z).machineNominal, -130.0, 1e-6);
}

TEST_F(ManualFunctionsTest, ThePresetTablesBasicRotationTurnsTheNextMdiBlock) {
    // Row 0 carries a basic rotation of 30 degrees (SPC, as Probing ROT or cycle 400 with
    // Q305 = 0 leave it): X+10 Y+0 is 10 mm along the turned X axis, machine X 10 cos 30 = 8.660,
    // Y 10 sin 30 = 5.
    const std::filesystem::path root = kerf::test::uniqueTempDir("hmi_preset_rotation");
    std::ofstream(root / "PRESET.PR") << "BEGIN PRESET.PR MM\n"
                                         "NR   DOC  X        Y        Z        SPC\n"
                                         "0    -    +0       +0       -400     +30\n"
                                         "[END]\n";
    connect(*machine::loadMachine("mill"), root);
    settle();
    ASSERT_TRUE(session->executeMdi("L X+10 Y+0 Z+20 FMAX"));
    ASSERT_TRUE(runToEnd());
    ASSERT_EQ(session->runState(), RunState::Finished);
    settle();
    EXPECT_NEAR(axis(Axis::X).machineNominal, 10.0 * std::cos(std::numbers::pi / 6.0), 1e-6);
    EXPECT_NEAR(axis(Axis::Y).machineNominal, 5.0, 1e-6);
    EXPECT_NEAR(axis(Axis::Z).machineNominal, -380.0, 1e-6);
}

TEST_F(ManualFunctionsTest, ALatheXPresetIsEnteredAsADiameter) {
    connect(*machine::loadMachine("lathe"));
    settle();
    // X shows a diameter: 40 there is a radius of 20 from the new origin at machine X -20.
    ASSERT_TRUE(session->setPresetByEntry(Axis::X, 40.0));
    EXPECT_NEAR(axis(Axis::X).actual, 20.0, 1e-6);
    EXPECT_NEAR(session->presetInMachine()[Axis::X], -20.0, 1e-6);
}

TEST_F(ManualFunctionsTest, HandwheelDetentsMoveTheSelectedAxisByTheFactor) {
    connect(*machine::loadMachine("mill"));
    settle();
    session->setHandwheelAxis(Axis::Y);
    session->setHandwheelFactor(100);
    // 5 detents at x100: 5 x 100 x 0.001 mm = 0.5 mm.
    ASSERT_TRUE(session->turnHandwheel(5));
    serviceUntil([this] { return axis(Axis::Y).nominal > 0.4999; }, 5s);
    settle();
    EXPECT_NEAR(axis(Axis::Y).nominal, 0.5, 1e-5);
    EXPECT_NEAR(axis(Axis::X).nominal, 0.0, 1e-9);
    session->setHandwheelFactor(10);
    ASSERT_TRUE(session->turnHandwheel(-3));
    serviceUntil([this] { return axis(Axis::Y).nominal < 0.4701; }, 5s);
    settle();
    EXPECT_NEAR(axis(Axis::Y).nominal, 0.47, 1e-5);
}

TEST_F(ManualFunctionsTest, CoolantAndPresetAreRefusedWhileAProgramRuns) {
    connect(*machine::loadMachine("mill"));
    settle();
    EXPECT_TRUE(session->coolant(true));
    settle();
    EXPECT_TRUE(session->coolant(false));
    settle();
    ASSERT_TRUE(session->startProgram("0 BEGIN PGM P MM\n1 L X+50 F3000\n2 END PGM P MM\n", "P.H"));
    EXPECT_FALSE(session->coolant(true));
    EXPECT_FALSE(session->setPresetByEntry(Axis::X, 0.0));
    EXPECT_NEAR(session->presetInMachine()[Axis::X], 0.0, 1e-12);
    session->stop();
    runToEnd();
}

TEST_F(ManualFunctionsTest, AFagorZeroOffsetFromTheTableMovesTheOriginOfTheRun) {
    // G54 lies 50 mm below the machine's Z zero (the lathe's presets are 0).
    const auto dir = kerf::test::uniqueTempDir("hmi_zero_offset");
    std::ofstream(dir / "fagor_zero_offsets.tab") << "G54 Z-50\nACTIVE G54\n";
    connect(*machine::loadMachine("lathe"), dir);
    settle();
    ASSERT_TRUE(session->startProgram("G00 X20 Z5\nM30\n", dir / "zero.pim"));
    ASSERT_TRUE(runToEnd());
    ASSERT_EQ(session->runState(), RunState::Finished);
    settle();
    // Z5 from G54 is machine Z -45; X20 a diameter, so radius 10 on the machine.
    EXPECT_NEAR(axis(Axis::Z).nominal, 5.0, 1e-6);
    EXPECT_NEAR(axis(Axis::Z).machineNominal, -45.0, 1e-6);
    EXPECT_NEAR(axis(Axis::X).machineNominal, 10.0, 1e-6);
    EXPECT_NEAR(session->presetInMachine()[Axis::Z], -50.0, 1e-9);
}

// The machine file's workpiece origin (Z preset -100) and its probe box: a bar of radius 30 whose
// face is at machine Z -102.5, so 2.5 mm below the workpiece zero (docs/machine-config.md).
TEST_F(ManualFunctionsTest, FagorG75TouchesTheMachineFilesProbeBoxAtTheWorkpieceOrigin) {
    const auto dir = kerf::test::uniqueTempDir("hmi_probe_lathe");
    std::ofstream(dir / "probing_lathe.toml") << "base = \"lathe\"\n"
                                                 "[axes.Z]\n"
                                                 "preset = -100.0\n"
                                                 "[simulation.probe]\n"
                                                 "enabled = true\n"
                                                 "x_max = 30.0\n"
                                                 "z_max = -102.5\n";
    auto lathe = machine::loadMachine((dir / "probing_lathe.toml").string());
    ASSERT_TRUE(lathe.ok());
    connect(*lathe);
    settle();
    // The tip starts at the workpiece zero: machine Z -100.
    EXPECT_NEAR(axis(Axis::Z).machineActual, -100.0, 1e-6);
    // 1 mm above the face, so the probing move takes 0.6 s at F100.
    ASSERT_TRUE(
        session->startProgram("N10 G90 G94 G00 X20 Z-1.5\n"
                              "N20 G75 Z-10 F100\n"
                              "N30 G00 X80\n"
                              "N40 M30\n",
                              dir / "probe.pim"));
    ASSERT_TRUE(runToEnd());
    ASSERT_EQ(session->runState(), RunState::Finished);
    const interp::WorldSnapshot world = session->motion().world();
    ASSERT_TRUE(world.probeTriggered);
    // Touched at Z -2.5 (the face), X 10 (diameter 20, a radius in the stream).
    EXPECT_NEAR(world.probePosition[Axis::Z], -2.5, 1e-3);
    EXPECT_NEAR(world.probePosition[Axis::X], 10.0, 1e-6);
    settle();
    // X80 runs from where the probe stopped: just past the face (less than 0.05 mm).
    EXPECT_LT(axis(Axis::Z).nominal, -2.5);
    EXPECT_GT(axis(Axis::Z).nominal, -2.55);
    EXPECT_NEAR(axis(Axis::Z).machineNominal, axis(Axis::Z).nominal - 100.0, 1e-9);
}

}  // namespace
}  // namespace kerf::ui
