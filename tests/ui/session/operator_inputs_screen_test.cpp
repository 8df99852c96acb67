// Operator inputs of the lathe panel (docs/fagor.md, "Operator inputs"): a FAGOR program that
// reads IBn asks for the values in a dialog before it runs, and runs with them.
#include <QApplication>
#include <QLineEdit>
#include <QPushButton>
#include <QTimer>
#include <QTreeWidget>
#include <chrono>
#include <fstream>
#include <functional>
#include <thread>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/operator_input_dialog.h"
#include "ui/shell/softkey_bar.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;

bool processUntil(const std::function<bool()>& done, std::chrono::milliseconds limit = 10s) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        QCoreApplication::processEvents();
        if (done()) return true;
        std::this_thread::sleep_for(2ms);
    }
    return false;
}

QString lastMessage(const MainWindow& window) {
    QTreeWidget* list = window.messages()->list();
    return list->topLevelItemCount() == 0 ? QString() : list->topLevelItem(0)->text(1);
}

class OperatorInputsScreen : public testing::Test {
protected:
    OperatorInputsScreen() {
        test::testApp();
        dir = kerf::test::uniqueTempDir("hmi_operator_inputs");
        HmiContext context;
        context.machine = *machine::loadMachine("lathe");
        context.machine.referenceRequired = false;
        context.ncRoot = dir;
        context.recoveryFolder = dir / "recovery";
        context.motion = [config = context.machine] {
            return test::connectSimulatedMachine(config);
        };
        window = std::make_unique<MainWindow>(std::move(context));
        window->resize(1280, 800);
        window->show();
        // IB3 is read twice and IB1 once; the comment's IB9 and the text's IB8 are not reads.
        std::ofstream(dir / "P000001.PIM") << "(P100=IB3)\n"
                                              "(P101=IB3 - IB1) ; IB9\n"
                                              "(MSG \"IB8\")\n"
                                              "G90 G00 XP100 Z0\n"
                                              "G00 XP101\n"
                                              "M30\n";
        EXPECT_TRUE(window->openProgram(dir / "P000001.PIM"));
        EXPECT_TRUE(window->modes().requestMachineMode(task::MachineMode::FullSequence));
    }
    // The X the simulated machine stands at, as a diameter (the lathe programs diameters).
    double diameter() const { return 2.0 * window->session()->status().axes[0].nominal; }

    std::filesystem::path dir;
    std::unique_ptr<MainWindow> window;
};

TEST_F(OperatorInputsScreen, StartAsksForTheInputsTheProgramReadsAndRunsWithThem) {
    bool asked = false;
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<OperatorInputDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        asked = true;
        ASSERT_EQ(dialog->values(), (std::vector<std::pair<int, double>>{{1, 0.0}, {3, 0.0}}));
        EXPECT_EQ(dialog->field(9), nullptr);
        EXPECT_EQ(dialog->field(8), nullptr);
        // A field that is not a number cannot start the program.
        dialog->field(3)->setText(QStringLiteral("4x"));
        QPushButton* ok = nullptr;
        for (QPushButton* b : dialog->findChildren<QPushButton*>())
            if (b->text() == QObject::tr("Start")) ok = b;
        ASSERT_NE(ok, nullptr);
        EXPECT_FALSE(ok->isEnabled());
        dialog->field(3)->setText(QStringLiteral("40"));
        dialog->field(1)->setText(QStringLiteral("12.5"));
        EXPECT_TRUE(ok->isEnabled());
        ok->click();
    });
    ASSERT_TRUE(window->softkeys()->pressId("ncStart"));
    EXPECT_TRUE(asked);
    // X IB3 = 40, then X IB3 - IB1 = 27.5 (diameters).
    EXPECT_TRUE(processUntil([&] {
        return !window->session()->busy() && std::abs(diameter() - 27.5) < 1e-6;
    })) << diameter()
        << " " << lastMessage(*window).toStdString();
}

TEST_F(OperatorInputsScreen, CancellingTheInputsDoesNotStartTheProgram) {
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<OperatorInputDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        dialog->reject();
    });
    window->softkeys()->pressId("ncStart");
    processUntil([] { return false; }, 200ms);
    EXPECT_FALSE(window->session()->busy());
    EXPECT_NEAR(diameter(), 0.0, 1e-9);
}

}  // namespace
}  // namespace kerf::ui
