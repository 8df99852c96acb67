// The editor's live check for every dialect, as the operator sees it in the message list.
#include <QSignalSpy>
#include <QTreeWidget>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/editor/program_panel.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

HmiContext contextIn(const fs::path& dir, const char* machineName) {
    HmiContext context;
    context.machine = *machine::loadMachine(machineName);
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.programmingStation = true;
    return context;
}

// The check's messages in the list: severity, text, line.
std::vector<std::array<QString, 3>> listed(const MainWindow& window) {
    std::vector<std::array<QString, 3>> rows;
    QTreeWidget* list = window.messages()->list();
    for (int i = 0; i < list->topLevelItemCount(); ++i) {
        const QTreeWidgetItem* item = list->topLevelItem(i);
        rows.push_back({item->text(0), item->text(1), item->text(2)});
    }
    return rows;
}

TEST(LiveCheck, FagorErrorAppearsInTheMessageListAtItsLine) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_live_fagor");
    // Line 3 programs X twice in one block, which the FAGOR check refuses.
    ASSERT_FALSE(writeFileAtomically(dir / "P1.PIM", "; turning\nG0 X10 Z5\nG1 X20 X30 F100\nM30\n")
                     .has_value());
    MainWindow window(contextIn(dir, "lathe"));
    QSignalSpy checked(window.program(), &ProgramPanel::diagnosticsChanged);
    ASSERT_TRUE(window.openProgram(dir / "P1.PIM"));
    ASSERT_TRUE(checked.wait(10000));
    bool found = false;
    for (const auto& row : listed(window))
        // A FAGOR line without an N number is named by its line.
        found |= row[1].contains("X is programmed twice") && row[2] == QStringLiteral("line 3");
    EXPECT_TRUE(found);
    ASSERT_TRUE(hasErrors(window.program()->diagnostics()));
    for (const Diagnostic& d : window.program()->diagnostics())
        EXPECT_EQ(d.line, 3u) << d.format();
}

TEST(LiveCheck, TncIsoProgramIsCheckedLikeKerfCheck) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_live_iso");
    ASSERT_FALSE(writeFileAtomically(dir / "P2.I",
                                     "%P2 G71 *\nN10 G00 G40 G90 Z+50 *\nN20 X+0 Y+0 G77 *\n"
                                     "N30 G01 Z-5 F200 *\nN99999999 %P2 G71 *\n")
                     .has_value());
    MainWindow window(contextIn(dir, "mill"));
    QSignalSpy checked(window.program(), &ProgramPanel::diagnosticsChanged);
    ASSERT_TRUE(window.openProgram(dir / "P2.I"));
    ASSERT_TRUE(checked.wait(10000));
    const DiagnosticList& diagnostics = window.program()->diagnostics();
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].severity, Severity::Error);
    EXPECT_EQ(diagnostics[0].line, 3u);
    EXPECT_EQ(diagnostics[0].column, 13u);  // at G77
    bool listedError = false;
    for (const auto& row : listed(window))
        listedError |= row[1].contains("unknown G function G77");
    EXPECT_TRUE(listedError);
}

}  // namespace
}  // namespace kerf::ui
