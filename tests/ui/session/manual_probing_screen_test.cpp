// Manual probing from the panel: the probing softkeys of Manual operation touch the blank the
// last program defined (box 0..100 x 0..60 x -40..0), placed with the setup error of
// examples/probing/machine.toml (shift (1.5, -0.8, -0.2), rotation 0.7 degrees about the
// program's origin), and write what the operator confirms to PRESET.PR.
#include <QApplication>
#include <QInputDialog>
#include <QPushButton>
#include <QTimer>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <numbers>
#include <thread>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "core/tables/preset_table.h"
#include "core/tables/tool_table.h"
#include "core/task/preset_store.h"
#include "qt_test_app.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/session/program_origin.h"
#include "ui/shell/main_window.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"
#include "ui/status/position_display.h"
#include "ui/status/status_tabs.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

const double kAngle = 0.7 * std::numbers::pi / 180.0;
constexpr double kBall = 2.0;  // TOOL.T: probe 1 has R 2

bool processUntil(const std::function<bool()>& done, std::chrono::milliseconds limit = 20s) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        QCoreApplication::processEvents();
        if (done()) return true;
        std::this_thread::sleep_for(2ms);
    }
    return false;
}

// Answers the probing dialogs as they come, in order: records what each showed and enters
// the operator's value.
class DialogAnswers {
public:
    explicit DialogAnswers(std::vector<double> answers) : m_answers(std::move(answers)) {
        m_timer.setInterval(5);
        QObject::connect(&m_timer, &QTimer::timeout, [this] { answer(); });
        m_timer.start();
    }
    std::vector<QString> names;
    std::vector<QString> labels;
    std::vector<double> shown;
    size_t answered() const { return names.size(); }

private:
    void answer() {
        auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
        if (dialog == nullptr || names.size() >= m_answers.size()) return;
        names.push_back(dialog->objectName());
        labels.push_back(dialog->labelText());
        shown.push_back(dialog->doubleValue());
        dialog->setDoubleValue(m_answers[names.size() - 1]);
        dialog->accept();
    }
    std::vector<double> m_answers;
    QTimer m_timer;
};

class ManualProbingScreen : public testing::Test {
protected:
    ManualProbingScreen() {
        test::testApp();
        dir = kerf::test::uniqueTempDir("hmi_manual_probing");
        const fs::path examples = fs::path(KERF_SOURCE_DIR) / "examples/probing";
        fs::copy_file(examples / "TOOL.T", dir / "TOOL.T");
        fs::copy_file(examples / "tchprobe.tp", dir / "tchprobe.tp");
        HmiContext context;
        context.machine = *machine::loadMachine((examples / "machine.toml").string());
        context.ncRoot = dir;
        context.recoveryFolder = dir / "recovery";
        context.motion = [config = context.machine] {
            return test::connectSimulatedMachine(config);
        };
        machine = context.machine;
        window = std::make_unique<MainWindow>(std::move(context));
        window->resize(1280, 800);
        window->show();
        EXPECT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
        session = window->session();
        // The part's program clamps the blank and calls the probe.
        EXPECT_TRUE(session->startProgram(QStringLiteral("0 BEGIN PGM SETUP MM\n"
                                                         "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n"
                                                         "2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
                                                         "3 TOOL CALL 1 Z\n"
                                                         "4 L Z+50 R0 FMAX\n"
                                                         "5 END PGM SETUP MM\n"),
                                          dir / "SETUP.H"));
        EXPECT_TRUE(processUntil([&] { return !session->busy(); }));
    }

