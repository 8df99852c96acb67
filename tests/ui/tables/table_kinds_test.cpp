// Editing and saving the datum, point, touch-probe and FAGOR tables through the table editor:
// the saved bytes are compared with hand-written files.
#include <QSignalSpy>
#include <QTableView>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/common/diagnostic_text.h"
#include "ui/tables/editable_table_model.h"
#include "ui/tables/fagor_table_model.h"
#include "ui/tables/table_chooser.h"
#include "ui/tables/table_editor.h"
#include "ui/tables/tnc_table_model.h"

Q_DECLARE_METATYPE(std::filesystem::path)

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

fs::path writeTable(const std::string& dirName, const std::string& fileName,
                    const std::string& bytes) {
    const fs::path dir = kerf::test::uniqueTempDir(dirName);
    EXPECT_FALSE(writeFileAtomically(dir / fileName, bytes).has_value());
    return dir / fileName;
}

std::string fileText(const fs::path& path) {
    return readWholeFile(path).value();
}

// Index of a cell by the column's header name (the header may carry "\n[unit]").
QModelIndex cellOf(const EditableTableModel& model, int row, const QString& column) {
    for (int c = 0; c < model.columnCount(); ++c) {
        const QString header = model.headerData(c, Qt::Horizontal, Qt::DisplayRole).toString();
        if (header.section(QLatin1Char('\n'), 0, 0) == column) return model.index(row, c);
    }
    ADD_FAILURE() << "no column " << column.toStdString();
    return {};
}

QString lastMessage(const QSignalSpy& spy) {
    return spy.isEmpty() ? QString() : spy.last().at(1).toString();
}

TEST(TableKinds, DatumTableEditAndDeleteSaveTheExpectedBytes) {
    test::testApp();
    const fs::path file = writeTable("hmi_kinds_datum", "FIX.D",
                                     "BEGIN FIX.D MM\n"
                                     "D    X         Y         DOC\n"
                                     "0    +0        +0        origin\n"
                                     "1    +10       -5        vice\n"
                                     "[END]\n");
    TableEditor editor(file.parent_path());
    QSignalSpy messages(&editor, &TableEditor::message);
    ASSERT_TRUE(editor.open(file));
    EditableTableModel& model = *editor.tableModel();
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_EQ(model.columnUnit(1), QStringLiteral("mm"));
    EXPECT_FALSE(model.setData(cellOf(model, 1, "X"), "ten", Qt::EditRole));
    EXPECT_TRUE(lastMessage(messages).contains("column X needs a number, not \"ten\""))
        << lastMessage(messages).toStdString();
    ASSERT_TRUE(model.setData(cellOf(model, 1, "X"), "+12.5", Qt::EditRole));
    editor.setConfirm([](const QString&) { return true; });
    editor.view()->setCurrentIndex(model.index(0, 0));
    ASSERT_TRUE(editor.deleteRow());
    ASSERT_TRUE(editor.save());
    EXPECT_EQ(fileText(file),
              "BEGIN FIX.D MM\n"
              "D    X         Y         DOC\n"
              "1    +12.5     -5        vice\n"
              "[END]\n");
}

TEST(TableKinds, DuplicateDatumNumberBlocksTheSave) {
    test::testApp();
    const std::string original =
        "BEGIN FIX.D MM\n"
        "D    X         DOC\n"
        "0    +0        a\n"
        "1    +1        b\n"
        "[END]\n";
    const fs::path file = writeTable("hmi_kinds_datum_dup", "FIX.D", original);
    TableEditor editor(file.parent_path());
    QSignalSpy messages(&editor, &TableEditor::message);
    ASSERT_TRUE(editor.open(file));
    ASSERT_TRUE(
        editor.tableModel()->setData(cellOf(*editor.tableModel(), 1, "D"), "0", Qt::EditRole));
    EXPECT_FALSE(editor.save());
    EXPECT_EQ(fileText(file), original);
    bool namesTheLine = false;
    for (const auto& message : messages)
        namesTheLine |= message.at(1).toString().startsWith("FIX.D:4:");
    EXPECT_TRUE(namesTheLine);
}

