#include "ui/tables/table_editor.h"

#include <QSignalSpy>
#include <QTableView>
#include <chrono>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/tables/preset_table.h"
#include "core/tables/tool_table.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/common/diagnostic_text.h"
#include "ui/tables/tnc_table_model.h"

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

fs::path writeToolTable(const std::string& name) {
    const fs::path dir = kerf::test::uniqueTempDir(name);
    EXPECT_FALSE(
        writeFileAtomically(dir / "TOOL.T", tables::ToolTable::createDefault()).has_value());
    return dir / "TOOL.T";
}

QModelIndex cellOf(const TncTableModel& model, int row, const char* column) {
    const auto index = model.table().findColumn(column);
    EXPECT_TRUE(index.has_value()) << column;
    return model.index(row, static_cast<int>(index.value_or(0)));
}

TEST(TableEditor, NumericCellsRefuseTextAndSavedValuesReadBack) {
    test::testApp();
    const fs::path file = writeToolTable("hmi_tables_edit");
    TableEditor editor(file.parent_path());
    QSignalSpy messages(&editor, &TableEditor::message);
    ASSERT_TRUE(editor.open(file));
    TncTableModel& model = *editor.model();
    ASSERT_EQ(model.rowCount(), 1);  // the null tool 0
    EXPECT_FALSE(model.setData(cellOf(model, 0, "L"), "abc", Qt::EditRole));
    ASSERT_EQ(messages.count(), 1);
    EXPECT_EQ(messages.at(0).at(0).value<Severity>(), Severity::Error);
    EXPECT_TRUE(messages.at(0).at(1).toString().startsWith("TOOL.T:"))
        << messages.at(0).at(1).toString().toStdString();
    EXPECT_TRUE(model.setData(cellOf(model, 0, "L"), "12.5", Qt::EditRole));
    EXPECT_TRUE(model.setData(cellOf(model, 0, "NAME"), "MILL_D10", Qt::EditRole));
    EXPECT_TRUE(editor.modified());
    ASSERT_TRUE(editor.save());
    EXPECT_FALSE(editor.modified());
    const auto reloaded = tables::ToolTable::load(file);
    ASSERT_TRUE(reloaded) << reloaded.error().format();
    ASSERT_NE(reloaded->byNumber(0), nullptr);
    EXPECT_DOUBLE_EQ(reloaded->byNumber(0)->length, 12.5);
    EXPECT_EQ(reloaded->byNumber(0)->name, "MILL_D10");
}

// A program run's tool measurement rewrites TOOL.T while the table is open: an unedited table
// reloads; edits are not saved over the new file unless the operator says so.
TEST(TableEditor, AFileChangedOnDiskIsReloadedOrNotOverwrittenUnasked) {
    test::testApp();
    const fs::path file = writeToolTable("hmi_tables_changed_on_disk");
    TableEditor editor(file.parent_path());
    ASSERT_TRUE(editor.open(file));
    const auto writeLengthElsewhere = [&](const char* length) {
        TableEditor other(file.parent_path());
        ASSERT_TRUE(other.open(file));
        ASSERT_TRUE(other.model()->setData(cellOf(*other.model(), 0, "L"), length, Qt::EditRole));
        ASSERT_TRUE(other.save());
        // A later time than any the editor saw, whatever the file system's clock resolution.
        fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
    };
    writeLengthElsewhere("33");
    editor.checkFileOnDisk();
    EXPECT_EQ(editor.model()->data(cellOf(*editor.model(), 0, "L"), Qt::DisplayRole).toDouble(),
              33.0);

    ASSERT_TRUE(editor.model()->setData(cellOf(*editor.model(), 0, "NAME"), "MINE", Qt::EditRole));
    writeLengthElsewhere("44");
    QSignalSpy messages(&editor, &TableEditor::message);
    editor.checkFileOnDisk();
    ASSERT_EQ(messages.count(), 1);
    EXPECT_EQ(messages.at(0).at(0).value<Severity>(), Severity::Warning);
    EXPECT_TRUE(editor.modified()) << "the edits are kept";
    bool overwrite = false;
    editor.setConfirm([&overwrite](const QString&) { return overwrite; });
    EXPECT_FALSE(editor.save());
    EXPECT_DOUBLE_EQ(tables::ToolTable::load(file)->byNumber(0)->length, 44.0);
    overwrite = true;
    EXPECT_TRUE(editor.save());
    EXPECT_EQ(tables::ToolTable::load(file)->byNumber(0)->name, "MINE");
    EXPECT_DOUBLE_EQ(tables::ToolTable::load(file)->byNumber(0)->length, 33.0);
}

