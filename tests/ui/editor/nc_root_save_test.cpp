#include <QSignalSpy>
#include <QTextBlock>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/common/diagnostic_text.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

const char* kProgram = "0 BEGIN PGM A MM\n1 L Z+50 R0 FMAX\n2 END PGM A MM\n";

ProgramPanel::Settings settingsIn(const fs::path& root) {
    ProgramPanel::Settings settings;
    settings.machine = *machine::loadMachine("mill");
    settings.ncRoot = root;
    settings.recoveryFolder = root.parent_path() / "recovery";
    settings.autosaveDelayMs = 60000;
    return settings;
}

void appendToLine2(ProgramPanel& panel) {
    QTextCursor cursor(panel.editor()->document()->findBlockByNumber(1));
    cursor.movePosition(QTextCursor::EndOfBlock);
    cursor.insertText(" M3");
}

// A link inside the NC root to a program outside it: the editor opens it, but a save would
// write outside the root. It is refused with a message; the file outside stays as it was.
TEST(NcRootSave, AProgramSaveNeverWritesThroughALinkOutOfTheRoot) {
    test::testApp();
    const fs::path base = kerf::test::uniqueTempDir("hmi_save_link");
    const fs::path root = base / "nc_prog";
    fs::create_directories(root);
    ASSERT_FALSE(writeFileAtomically(base / "OUTSIDE.H", kProgram).has_value());
    fs::create_symlink(base / "OUTSIDE.H", root / "A.H");
    ProgramPanel panel(settingsIn(root));
    QSignalSpy messages(&panel, &ProgramPanel::message);
    ASSERT_TRUE(panel.open(root / "A.H"));
    appendToLine2(panel);
    panel.save();
    EXPECT_EQ(readWholeFile(base / "OUTSIDE.H").value(), kProgram);
    EXPECT_TRUE(fs::is_symlink(root / "A.H"));
    EXPECT_TRUE(panel.modified());
    ASSERT_GE(messages.count(), 1);
    EXPECT_EQ(messages.last().at(0).value<Severity>(), Severity::Error);
}

TEST(NcRootSave, AProgramOutsideTheRootIsNotSavedThere) {
    test::testApp();
    const fs::path base = kerf::test::uniqueTempDir("hmi_save_outside");
    const fs::path root = base / "nc_prog";
    fs::create_directories(root);
    ASSERT_FALSE(writeFileAtomically(base / "B.H", kProgram).has_value());
    ProgramPanel panel(settingsIn(root));
    ASSERT_TRUE(panel.open(base / "B.H"));
    appendToLine2(panel);
    panel.save();
    EXPECT_EQ(readWholeFile(base / "B.H").value(), kProgram);
    // Inside the root the same save works.
    ASSERT_FALSE(writeFileAtomically(root / "B.H", kProgram).has_value());
    ASSERT_TRUE(panel.open(root / "B.H"));
    appendToLine2(panel);
    ASSERT_TRUE(panel.save());
    EXPECT_EQ(readWholeFile(root / "B.H").value(),
              "0 BEGIN PGM A MM\n1 L Z+50 R0 FMAX M3\n2 END PGM A MM\n");
}

}  // namespace
}  // namespace kerf::ui