TEST(TableKinds, PointTableFlagSavesTheExpectedBytes) {
    test::testApp();
    const fs::path file = writeTable("hmi_kinds_point", "HOLES.PNT",
                                     "BEGIN HOLES.PNT MM\n"
                                     "NR   X       Y       Z       FADE CLEAR\n"
                                     "0    +10     +20     +0\n"
                                     "[END]\n");
    TableEditor editor(file.parent_path());
    QSignalSpy messages(&editor, &TableEditor::message);
    ASSERT_TRUE(editor.open(file));
    EditableTableModel& model = *editor.tableModel();
    ASSERT_TRUE(model.setData(cellOf(model, 0, "FADE"), "N", Qt::EditRole));
    ASSERT_TRUE(model.setData(cellOf(model, 0, "CLEAR"), "maybe", Qt::EditRole));
    EXPECT_FALSE(editor.save());
    bool clearNamed = false;
    for (const auto& message : messages) {
        clearNamed |= message.at(1).toString().contains(
            "HOLES.PNT:3:35: column CLEAR needs Y or nothing, not \"maybe\"");
    }
    EXPECT_TRUE(clearNamed) << lastMessage(messages).toStdString();
    editor.undo();  // CLEAR empty again
    ASSERT_TRUE(model.setData(cellOf(model, 0, "FADE"), "Y", Qt::EditRole));
    ASSERT_TRUE(model.setData(cellOf(model, 0, "Y"), "-7.5", Qt::EditRole));
    ASSERT_TRUE(editor.save());
    // A row that ended early ends right after the rewritten cell.
    EXPECT_EQ(fileText(file),
              "BEGIN HOLES.PNT MM\n"
              "NR   X       Y       Z       FADE CLEAR\n"
              "0    +10     -7.5    +0      Y\n"
              "[END]\n");
}

TEST(TableKinds, ProbeTableEditsFeedAndRefusesBadWords) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_kinds_probe");
    const fs::path file = standardTablePath(dir, TableKind::Probe);
    EXPECT_EQ(file.filename(), "tchprobe.tp");
    ASSERT_FALSE(writeFileAtomically(file, defaultTableContent(TableKind::Probe)).has_value());
    TableEditor editor(file.parent_path());
    QSignalSpy messages(&editor, &TableEditor::message);
    ASSERT_TRUE(editor.open(file));
    EditableTableModel& model = *editor.tableModel();
    EXPECT_EQ(model.headerData(cellOf(model, 0, "F").column(), Qt::Horizontal, Qt::DisplayRole),
              QStringLiteral("F\n[mm/min]"));
    EXPECT_EQ(model.columnUnit(static_cast<size_t>(cellOf(model, 0, "CAL_ANG").column())),
              QStringLiteral("\u00b0"));
    EXPECT_FALSE(model.setData(cellOf(model, 0, "F"), "fast", Qt::EditRole));
    ASSERT_TRUE(model.setData(cellOf(model, 0, "TRACK"), "YES", Qt::EditRole));
    EXPECT_FALSE(editor.save());
    EXPECT_TRUE(lastMessage(messages).contains("Not saved"));
    bool trackNamed = false;
    for (const auto& message : messages)
        trackNamed |=
            message.at(1).toString().contains("column TRACK needs OFF or ON, not \"YES\"");
    EXPECT_TRUE(trackNamed);
    ASSERT_TRUE(model.setData(cellOf(model, 0, "TRACK"), "ON", Qt::EditRole));
    ASSERT_TRUE(model.setData(cellOf(model, 0, "F"), "500", Qt::EditRole));
    ASSERT_TRUE(editor.save());
    // Widths: NO 5, TYPE 11, CAL_OF1 11, CAL_OF2 11, CAL_ANG 9, F 9, FMAX 9, DIST 8, SET_UP 8,
    // F_PREPOS 14, TRACK 7, SERIAL 12.
    EXPECT_EQ(fileText(file),
              "BEGIN TCHPROBE.TP MM\n"
              "NO   TYPE       CAL_OF1    CAL_OF2    CAL_ANG  F        FMAX     DIST    SET_UP  "
              "F_PREPOS      TRACK  SERIAL      \n"
              "1    TS460      +0         +0         +0       500      3000     20      2       "
              "FMAX_PROBE    ON                 \n"
              "[END]\n");
}

