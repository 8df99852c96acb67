// The FAGOR user screen of the lathe panel: the User softkey runs USEREDIT.PIM (the seed's
// EX-12.19), its softkeys and input line answer WKEY and IB, WBUF writes into the program in the
// editor, SYSTEM returns to the standard screen.
#include <QImage>
#include <QLineEdit>
#include <QPushButton>
#include <QTest>
#include <QTreeWidget>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/workspace.h"
#include "ui/userscreen/user_screen_run.h"
#include "ui/userscreen/user_screen_view.h"

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

HmiContext latheIn(const fs::path& dir) {
    HmiContext context;
    context.machine = *machine::loadMachine("lathe");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    return context;
}

QString lastMessage(const MainWindow& window) {
    QTreeWidget* list = window.messages()->list();
    // Newest first.
    return list->topLevelItemCount() == 0 ? QString() : list->topLevelItem(0)->text(1);
}

bool waitForOperator(MainWindow& window) {
    return QTest::qWaitFor([&] { return window.userScreenRun()->waiting(); }, 5000);
}

void typeNumber(MainWindow& window, const char* number) {
    QLineEdit* input = window.userScreenView()->inputLine();
    ASSERT_TRUE(input->isEnabled());
    input->setText(QString::fromLatin1(number));
    QTest::keyClick(input, Qt::Key_Return);
}

TEST(UserScreenPanel, Ex12_19WritesTheCycleCallIntoTheEditedProgram) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_user_screen");
    fs::copy_file(fs::path(KERF_SOURCE_DIR) / "examples/fagor_user_screen/P000019.PIM",
                  dir / "USEREDIT.PIM");
    { std::ofstream(dir / "P000100.PIM") << "G0 X40 Z2\nM30\n"; }
    MainWindow window(latheIn(dir));
    window.show();
    ASSERT_TRUE(window.openProgram(dir / "P000100.PIM"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    window.program()->editor()->goToLine(1);
    ASSERT_TRUE(window.softkeys()->pressId("userScreen"));
    EXPECT_EQ(window.workspace()->currentPage(), window.userScreenView());
    ASSERT_TRUE(waitForOperator(window));
    EXPECT_EQ(window.softkeys()->keyButton(0)->text(), QStringLiteral("CICLO 1"));
    EXPECT_EQ(window.softkeys()->keyButton(6)->text(), QStringLiteral("SALIR"));
    EXPECT_FALSE(window.userScreenView()->inputLine()->isEnabled());

    ASSERT_TRUE(window.softkeys()->pressId("userF1"));
    ASSERT_TRUE(waitForOperator(window));
    EXPECT_EQ(window.userScreenRun()->screen()->page(), 11);
    EXPECT_EQ(window.userScreenRun()->screen()->prompt(), "X:");
    // A text is refused with the reason; the input stays asked for.
    typeNumber(window, "abc");
    EXPECT_EQ(lastMessage(window), QStringLiteral("a number is expected"));
    EXPECT_TRUE(window.userScreenRun()->waiting());
    typeNumber(window, "2");
    ASSERT_TRUE(waitForOperator(window));
    EXPECT_EQ(window.userScreenRun()->screen()->windows()[1]->text, "2");
    typeNumber(window, "-3.5");
    ASSERT_TRUE(waitForOperator(window));  // back at N5, page 10
    EXPECT_EQ(window.program()->editor()->toPlainText(),
              QStringLiteral("G0 X40 Z2\n( PCALL 1,X2,Y-3.5)\nM30\n"));

    ASSERT_TRUE(window.softkeys()->pressId("userF7"));  // SALIR: SYSTEM
    EXPECT_NE(window.workspace()->currentPage(), window.userScreenView());
    EXPECT_TRUE(window.userScreenRun()->screen()->left());
}

TEST(UserScreenPanel, UserPagesAndSymbolsAreDrawnFromTheirPictures) {
    // PAGE3.PNG fills the 640 x 336 screen in red; SYMBOL7.PNG, 40 x 20 pixels of green, stands
    // at pixel column 320, row 168: its middle (340, 178) is green, 10 pixels left of it red.
    // Symbol 8 has no picture: its marked box (yellow outline) at column 100, row 40.
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_user_screen_pictures");
    QImage page(640, 336, QImage::Format_RGB32);
    page.fill(Qt::red);
    ASSERT_TRUE(page.save(QString::fromStdString((dir / "PAGE3.PNG").string()), "PNG"));
    QImage symbol(40, 20, QImage::Format_RGB32);
    symbol.fill(Qt::green);
    ASSERT_TRUE(symbol.save(QString::fromStdString((dir / "SYMBOL7.PNG").string()), "PNG"));
    {
        std::ofstream(dir / "USEREDIT.PIM")
            << "(PAGE 3)\n(SYMBOL 7, 320, 168)\n(SYMBOL 8, 100, 40)\n(WKEY)\n";
    }
    MainWindow window(latheIn(dir));
    window.show();
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    ASSERT_TRUE(window.softkeys()->pressId("userScreen"));
    ASSERT_TRUE(waitForOperator(window));
    auto* area = window.userScreenView()->findChild<QWidget*>(QStringLiteral("userScreenArea"));
    ASSERT_NE(area, nullptr);
    const QImage shown = area->grab().toImage();
    const double sx = shown.width() / 640.0;
    const double sy = shown.height() / 336.0;
    auto at = [&](double column, double row) {
        return shown.pixelColor(static_cast<int>(column * sx), static_cast<int>(row * sy));
    };
    EXPECT_EQ(at(340, 178), QColor(Qt::green));
    EXPECT_EQ(at(310, 178), QColor(Qt::red));
    EXPECT_EQ(at(500, 300), QColor(Qt::red));
    EXPECT_EQ(at(100, 40).red(), 0xff);  // the box's corner: yellow (ff, d0, 40)
    EXPECT_EQ(at(100, 40).green(), 0xd0);
}

TEST(UserScreenPanel, WithoutTheModesProgramTheOperatorIsTold) {
    test::testApp();
    MainWindow window(latheIn(kerf::test::uniqueTempDir("hmi_user_screen_none")));
    window.show();
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    ASSERT_TRUE(window.softkeys()->pressId("userScreen"));
    EXPECT_EQ(lastMessage(window),
              QStringLiteral("No user customisation program: USEREDIT.PIM is not in the NC root"));
    EXPECT_NE(window.workspace()->currentPage(), window.userScreenView());
}

TEST(UserScreenPanel, TheMillHasNoUserScreen) {
    test::testApp();
    HmiContext context = latheIn(kerf::test::uniqueTempDir("hmi_user_screen_mill"));
    context.machine = *machine::loadMachine("mill");
    MainWindow window(std::move(context));
    window.show();
    EXPECT_FALSE(window.softkeys()->pressId("userScreen"));
}

}  // namespace
}  // namespace kerf::ui