    // The tool tip there, from the origin of the machine file's preset, by MDI.
    void moveTo(double x, double y, double z) {
        ASSERT_TRUE(
            session->executeMdi(QStringLiteral("L X%1 Y%2 Z%3 R0 FMAX").arg(x).arg(y).arg(z)));
        ASSERT_TRUE(processUntil([&] { return !session->busy(); }));
    }
    void press(const char* id) {
        ASSERT_TRUE(window->softkeys()->pressId(QString::fromLatin1(id))) << id;
    }
    // Direction key pressed until it shows `name`.
    void chooseDirection(const QString& name) {
        for (int i = 0; i < 5; ++i) {
            if (keyText("probeDirection") == QStringLiteral("Direction\n") + name) return;
            press("probeDirection");
        }
        FAIL() << name.toStdString();
    }
    void touch() {
        press("probeTouch");
        ASSERT_TRUE(processUntil([&] { return !session->busy(); }));
    }
    QString keyText(const QString& id) {
        SoftkeyBar& bar = *window->softkeys();
        for (int row = 0; row < bar.rowCount(); ++row) {
            bar.showRow(row);
            for (int i = 0; i < SoftkeyBar::kKeys; ++i)
                if (bar.keyId(i) == id) return bar.keyButton(i)->text();
        }
        return {};
    }
    const tables::PresetData& row0() {
        auto table = tables::PresetTable::load(dir / "PRESET.PR");
        EXPECT_TRUE(table.ok());
        presets = std::make_unique<tables::PresetTable>(std::move(*table));
        return *presets->byNumber(0);
    }

    // Row 0's SPC column, where the basic rotation is kept.
    double spc0() {
        row0();
        const auto column = presets->table().findColumn("SPC");
        EXPECT_TRUE(column.has_value());
        if (!column) return 0.0;
        return std::stod(std::string(presets->table().cell(presets->byNumber(0)->row, *column)));
    }

    fs::path dir;
    machine::MachineConfig machine;
    std::unique_ptr<MainWindow> window;
    MachineSession* session = nullptr;
    std::unique_ptr<tables::PresetTable> presets;
};

TEST_F(ManualProbingScreen, ProbingPosSetsTheDatumOnTheTurnedLeftFace) {
    EXPECT_EQ(keyText("probeTouch"), QStringLiteral("Touch POS\n0/1"));
    press("probePosition");
    chooseDirection(QStringLiteral("X+"));
    moveTo(-10, 20, -5);  // the ball centre at (-10, 20, -3)
    DialogAnswers answers({0.0});
    touch();
    ASSERT_TRUE(processUntil([&] { return answers.answered() == 1; }, 5s));
    EXPECT_EQ(answers.names[0], QStringLiteral("probeDatumPrompt"));
    // The left face x' = 0 of the turned part: cos a (x - 1.5) + sin a (y + 0.8) = 0. The ball
    // centre stops r_b from it, x' = -2, at y = 20; the surface point lies r_b further along +X.
    const double ball = 1.5 + (-kBall - 20.8 * std::sin(kAngle)) / std::cos(kAngle);
    const double measured = ball + kBall;
    EXPECT_TRUE(answers.labels[0].contains(QString::number(measured, 'f', 4)))
        << answers.labels[0].toStdString();
    // The probed face reads 0 now: the origin lies `measured` further along X.
    const double presetX = machineFilePreset(machine)[Axis::X] + measured;
    EXPECT_NEAR(session->presetInMachine()[Axis::X], presetX, 1e-9);
    EXPECT_NEAR(*row0().axis('X'), presetX, 1e-4);
    EXPECT_EQ(keyText("probeTouch"), QStringLiteral("Touch POS\n1/1"));
}

TEST_F(ManualProbingScreen, ProbingRotWritesTheEdgesMisalignmentAsBasicRotation) {
    press("probeRotation");
    EXPECT_EQ(keyText("probeTouch"), QStringLiteral("Touch ROT\n0/2"));
    chooseDirection(QStringLiteral("Y+"));
    moveTo(20, -10, -5);
    touch();
    EXPECT_EQ(keyText("probeTouch"), QStringLiteral("Touch ROT\n1/2"));
    moveTo(80, -10, -5);
    DialogAnswers answers({0.7});
    touch();
    ASSERT_TRUE(processUntil([&] { return answers.answered() == 1; }, 5s));
    EXPECT_EQ(answers.names[0], QStringLiteral("probeRotationPrompt"));
    // Both touches of the front edge stop r_b / cos a before it along Y: the line through the
    // surface points is parallel to the edge, turned by the setup's 0.7 degrees. The dialog
    // shows it with four decimals.
    EXPECT_NEAR(answers.shown[0], 0.7, 1e-4);
    processUntil([] { return false; }, 50ms);
    EXPECT_NEAR(spc0(), 0.7, 1e-9);
}