TEST(TableKinds, FagorToolOffsetsInsertEditDeleteAndUndo) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_kinds_fagor_offsets");
    const fs::path file = standardTablePath(dir, TableKind::FagorToolOffsets);
    ASSERT_FALSE(
        writeFileAtomically(file, "%TOOL OFFSETS,MX,\nD1 X12.5 Z-30 F3 R0.8\n").has_value());
    TableEditor editor(file.parent_path());
    QSignalSpy messages(&editor, &TableEditor::message);
    ASSERT_TRUE(editor.open(file));
    EXPECT_EQ(editor.model(), nullptr);  // not a TNC table
    EditableTableModel& model = *editor.tableModel();
    ASSERT_EQ(model.rowCount(), 1);
    EXPECT_EQ(model.data(model.index(0, 0), Qt::DisplayRole), QStringLiteral("D1"));
    EXPECT_EQ(model.data(cellOf(model, 0, "R"), Qt::DisplayRole), QStringLiteral("0.8"));
    EXPECT_EQ(model.data(cellOf(model, 0, "I"), Qt::DisplayRole), QStringLiteral("0"));
    EXPECT_EQ(model.headerData(cellOf(model, 0, "X").column(), Qt::Horizontal, Qt::DisplayRole),
              QStringLiteral("X\n[mm]"));
    // The location code is a whole number 0-9; the message names the offset and the field.
    EXPECT_FALSE(model.setData(cellOf(model, 0, "F"), "12", Qt::EditRole));
    EXPECT_TRUE(lastMessage(messages).endsWith("D1 F must be a whole number from 0 to 9"))
        << lastMessage(messages).toStdString();
    EXPECT_TRUE(lastMessage(messages).startsWith("fagor_tool_offsets.tab:2:"));
    EXPECT_FALSE(model.setData(cellOf(model, 0, "X"), "abc", Qt::EditRole));
    EXPECT_TRUE(lastMessage(messages).contains("D1 X needs a number, not \"abc\""));

    editor.view()->setCurrentIndex(model.index(0, 0));
    ASSERT_TRUE(editor.insertRow());
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_EQ(editor.view()->currentIndex().row(), 1);
    ASSERT_TRUE(model.setData(cellOf(model, 1, "Z"), "-45,25", Qt::EditRole));
    ASSERT_TRUE(editor.save());
    EXPECT_EQ(fileText(file),
              "%TOOL OFFSETS,MX,\nD1 X12.5 Z-30 F3 R0.8\nD2 X0 Z-45.25 R0 F0 I0 K0\n");

    editor.setConfirm([](const QString&) { return true; });
    editor.view()->setCurrentIndex(model.index(0, 0));
    ASSERT_TRUE(editor.deleteRow());
    ASSERT_TRUE(editor.find("d2"));
    ASSERT_TRUE(editor.save());
    EXPECT_EQ(fileText(file), "%TOOL OFFSETS,MX,\nD2 X0 Z-45.25 R0 F0 I0 K0\n");
    editor.undo();
    ASSERT_EQ(model.rowCount(), 2);
    EXPECT_TRUE(editor.modified());
}

TEST(TableKinds, FagorZeroOffsetsHaveFixedRowsForTheMachineAxes) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_kinds_fagor_zero");
    const fs::path file = standardTablePath(dir, TableKind::FagorZeroOffsets);
    ASSERT_FALSE(
        writeFileAtomically(file, "%ZERO OFFSETS,MX,\nG54 X0 Z330\nACTIVE G54\n").has_value());
    TableEditor editor(file.parent_path());
    editor.setAxisLetters("XZ");
    QSignalSpy messages(&editor, &TableEditor::message);
    ASSERT_TRUE(editor.open(file));
    EditableTableModel& model = *editor.tableModel();
    ASSERT_EQ(model.rowCount(), 21);  // G54-G59, G159N7-G159N20, PLC
    ASSERT_EQ(model.columnCount(), 3);
    EXPECT_EQ(model.data(model.index(6, 0), Qt::DisplayRole), QStringLiteral("G159N7"));
    EXPECT_EQ(model.data(model.index(20, 0), Qt::DisplayRole), QStringLiteral("PLC"));
    EXPECT_EQ(model.data(cellOf(model, 0, "Z"), Qt::DisplayRole), QStringLiteral("330"));
    EXPECT_FALSE(editor.insertRow());
    EXPECT_TRUE(lastMessage(messages).contains("fixed row"));
    ASSERT_TRUE(model.setData(cellOf(model, 1, "Z"), "-180", Qt::EditRole));
    ASSERT_TRUE(model.setData(cellOf(model, 0, "X"), "12.5", Qt::EditRole));
    ASSERT_TRUE(editor.save());
    EXPECT_EQ(fileText(file), "%ZERO OFFSETS,MX,\nG54 X12.5 Z330\nACTIVE G54\nG55 Z-180\n");
}

