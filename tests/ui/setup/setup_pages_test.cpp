// The "Tables" and "MOD" softkeys of the main window, the pages behind them, and pictures of
// those pages for a person to look at.
#include <QComboBox>
#include <QImage>
#include <QPixmap>
#include <QSettings>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/settings/mod_page.h"
#include "ui/settings/settings_page.h"
#include "ui/shell/main_window.h"
#include "ui/shell/workspace.h"
#include "ui/status/position_display.h"
#include "ui/tables/table_chooser.h"
#include "ui/tables/table_editor.h"

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

void shoot(MainWindow& window, const char* name) {
    for (int i = 0; i < 5; ++i)
        QCoreApplication::processEvents();
    const QString file = QStringLiteral("hmi_%1.png").arg(name);
    ASSERT_TRUE(window.grab().save(file)) << name;
    EXPECT_EQ(QImage(file).size(), QSize(1280, 800)) << name;
}

TEST(SetupPages, TablesKeyOpensTheChooserAndADatumTable) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_setup_tables");
    // The MOD page's choices go to a settings file of this test, not the user's.
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope,
                       QString::fromStdString(dir.string()));
    MainWindow window(contextIn(dir, "mill"));
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.softkeys()->pressId("tables"));
    auto* chooser = window.findChild<TableChooser*>();
    ASSERT_NE(chooser, nullptr);
    EXPECT_EQ(window.workspace()->currentPage(), chooser);
    shoot(window, "tables_chooser");
    // The datum table's key creates the standard table in a fresh NC root and opens it.
    ASSERT_TRUE(window.softkeys()->pressId(
        QStringLiteral("table_%1").arg(static_cast<int>(TableKind::Datum))));
    EXPECT_EQ(window.workspace()->currentPage(), window.tables());
    EXPECT_TRUE(fs::exists(dir / "DATUM.D"));
    EXPECT_EQ(window.tables()->path(), dir / "DATUM.D");
    EXPECT_EQ(readWholeFile(dir / "DATUM.D").value().substr(0, 17), "BEGIN DATUM.D MM\n");
    shoot(window, "datum_table");
    ASSERT_TRUE(window.softkeys()->pressId("back"));
    EXPECT_NE(window.workspace()->currentPage(), window.tables());
}

TEST(SetupPages, LatheTablesAreTheFagorTables) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_setup_lathe");
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope,
                       QString::fromStdString(dir.string()));
    MainWindow window(contextIn(dir, "lathe"));
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.softkeys()->pressId("tables"));
    ASSERT_TRUE(window.softkeys()->pressId(
        QStringLiteral("table_%1").arg(static_cast<int>(TableKind::FagorToolOffsets))));
    EXPECT_EQ(window.tables()->path(), dir / "fagor_tool_offsets.tab");
    ASSERT_TRUE(window.tables()->insertRow());
    ASSERT_TRUE(window.tables()->save());
    const std::string saved = readWholeFile(dir / "fagor_tool_offsets.tab").value();
    EXPECT_NE(saved.find("\nD1 X0 Z0 R0 F0 I0 K0\n"), std::string::npos) << saved;
    shoot(window, "lathe_tool_offsets");
}

TEST(SetupPages, ModChoiceReachesThePositionDisplayAndSettingsOpenFromMod) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_setup_mod");
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope,
                       QString::fromStdString(dir.string()));
    MainWindow window(contextIn(dir, "mill"));
    window.resize(1280, 800);
    window.show();
    ASSERT_TRUE(window.softkeys()->pressId("mod"));
    auto* mod = window.findChild<ModPage*>();
    ASSERT_NE(mod, nullptr);
    EXPECT_EQ(window.workspace()->currentPage(), mod);
    mod->setPositionKind(PositionKind::Lag);
    mod->setInch(true);
    EXPECT_EQ(window.positions()->displaySettings().positionKind, PositionKind::Lag);
    EXPECT_TRUE(window.positions()->displaySettings().inch);
    shoot(window, "mod");
    ASSERT_TRUE(window.softkeys()->pressId("modSettings"));
    auto* settings = window.findChild<SettingsPage*>();
    ASSERT_NE(settings, nullptr);
    EXPECT_EQ(window.workspace()->currentPage(), settings);
    shoot(window, "settings");
}

}  // namespace
}  // namespace kerf::ui