TEST(TableEditor, DuplicateToolNumberBlocksTheSave) {
    test::testApp();
    const fs::path file = writeToolTable("hmi_tables_duplicate");
    const std::string before = readWholeFile(file).value();
    TableEditor editor(file.parent_path());
    ASSERT_TRUE(editor.open(file));
    TncTableModel& model = *editor.model();
    editor.view()->setCurrentIndex(QModelIndex());
    ASSERT_TRUE(editor.insertRow());
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_EQ(model.data(cellOf(model, 1, "T"), Qt::DisplayRole).toString(), QStringLiteral("1"));
    EXPECT_TRUE(editor.validate().empty());
    ASSERT_TRUE(model.setData(cellOf(model, 1, "T"), "0", Qt::EditRole));
    EXPECT_TRUE(hasErrors(editor.validate()));
    EXPECT_FALSE(editor.save());
    EXPECT_EQ(readWholeFile(file).value(), before);
    editor.undo();  // back to tool 1
    ASSERT_TRUE(editor.save());
    const auto reloaded = tables::ToolTable::load(file);
    ASSERT_TRUE(reloaded);
    EXPECT_NE(reloaded->byNumber(1), nullptr);
}

TEST(TableEditor, DeleteRowAsksAndCanBeUndone) {
    test::testApp();
    const fs::path file = writeToolTable("hmi_tables_delete");
    TableEditor editor(file.parent_path());
    ASSERT_TRUE(editor.open(file));
    TncTableModel& model = *editor.model();
    editor.view()->setCurrentIndex(QModelIndex());
    ASSERT_TRUE(editor.insertRow());  // tool 1 at the end
    bool answer = false;
    editor.setConfirm([&answer](const QString&) { return answer; });
    editor.view()->setCurrentIndex(model.index(1, 0));
    EXPECT_FALSE(editor.deleteRow());
    EXPECT_EQ(model.rowCount(), 2);
    answer = true;
    EXPECT_TRUE(editor.deleteRow());
    EXPECT_EQ(model.rowCount(), 1);
    editor.undo();
    EXPECT_EQ(model.rowCount(), 2);
    ASSERT_TRUE(model.setData(cellOf(model, 1, "NAME"), "DRILL_8", Qt::EditRole));
    EXPECT_TRUE(editor.find("drill"));
    EXPECT_EQ(editor.view()->currentIndex().row(), 1);
}

TEST(TableEditor, PresetTableEditsAndUnits) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_tables_preset");
    ASSERT_FALSE(
        writeFileAtomically(dir / "PRESET.PR", tables::PresetTable::createDefault()).has_value());
    TableEditor editor(dir);
    ASSERT_TRUE(editor.open(dir / "PRESET.PR"));
    TncTableModel& model = *editor.model();
    const auto x = model.table().findColumn("X");
    ASSERT_TRUE(x.has_value());
    EXPECT_EQ(model.columnUnit(*x), QStringLiteral("mm"));
    EXPECT_EQ(model.headerData(static_cast<int>(*x), Qt::Horizontal, Qt::DisplayRole).toString(),
              QStringLiteral("X\n[mm]"));
    ASSERT_GE(model.rowCount(), 1);
    EXPECT_FALSE(model.setData(cellOf(model, 0, "X"), "abc", Qt::EditRole));
    ASSERT_TRUE(model.setData(cellOf(model, 0, "X"), "-125.25", Qt::EditRole));
    ASSERT_TRUE(editor.save());
    const auto presets = tables::PresetTable::load(dir / "PRESET.PR");
    ASSERT_TRUE(presets) << presets.error().format();
    EXPECT_DOUBLE_EQ(presets->table().number(0, *presets->table().findColumn("X")).value_or(0),
                     -125.25);
}

TEST(TableEditor, MissingFileIsReported) {
    test::testApp();
    TableEditor editor("/nonexistent");
    QSignalSpy messages(&editor, &TableEditor::message);
    EXPECT_FALSE(editor.open("/nonexistent/TOOL.T"));
    EXPECT_EQ(messages.count(), 1);
}

}  // namespace
}  // namespace kerf::ui