TEST(TableKinds, FagorToolTableNewToolUsesItsOwnOffset) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_kinds_fagor_tools");
    const fs::path file = standardTablePath(dir, TableKind::FagorTools);
    ASSERT_FALSE(writeFileAtomically(file, "T1 D1 FAM3\n").has_value());
    TableEditor editor(file.parent_path());
    ASSERT_TRUE(editor.open(file));
    EditableTableModel& model = *editor.tableModel();
    ASSERT_TRUE(editor.insertRow());
    EXPECT_FALSE(model.setData(cellOf(model, 1, "FAM"), "300", Qt::EditRole));
    ASSERT_TRUE(editor.save());
    EXPECT_EQ(fileText(file), "T1 D1 FAM3\nT2 D2 FAM0 NLIFE0 RLIFE0 NOSEA0 NOSEW0 CUTA0\n");
}

// T0 is "no tool" and D0 "no offset" on the 8035 (spec part 1, tool offsets): the first row
// inserted in an empty table is tool 1 with its offset 1, offset 1.
TEST(TableKinds, FagorEmptyTablesStartAtToolAndOffsetOne) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_kinds_fagor_empty");
    const fs::path tools = standardTablePath(dir, TableKind::FagorTools);
    const fs::path offsets = standardTablePath(dir, TableKind::FagorToolOffsets);
    ASSERT_FALSE(writeFileAtomically(tools, "").has_value());
    ASSERT_FALSE(writeFileAtomically(offsets, "%TOOL OFFSETS,MX,\n").has_value());
    TableEditor editor(dir);
    ASSERT_TRUE(editor.open(tools));
    ASSERT_TRUE(editor.insertRow());
    EXPECT_EQ(editor.tableModel()->data(editor.tableModel()->index(0, 0), Qt::DisplayRole),
              QStringLiteral("T1"));
    ASSERT_TRUE(editor.save());
    EXPECT_EQ(fileText(tools), "T1 D1 FAM0 NLIFE0 RLIFE0 NOSEA0 NOSEW0 CUTA0\n");
    ASSERT_TRUE(editor.open(offsets));
    ASSERT_TRUE(editor.insertRow());
    ASSERT_TRUE(editor.save());
    EXPECT_EQ(fileText(offsets), "%TOOL OFFSETS,MX,\nD1 X0 Z0 R0 F0 I0 K0\n");
}

TEST(TableKinds, KindsFollowTheFileAndNewTablesTheirName) {
    EXPECT_EQ(tableKindOf("/nc/fix.d"), TableKind::Datum);
    EXPECT_EQ(tableKindOf("/nc/TCHPROBE.TP"), TableKind::Probe);
    EXPECT_EQ(tableKindOf("/nc/fagor_zero_offsets.tab"), TableKind::FagorZeroOffsets);
    EXPECT_EQ(tableKindOf("/nc/pallet.tab"), TableKind::OtherTnc);
    EXPECT_TRUE(isTableFile("/nc/tchprobe.tp"));
    EXPECT_FALSE(isTableFile("/nc/PART.H"));
    EXPECT_EQ(defaultTableContent(TableKind::Datum, "/nc/fix.d").substr(0, 15), "BEGIN FIX.D MM\n");
    EXPECT_EQ(defaultTableContent(TableKind::Point).substr(0, 20), "BEGIN POINTS.PNT MM\n");
    EXPECT_EQ(defaultTableContent(TableKind::FagorZeroOffsets).substr(0, 18),
              "%ZERO OFFSETS,MX,\n");
    EXPECT_TRUE(defaultTableContent(TableKind::OtherTnc).empty());
}

TEST(TableChooser, OffersTheTablesOfTheMachineKind) {
    test::testApp();
    const fs::path root = "/nc";
    qRegisterMetaType<fs::path>();
    TableChooser mill(root, false);
    ASSERT_EQ(mill.kinds().size(), 5u);
    QSignalSpy opened(&mill, &TableChooser::openRequested);
    mill.choose(TableKind::Datum);
    ASSERT_EQ(opened.count(), 1);
    EXPECT_EQ(opened.at(0).at(0).value<fs::path>(), fs::path("/nc/DATUM.D"));
    TableChooser lathe(root, true);
    ASSERT_EQ(lathe.kinds().size(), 3u);
    EXPECT_EQ(lathe.kinds()[0], TableKind::FagorToolOffsets);
    EXPECT_EQ(lathe.pathOf(TableKind::FagorZeroOffsets), fs::path("/nc/fagor_zero_offsets.tab"));
}

}  // namespace
}  // namespace kerf::ui
