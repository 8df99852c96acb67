// Every button an operator presses in a prompt, and every row of the file manager and the
// message list, is at least as high as a softkey (48 px): a finger's target on a touch panel.
#include <QAbstractButton>
#include <QApplication>
#include <QDialog>
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QTableView>
#include <QTimer>
#include <QTreeView>
#include <QTreeWidget>
#include <chrono>
#include <functional>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/files/file_manager.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"
#include "ui/tables/table_editor.h"

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

constexpr int kFinger = 48;

HmiContext contextIn(const fs::path& dir) {
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    return context;
}

struct Prompt {
    bool seen = false;
    QString title;
    std::vector<std::pair<QString, int>> targets;  // text of each button / field, its height
};

// Runs `open`, which shows a modal prompt; notes the heights of its buttons and fields as
// shown, then cancels it.
Prompt walkPrompt(const std::function<void()>& open) {
    Prompt prompt;
    QTimer::singleShot(0, [&prompt] {
        QWidget* modal = QApplication::activeModalWidget();
        auto* dialog = qobject_cast<QDialog*>(modal);
        if (dialog == nullptr) return;
        prompt.seen = true;
        prompt.title = dialog->windowTitle();
        // As laid out for the first paint.
        QApplication::sendPostedEvents();
        if (dialog->layout() != nullptr) dialog->layout()->activate();
        for (QWidget* child : dialog->findChildren<QWidget*>()) {
            if (!child->isVisible()) continue;
            if (auto* button = qobject_cast<QAbstractButton*>(child))
                prompt.targets.emplace_back(button->text(), button->height());
            else if (qobject_cast<QLineEdit*>(child))
                prompt.targets.emplace_back(QStringLiteral("<field>"), child->height());
        }
        dialog->reject();
    });
    open();
    return prompt;
}

void expectTouchSized(const Prompt& prompt, const char* what) {
    ASSERT_TRUE(prompt.seen) << what << ": no prompt came up";
    ASSERT_FALSE(prompt.targets.empty()) << what;
    for (const auto& [text, height] : prompt.targets)
        EXPECT_GE(height, kFinger)
            << what << ": \"" << text.toStdString() << "\" is " << height << " px high";
}

TEST(TouchSizes, EveryPromptsButtonsAndFieldsAreFingerSized) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_touch_prompts");
    ASSERT_FALSE(
        writeFileAtomically(dir / "A.H", "0 BEGIN PGM A MM\n1 END PGM A MM\n").has_value());
    ASSERT_FALSE(
        writeFileAtomically(dir / "B.H", "0 BEGIN PGM B MM\n1 END PGM B MM\n").has_value());
    MainWindow window(contextIn(dir));
    window.show();

    // File manager: Delete asks Yes/No, Rename asks for the name.
    ASSERT_TRUE(window.softkeys()->pressId("files"));
    ASSERT_TRUE(window.files()->selectPath(dir / "A.H"));
    expectTouchSized(walkPrompt([&] { window.files()->deleteSelected(); }), "Delete");
    expectTouchSized(walkPrompt([&] { window.files()->renameSelected(); }), "Rename");
    EXPECT_TRUE(fs::exists(dir / "A.H"));  // both cancelled
    ASSERT_TRUE(window.softkeys()->pressId("back"));

    // Table: Delete row asks first.
    ASSERT_TRUE(window.softkeys()->pressId("toolTable"));
    auto* table = window.tables()->findChild<QTableView*>("tableView");
    ASSERT_NE(table, nullptr);
    ASSERT_GT(table->model()->rowCount(), 0);
    table->setCurrentIndex(table->model()->index(0, 0));
    EXPECT_GE(table->rowHeight(0), kFinger);
    expectTouchSized(walkPrompt([&] { window.tables()->deleteRow(); }), "Delete row");
    ASSERT_TRUE(window.softkeys()->pressId("back"));

    // Programming: Edit cycle away from a cycle explains why; another program with unsaved
    // edits asks Save / Discard / Cancel.
    ASSERT_TRUE(window.openProgram(dir / "A.H"));
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    expectTouchSized(walkPrompt([&] { EXPECT_TRUE(window.softkeys()->pressId("editCycle")); }),
                     "Edit cycle");
    window.program()->editor()->appendPlainText(QStringLiteral("2 L X+1 FMAX"));
    expectTouchSized(walkPrompt([&] { window.openProgram(dir / "B.H"); }), "Unsaved edits");
    EXPECT_EQ(window.program()->path(), dir / "A.H");  // Cancel kept it
}

TEST(TouchSizes, FileManagerAndMessageListRowsAreFingerSized) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_touch_rows");
    ASSERT_FALSE(
        writeFileAtomically(dir / "A.H", "0 BEGIN PGM A MM\n1 END PGM A MM\n").has_value());
    MainWindow window(contextIn(dir));
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.softkeys()->pressId("files"));
    ASSERT_TRUE(window.files()->selectPath(dir / "A.H"));
    auto* tree = window.files()->findChild<QTreeView*>("fileTree");
    ASSERT_NE(tree, nullptr);
    // The file system model lists the folder in the background (a thread: seconds on a loaded
    // host, so a deadline rather than a count of short sleeps).
    const auto listed = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!tree->visualRect(tree->currentIndex()).isValid() &&
           std::chrono::steady_clock::now() < listed) {
        QApplication::processEvents();
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    const QRect fileRow = tree->visualRect(tree->currentIndex());
    ASSERT_TRUE(fileRow.isValid());
    EXPECT_GE(fileRow.height(), kFinger);

    MessagePanel* messages = window.messages();
    messages->addMessage(Severity::Error, QStringLiteral("first"), 0);
    messages->addMessage(Severity::Warning, QStringLiteral("second"), 0);
    messages->setListVisible(true);
    QApplication::processEvents();
    for (int i = 0; i < 2; ++i) {
        const QRect row = messages->list()->visualItemRect(messages->list()->topLevelItem(i));
        ASSERT_TRUE(row.isValid()) << i;
        EXPECT_GE(row.height(), kFinger) << "message row " << i;
    }
    EXPECT_GE(messages->clearKey()->height(), kFinger);
}

}  // namespace
}  // namespace kerf::ui