TEST_F(ManualProbingScreen, ProbingPFindsTheCornerOfTheTwoTurnedEdges) {
    press("probeCorner");
    chooseDirection(QStringLiteral("Y+"));
    moveTo(20, -10, -5);
    touch();
    moveTo(80, -10, -5);
    touch();
    chooseDirection(QStringLiteral("X+"));
    moveTo(-10, 15, -5);
    touch();
    moveTo(-10, 45, -5);
    DialogAnswers answers({0.0, 0.0});
    touch();
    ASSERT_TRUE(processUntil([&] { return answers.answered() == 2; }, 5s));
    // The real corner is the setup's shift (1.5, -0.8). Probed along the axes, each surface
    // point lies d = r_b (1 - cos a) outside its turned face, so the corner found lies d along
    // both outward normals (sin a, -cos a) and (-cos a, -sin a).
    const double d = kBall * (1.0 - std::cos(kAngle));
    const double x = 1.5 + d * (std::sin(kAngle) - std::cos(kAngle));
    const double y = -0.8 - d * (std::cos(kAngle) + std::sin(kAngle));
    const Pose file = machineFilePreset(machine);
    EXPECT_NEAR(session->presetInMachine()[Axis::X], file[Axis::X] + x, 1e-9);
    EXPECT_NEAR(session->presetInMachine()[Axis::Y], file[Axis::Y] + y, 1e-9);
    EXPECT_TRUE(
        answers.labels[0].startsWith(QStringLiteral("Probed X = ") + QString::number(x, 'f', 4)))
        << answers.labels[0].toStdString();  // The completed function's log in the NC root.
    std::ifstream in(dir / "TCHPRMAN.html");
    const std::string log{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_NE(log.find("<h2>PROBING P</h2>"), std::string::npos) << log;
    EXPECT_NE(
        log.find("<tr><td>X</td><td>" + QString::number(x, 'f', 4).toStdString() + "</td></tr>"),
        std::string::npos)
        << log;
    EXPECT_NE(log.find("<tr><td>Basic rotation</td><td>0.7000</td></tr>"), std::string::npos);
}

TEST_F(ManualProbingScreen, UnderABasicRotationProbingPSetsTheRealCornerInTheTurnedSystem) {
    // Row 0 holds the part's misalignment, 0.7 degrees, as Probing ROT wrote it: the display
    // and MDI work in the turned system, the touches go along the turned axes and so meet the
    // turned faces squarely; each surface point lies on its face, and their intersection is the
    // real corner (1.5, -0.8). In the turned system that reads (1.5 cos a - 0.8 sin a,
    // -1.5 sin a - 0.8 cos a); entering 0 for both moves the origin there: R(a) of it is
    // (1.5, -0.8) in the machine's axes.
    ASSERT_TRUE(session->setBasicRotation(0.7));
    const PositionDisplay& display = *window->positions();
    EXPECT_TRUE(display.kindLabel().endsWith(QStringLiteral("  ROT")))
        << display.kindLabel().toStdString();
    press("probeCorner");
    chooseDirection(QStringLiteral("Y+"));
    moveTo(20, -10, -5);
    // The display shows the MDI's target in the turned system (ACTL, three decimals).
    ASSERT_TRUE(processUntil([&] {
        return std::fabs(session->status().axes[0].actual - session->status().axes[0].nominal) <
               1e-6;
    }));
    processUntil([] { return false; }, 50ms);
    EXPECT_EQ(display.axisText(Axis::X), QStringLiteral("+20.000"));
    EXPECT_EQ(display.axisText(Axis::Y), QStringLiteral("-10.000"));
    touch();
    EXPECT_EQ(session->manualTouchesDone(), 1);
    moveTo(80, -10, -5);
    touch();
    chooseDirection(QStringLiteral("X+"));
    moveTo(-10, 15, -5);
    touch();
    moveTo(-10, 45, -5);
    DialogAnswers answers({0.0, 0.0});
    touch();
    ASSERT_EQ(session->manualTouchesDone(), 4);
    ASSERT_TRUE(processUntil([&] { return answers.answered() == 2; }, 5s));
    const double x = 1.5 * std::cos(kAngle) - 0.8 * std::sin(kAngle);
    const double y = -1.5 * std::sin(kAngle) - 0.8 * std::cos(kAngle);
    EXPECT_TRUE(
        answers.labels[0].startsWith(QStringLiteral("Probed X = ") + QString::number(x, 'f', 4)))
        << answers.labels[0].toStdString();
    EXPECT_TRUE(
        answers.labels[1].startsWith(QStringLiteral("Probed Y = ") + QString::number(y, 'f', 4)))
        << answers.labels[1].toStdString();
    const Pose file = machineFilePreset(machine);
    EXPECT_NEAR(session->presetInMachine()[Axis::X], file[Axis::X] + 1.5, 1e-9);
    EXPECT_NEAR(session->presetInMachine()[Axis::Y], file[Axis::Y] - 0.8, 1e-9);
    // The first edge is the front face: its whole misalignment.
    const auto result = session->manualProbingResult();
    ASSERT_TRUE(result && result->basicRotationDeg);
    EXPECT_NEAR(*result->basicRotationDeg, 0.7, 1e-9);
    // The corner reads 0 now: the probe, back at turned (-10, 45) from the old origin, shows
    // that less the corner's turned coordinates, once the drives have settled (ACTL).
    const QString shownX = QString::number(-10.0 - x, 'f', 3);
    const QString shownY = QStringLiteral("+") + QString::number(45.0 - y, 'f', 3);
    EXPECT_TRUE(processUntil(
        [&] { return display.axisText(Axis::X) == shownX && display.axisText(Axis::Y) == shownY; },
        5s))
        << display.axisText(Axis::X).toStdString() << " "
        << display.axisText(Axis::Y).toStdString();
}

TEST_F(ManualProbingScreen, WithoutAProgramsBlankTheMachinesSimulatedBlankIsTouched) {
    // A session whose machine never saw a BLK FORM touches [simulation.blank]: the default box
    // 0..100 x 0..60 x -40..0 at the machine file's preset, placed with the same setup error,
    // so the left face is found where the fixture's program put it.
    window.reset();
    HmiContext context;
    context.machine = machine;
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.motion = [config = machine] { return test::connectSimulatedMachine(config); };
    window = std::make_unique<MainWindow>(std::move(context));
    ASSERT_TRUE(window->modes().requestMachineMode(task::MachineMode::Manual));
    session = window->session();
    ASSERT_TRUE(session->executeMdi(QStringLiteral("TOOL CALL 1 Z")));
    ASSERT_TRUE(processUntil([&] { return !session->busy(); }));
    moveTo(-10, 20, -5);
    session->startManualProbing(cycles::probing::ManualProbingFunction::Position);
    ASSERT_TRUE(session->probeTouch(Vec3(1.0, 0.0, 0.0)));
    ASSERT_TRUE(processUntil([&] { return !session->busy(); }));
    const double ball = 1.5 + (-kBall - 20.8 * std::sin(kAngle)) / std::cos(kAngle);
    const auto result = session->manualProbingResult();
    ASSERT_TRUE(result && result->point[0]);
    EXPECT_NEAR(*result->point[0], ball + kBall, 1e-9);
    // The PROBE status tab shows the function and what it found.
    const StatusTabs& tabs = *window->findChild<StatusTabs*>();
    EXPECT_EQ(tabs.valueOf(StatusTabs::Tab::Probe, QStringLiteral("Manual probing")),
              QStringLiteral("POS  1/1"));
    EXPECT_EQ(tabs.valueOf(StatusTabs::Tab::Probe, QStringLiteral("Probed X")),
              StatusTabs::lengthText(ball + kBall, false));
}

TEST_F(ManualProbingScreen, ProgramRunTakesTheTouchesOfCycle400FromTheMachinesLatch) {
    // Program run on the simulated machine: each touch of 400 is a probe move that the servo
    // cycle stops at the latch, where the ball on the placed part triggers it. The front edge is
    // turned by the setup's 0.7 degrees: row 0's SPC gets it, to the latch's bisection.
    ASSERT_TRUE(session->startProgram(
        QStringLiteral("0 BEGIN PGM ROT MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n"
                       "2 BLK FORM 0.2 X+100 Y+60 Z+0\n3 TOOL CALL 1 Z\n"
                       "4 TCH PROBE 400 BASIC ROTATION\n  Q263=+10\n  Q264=+0\n  Q265=+80\n"
                       "  Q266=+0\n  Q272=+2\n  Q267=+1\n  Q261=-5\n  Q320=0\n  Q260=+20\n"
                       "  Q301=1\n  Q307=0\n  Q305=0\n5 L Z+50 R0 FMAX\n6 END PGM ROT MM\n"),
        dir / "ROT.H"));
    ASSERT_TRUE(processUntil([&] { return !session->busy(); }, 60s));
    EXPECT_NEAR(spc0(), 0.7, 1e-6);
}

TEST_F(ManualProbingScreen, ProbingPlOnTheTopGivesItsAnglesInTheProbeTab) {
    // The top is level (the setup turns the part about Z only): A = B = 0.
    press("probePlane");
    EXPECT_EQ(keyText("probeTouch"), QStringLiteral("Touch PL\n0/3"));
    chooseDirection(QStringLiteral("Z-"));
    for (const auto& [x, y] : {std::pair{20.0, 10.0}, {80.0, 15.0}, {50.0, 50.0}}) {
        moveTo(x, y, 5);
        touch();
    }
    EXPECT_EQ(session->manualTouchesDone(), 3);
    const StatusTabs& tabs = *window->findChild<StatusTabs*>();
    EXPECT_EQ(tabs.valueOf(StatusTabs::Tab::Probe, QStringLiteral("Manual probing")),
              QStringLiteral("PL  3/3"));
    EXPECT_EQ(tabs.valueOf(StatusTabs::Tab::Probe, QStringLiteral("Plane A")),
              QStringLiteral("0.000\u00b0"));
    EXPECT_EQ(tabs.valueOf(StatusTabs::Tab::Probe, QStringLiteral("Plane B")),
              QStringLiteral("0.000\u00b0"));
}

TEST_F(ManualProbingScreen, ToolLengthTouchOffWritesLIntoTheToolTable) {
    // The probe (tool 1, L 50) stands with its tip shown at Z +0.3 where it rests on the top
    // (Z 0): the operator enters 0 and TOOL.T's L becomes 50.3.
    moveTo(50, 30, 0.3);
    // Touch off once the drives have settled the last micrometres.
    ASSERT_TRUE(
        processUntil([&] { return std::fabs(session->status().axes[2].actual - 0.3) < 1e-7; }));
    DialogAnswers answers({0.0});
    press("toolLengthTouchOff");
    ASSERT_TRUE(processUntil([&] { return answers.answered() == 1; }, 5s));
    EXPECT_EQ(answers.names[0], QStringLiteral("toolLengthPrompt"));
    processUntil([] { return false; }, 50ms);
    const auto tools = tables::ToolTable::load(dir / "TOOL.T");
    ASSERT_TRUE(tools);
    EXPECT_NEAR(tools->byNumber(1)->length, 50.3, 1e-6);
    const StatusTabs& tabs = *window->findChild<StatusTabs*>();
    EXPECT_EQ(tabs.valueOf(StatusTabs::Tab::Probe, QStringLiteral("Tool length T1")),
              StatusTabs::lengthText(tools->byNumber(1)->length, false));
}

TEST_F(ManualProbingScreen, AMissStopsWithAMessageAndCountsNoTouch) {
    press("probePosition");
    chooseDirection(QStringLiteral("X-"));
    moveTo(-10, 20, -5);  // nothing on the -X side within DIST 20
    EXPECT_FALSE(session->probeTouch(session->probeDirection()));
    EXPECT_EQ(session->manualTouchesDone(), 0);
    EXPECT_FALSE(session->busy());
}

TEST_F(ManualProbingScreen, TheProbeTouchesThePartAsTheLastProgramMachinedIt) {
    // The program drills at (30, 20) with tool 5, really 0.012 thinner than TOOL.T says
    // (machine.toml): the hole's wall is 4.988 from (30, 20), where the tool went, whatever the
    // setup error. The probe in it, 5 deep, touching towards +X: the ball's centre stops 2
    // short of the wall, the probed point is the wall at x 34.988. Without the program's cuts
    // the stylus would stand in material.
    EXPECT_TRUE(session->startProgram(QStringLiteral("0 BEGIN PGM HOLE MM\n"
                                                     "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n"
                                                     "2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
                                                     "3 TOOL CALL 5 Z S3000\n"
                                                     "4 L X+30 Y+20 Z+10 R0 FMAX M3\n"
                                                     "5 L Z-15 F200\n"
                                                     "6 L Z+50 R0 FMAX M5\n"
                                                     "7 TOOL CALL 1 Z\n"
                                                     "8 END PGM HOLE MM\n"),
                                      dir / "HOLE.H"));
    ASSERT_TRUE(processUntil([&] { return !session->busy(); }));
    moveTo(30, 20, -5);
    session->startManualProbing(cycles::probing::ManualProbingFunction::Position);
    ASSERT_TRUE(session->probeTouch(Vec3(1.0, 0.0, 0.0)));
    ASSERT_TRUE(processUntil([&] { return !session->busy(); }));
    const auto result = session->manualProbingResult();
    ASSERT_TRUE(result && result->point[0]);
    EXPECT_NEAR(*result->point[0], 30.0 + 4.988, 1e-6);
    // Below the hole's floor (15.05 deep: the tool is 0.05 longer) the stylus stands in material.
    moveTo(30, 20, -20);
    EXPECT_FALSE(session->probeTouch(Vec3(1.0, 0.0, 0.0)));
}

TEST_F(ManualProbingScreen, ARapidIntoTheBlankIsReportedAsACollision) {
    // Tool 5 at FMAX from 10 above the top to 3 into it (block 5, line 6 of the file); the
    // retract at FMAX out of the uncut material (line 7) is one too. Both run: a warning.
    std::vector<std::pair<Severity, int>> messages;
    std::vector<QString> texts;
    QObject::connect(session, &MachineSession::message,
                     [&](Severity severity, const QString& text, int line) {
                         messages.emplace_back(severity, line);
                         texts.push_back(text);
                     });
    EXPECT_TRUE(session->startProgram(QStringLiteral("0 BEGIN PGM CRASH MM\n"
                                                     "1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n"
                                                     "2 BLK FORM 0.2 X+100 Y+60 Z+0\n"
                                                     "3 TOOL CALL 5 Z S3000\n"
                                                     "4 L X+50 Y+30 Z+10 R0 FMAX M3\n"
                                                     "5 L Z-3 R0 FMAX\n"
                                                     "6 L Z+50 R0 FMAX M5\n"
                                                     "7 END PGM CRASH MM\n"),
                                      dir / "CRASH.H"));
    ASSERT_TRUE(processUntil([&] { return !session->busy(); }));
    std::vector<int> collisionLines;
    for (size_t i = 0; i < messages.size(); ++i) {
        if (texts[i].contains(QStringLiteral("collision"))) {
            EXPECT_EQ(messages[i].first, Severity::Warning);
            collisionLines.push_back(messages[i].second);
        }
    }
    EXPECT_EQ(collisionLines, (std::vector<int>{6, 7}));
    EXPECT_EQ(session->runState(), task::RunState::Finished);
}

}  // namespace
}  // namespace kerf::ui
