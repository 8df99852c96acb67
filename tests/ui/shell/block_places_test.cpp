#include <QAbstractSpinBox>
#include <QInputDialog>
#include <QPushButton>
#include <QTimer>
#include <QTreeWidget>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"

namespace kerf::ui {
namespace {

// Block 1 takes two lines (a '~' continues it), so from block 2 on the block number is the
// line number minus 2: block 3 is on line 5. Line 3 carries no number.
const char* kContinued =
    "0 BEGIN PGM B MM\n"
    "1 L X+0 Y+0 Z+10 R0 ~\n"
    "  FMAX\n"
    "2 L X+10 FMAX\n"
    "3 L X+20 FMAX\n"
    "4 L X+30 FMAX\n"
    "5 END PGM B MM\n";

// A FAGOR program with N numbers on some lines only: N30 is on line 4, line 3 has none.
const char* kFagor =
    "%BLOCKS\n"
    "N10 G90 G0 X50 Z10\n"
    "G1 Z0 F100\n"
    "N30 G0 X60\n"
    "M30\n";

HmiContext contextIn(const std::filesystem::path& dir, const char* machineName = "mill") {
    HmiContext context;
    context.machine = *machine::loadMachine(machineName);
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    return context;
}

// Answers the block prompt the next softkey opens with `value` (or cancels it).
void answerBlockPrompt(MainWindow& window, std::optional<int> value) {
    auto* timer = new QTimer(&window);
    QObject::connect(timer, &QTimer::timeout, timer, [&window, timer, value] {
        auto* dialog = window.findChild<QInputDialog*>(QStringLiteral("blockPrompt"));
        if (dialog == nullptr || !dialog->isVisible()) return;
        timer->stop();
        timer->deleteLater();
        if (!value) return dialog->reject();
        dialog->setIntValue(*value);
        dialog->accept();
    });
    timer->start(5);
}

TEST(BlockPlaces, MessagesNameTheBlockNumberAndTheLineOnlyWhereThereIsNone) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_block_messages");
    std::ofstream(dir / "B.H") << kContinued;
    MainWindow window(contextIn(dir));
    ASSERT_TRUE(window.openProgram(dir / "B.H"));
    MessagePanel* messages = window.messages();
    messages->clearMessages();
    messages->addMessage(Severity::Warning, QStringLiteral("on the continuation"), 3);
    messages->addMessage(Severity::Error, QStringLiteral("beyond the limit"), 5);
    EXPECT_EQ(messages->list()->headerItem()->text(2), QStringLiteral("Block"));
    // Newest first.
    EXPECT_EQ(messages->list()->topLevelItem(0)->text(2), QStringLiteral("3"));
    EXPECT_EQ(messages->list()->topLevelItem(1)->text(2), QStringLiteral("line 3"));
    EXPECT_TRUE(messages->line()->text().contains(QStringLiteral("Block 3: beyond the limit")))
        << messages->line()->text().toStdString();
    // Touching the message still jumps to its line.
    messages->activate(0);
    EXPECT_EQ(window.program()->editor()->currentLine(), 5);
}

TEST(BlockPlaces, GoToTakesTheBlockNumber) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_block_goto");
    std::ofstream(dir / "B.H") << kContinued;
    MainWindow window(contextIn(dir));
    ASSERT_TRUE(window.openProgram(dir / "B.H"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    answerBlockPrompt(window, 3);
    ASSERT_TRUE(window.softkeys()->pressId("goto"));
    EXPECT_EQ(window.program()->editor()->currentLine(), 5);
    // A block the program does not have: a message, the cursor stays.
    const int before = window.messages()->messageCount();
    answerBlockPrompt(window, 9);
    ASSERT_TRUE(window.softkeys()->pressId("goto"));
    EXPECT_EQ(window.program()->editor()->currentLine(), 5);
    ASSERT_EQ(window.messages()->messageCount(), before + 1);
}

TEST(BlockPlaces, TheGoToPromptsButtonsAndFieldAreFingerSized) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_block_touch");
    std::ofstream(dir / "B.H") << kContinued;
    MainWindow window(contextIn(dir));
    window.show();
    ASSERT_TRUE(window.openProgram(dir / "B.H"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    std::vector<int> buttonHeights;
    int fieldHeight = 0;
    auto* timer = new QTimer(&window);
    QObject::connect(timer, &QTimer::timeout, timer, [&] {
        auto* dialog = window.findChild<QInputDialog*>(QStringLiteral("blockPrompt"));
        if (dialog == nullptr || !dialog->isVisible()) return;
        timer->stop();
        for (QPushButton* button : dialog->findChildren<QPushButton*>())
            if (button->isVisible()) buttonHeights.push_back(button->height());
        fieldHeight = dialog->findChild<QAbstractSpinBox*>()->height();
        dialog->reject();
    });
    timer->start(5);
    ASSERT_TRUE(window.softkeys()->pressId("goto"));
    ASSERT_EQ(buttonHeights.size(), 2u);  // OK and Cancel
    for (int height : buttonHeights)
        EXPECT_GE(height, SoftkeyBar::kMinimumKeyHeight);
    EXPECT_GE(fieldHeight, SoftkeyBar::kMinimumKeyHeight);
}

TEST(BlockPlaces, GoToTakesTheFagorNNumberOnALathe) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_block_goto_fagor");
    std::ofstream(dir / "P000100.PIM") << kFagor;
    MainWindow window(contextIn(dir, "lathe"));
    ASSERT_TRUE(window.openProgram(dir / "P000100.PIM"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    answerBlockPrompt(window, 30);
    ASSERT_TRUE(window.softkeys()->pressId("goto"));
    EXPECT_EQ(window.program()->editor()->currentLine(), 4);
    // Messages: N30 by its number, the line without N by its line.
    window.messages()->clearMessages();
    window.messages()->addMessage(Severity::Error, QStringLiteral("x"), 4);
    window.messages()->addMessage(Severity::Error, QStringLiteral("y"), 3);
    EXPECT_EQ(window.messages()->list()->topLevelItem(0)->text(2), QStringLiteral("line 3"));
    EXPECT_EQ(window.messages()->list()->topLevelItem(1)->text(2), QStringLiteral("N30"));
}

TEST(BlockPlaces, AProgramWithoutBlockNumbersIsAddressedByLine) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_block_goto_lines");
    std::ofstream(dir / "P000200.PIM") << "G90 G0 X50 Z10\nG1 Z0 F100\nG0 X60\nM30\n";
    MainWindow window(contextIn(dir, "lathe"));
    ASSERT_TRUE(window.openProgram(dir / "P000200.PIM"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    answerBlockPrompt(window, 3);
    ASSERT_TRUE(window.softkeys()->pressId("goto"));
    EXPECT_EQ(window.program()->editor()->currentLine(), 3);
}

}  // namespace
}  // namespace kerf::ui
