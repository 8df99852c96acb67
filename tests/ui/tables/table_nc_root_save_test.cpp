#include <QSignalSpy>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/tables/tool_table.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/tables/table_editor.h"
#include "ui/tables/tnc_table_model.h"

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

// TOOL.T in the NC root is a link to a table outside it: the table editor may show it, but its
// save is refused (never written through the link); the table outside is unchanged.
TEST(TableNcRootSave, ASaveNeverWritesThroughALinkOutOfTheRoot) {
    test::testApp();
    const fs::path base = kerf::test::uniqueTempDir("hmi_table_save_link");
    const fs::path root = base / "nc_prog";
    fs::create_directories(root);
    const std::string table = tables::ToolTable::createDefault();
    ASSERT_FALSE(writeFileAtomically(base / "TOOL.T", table).has_value());
    fs::create_symlink(base / "TOOL.T", root / "TOOL.T");
    TableEditor editor(root);
    QSignalSpy messages(&editor, &TableEditor::message);
    ASSERT_TRUE(editor.open(root / "TOOL.T"));
    TncTableModel& model = *editor.model();
    const auto column = model.table().findColumn("L");
    ASSERT_TRUE(column.has_value());
    ASSERT_TRUE(model.setData(model.index(0, static_cast<int>(*column)), QStringLiteral("42"),
                              Qt::EditRole));
    EXPECT_FALSE(editor.save());
    EXPECT_EQ(readWholeFile(base / "TOOL.T").value(), table);
    EXPECT_TRUE(fs::is_symlink(root / "TOOL.T"));
    EXPECT_GE(messages.count(), 1);
    // The same edit on a table of the root itself is saved.
    fs::remove(root / "TOOL.T");
    ASSERT_FALSE(writeFileAtomically(root / "TOOL.T", table).has_value());
    ASSERT_TRUE(editor.open(root / "TOOL.T"));
    ASSERT_TRUE(editor.model()->setData(editor.model()->index(0, static_cast<int>(*column)),
                                        QStringLiteral("42"), Qt::EditRole));
    EXPECT_TRUE(editor.save());
    EXPECT_NE(readWholeFile(root / "TOOL.T").value(), table);
}

}  // namespace
}  // namespace kerf::ui
