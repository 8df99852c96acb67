#include "ui/settings/settings_page.h"

#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTranslator>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "core/machine/machine_schema.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/common/diagnostic_text.h"
#include "ui/settings/settings_model.h"

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

bool anyMessageContains(const QSignalSpy& spy, const QString& text) {
    for (const auto& message : spy) {
        if (message.at(1).toString().contains(text)) return true;
    }
    return false;
}

TEST(SettingsPage, RowsComeFromTheSchemaByGroup) {
    test::testApp();
    const machine::MachineConfig mill = *machine::loadMachine("mill");
    SettingsModel model(mill);
    const size_t keys = machine::parameterKeys(mill).size();
    ASSERT_GT(static_cast<size_t>(model.rowCount()), keys);  // parameters plus headings
    EXPECT_TRUE(model.isHeading(0));
    EXPECT_EQ(model.data(model.index(0, SettingsModel::Name), Qt::DisplayRole),
              QStringLiteral("Machine"));
    const int rapid = model.rowOf("rapid_velocity");
    ASSERT_GT(rapid, 0);
    EXPECT_EQ(model.data(model.index(rapid, SettingsModel::Unit), Qt::DisplayRole),
              QStringLiteral("mm/s"));
    EXPECT_EQ(model.data(model.index(rapid, SettingsModel::Description), Qt::DisplayRole),
              QStringLiteral("Path velocity of rapid moves"));
    EXPECT_TRUE(model.flags(model.index(rapid, SettingsModel::Value)) & Qt::ItemIsEditable);
    EXPECT_FALSE(model.flags(model.index(rapid, SettingsModel::Default)) & Qt::ItemIsEditable);
    // The spindle parameters follow a "spindle" heading; each axis has its own group.
    const int spindle = model.rowOf("spindle.min_rpm");
    ASSERT_GT(spindle, 0);
    EXPECT_TRUE(model.isHeading(spindle - 1));
    EXPECT_EQ(model.data(model.index(spindle - 1, SettingsModel::Name), Qt::DisplayRole),
              QStringLiteral("spindle"));
    const int xVelocity = model.rowOf("axes.X.max_velocity");
    ASSERT_GT(xVelocity, 0);
    EXPECT_EQ(model.data(model.index(xVelocity, SettingsModel::Name), Qt::DisplayRole),
              QStringLiteral("max_velocity"));
}

// Translates the first heading the way kerf_pt.ts does.
class PortugueseHeadings : public QTranslator {
public:
    QString translate(const char* context, const char* source, const char* disambiguation,
                      int n) const override {
        (void)disambiguation;
        (void)n;
        if (QString::fromUtf8(context) == QLatin1String("kerf::ui::SettingsModel") &&
            QString::fromUtf8(source) == QLatin1String("Machine"))
            return QStringLiteral("M\u00e1quina");
        return {};
    }
    bool isEmpty() const override { return false; }
};

// The language is chosen after the page was made (at start, or in MOD): the first heading
// stayed "Machine" in Portuguese.
TEST(SettingsPage, HeadingsFollowTheLanguageChosenAfterThePageWasMade) {
    test::testApp();
    const fs::path file = kerf::test::uniqueTempDir("settings_language") / "mill.toml";
    SettingsPage page(*machine::loadMachine("mill"), file, false);
    SettingsModel& model = *page.model();
    const QSignalSpy refreshed(&model, &QAbstractItemModel::dataChanged);
    PortugueseHeadings portuguese;
    QCoreApplication::installTranslator(&portuguese);
    QCoreApplication::processEvents();  // LanguageChange reaches the page
    const QString heading =
        model.data(model.index(0, SettingsModel::Name), Qt::DisplayRole).toString();
    const int refreshes = refreshed.count();
    QCoreApplication::removeTranslator(&portuguese);
    QCoreApplication::processEvents();
    EXPECT_EQ(heading, QStringLiteral("M\u00e1quina"));
    EXPECT_GE(refreshes, 1) << "the views were not told to fetch the texts again";
    EXPECT_EQ(model.data(model.index(0, SettingsModel::Name), Qt::DisplayRole),
              QStringLiteral("Machine"));
}

TEST(SettingsPage, OutOfRangeIsRefusedNamingTheKeyAndAValidValueIsSavedAndReloads) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_settings_save");
    const fs::path file = dir / "mill.toml";
    const machine::MachineConfig mill = *machine::loadMachine("mill");
    SettingsPage page(mill, file, false);
    QSignalSpy messages(&page, &SettingsPage::message);
    ASSERT_TRUE(page.unlock("123"));
    SettingsModel& model = *page.model();

    // The schema allows 0.1 ... 5000 mm/s.
    EXPECT_FALSE(model.setValueText("rapid_velocity", "6000"));
    EXPECT_TRUE(anyMessageContains(messages, "rapid_velocity = 6000 is outside the allowed range"));
    EXPECT_FALSE(model.setValueText("rapid_velocity", "fast"));
    EXPECT_TRUE(anyMessageContains(messages, "rapid_velocity = \"fast\" has the wrong type"));
    EXPECT_FALSE(page.modified());

    const int rapid = model.rowOf("rapid_velocity");
    ASSERT_TRUE(model.setData(model.index(rapid, SettingsModel::Value), "750", Qt::EditRole));
    EXPECT_EQ(model.data(model.index(rapid, SettingsModel::Value), Qt::DisplayRole),
              QStringLiteral("750"));
    ASSERT_TRUE(model.setValueText("kind", "lathe"));  // an enum, by its spelling in the file
    EXPECT_EQ(model.config().kind, machine::MachineKind::Lathe);
    model.undo();
    EXPECT_EQ(model.config().kind, machine::MachineKind::Mill);
    ASSERT_TRUE(page.modified());
    ASSERT_TRUE(page.save());
    EXPECT_FALSE(page.modified());
    EXPECT_TRUE(anyMessageContains(messages, "apply when Kerf is restarted"));

    auto reloaded = machine::loadMachine(file.string());
    ASSERT_TRUE(reloaded) << reloaded.error().format();
    EXPECT_EQ(reloaded->rapidVelocityMmPerS, 750.0);
    EXPECT_EQ(reloaded->maxFeedMmPerS, mill.maxFeedMmPerS);
    // Written atomically: the new file and nothing else (no temporary left behind).
    size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir))
        ++files;
    EXPECT_EQ(files, 1u);
}

TEST(SettingsPage, RulesBetweenParametersBlockTheSave) {
    test::testApp();
    const fs::path dir = kerf::test::uniqueTempDir("hmi_settings_rules");
    const fs::path file = dir / "mill.toml";
    ASSERT_FALSE(writeFileAtomically(file, "base = \"mill\"\n").has_value());
    SettingsPage page(*machine::loadMachine("mill"), file, false);
    QSignalSpy messages(&page, &SettingsPage::message);
    ASSERT_TRUE(page.unlock("123"));
    // Each value is in range, but the spindle's minimum may not exceed its maximum.
    const QString maxRpm = page.model()
                               ->data(page.model()->index(page.model()->rowOf("spindle.max_rpm"),
                                                          SettingsModel::Value),
                                      Qt::DisplayRole)
                               .toString();
    ASSERT_TRUE(
        page.model()->setValueText("spindle.min_rpm", QString::number(maxRpm.toDouble() + 1)));
    EXPECT_FALSE(page.save());
    EXPECT_TRUE(anyMessageContains(messages, "spindle"));
    EXPECT_TRUE(anyMessageContains(messages, "Not saved"));
    EXPECT_EQ(readWholeFile(file).value(), "base = \"mill\"\n");
}

TEST(SettingsPage, EditingAsksForTheCodeNumberViewingDoesNot) {
    test::testApp();
    const fs::path file = kerf::test::uniqueTempDir("hmi_settings_code") / "mill.toml";
    machine::MachineConfig mill = *machine::loadMachine("mill");
    EXPECT_EQ(mill.parameterCode, 123);  // the TNC's code for the user parameters
    mill.parameterCode = 4711;
    SettingsPage page(mill, file, false);
    QSignalSpy messages(&page, &SettingsPage::message);
    SettingsModel& model = *page.model();
    const int rapid = model.rowOf("rapid_velocity");
    const QModelIndex value = model.index(rapid, SettingsModel::Value);
    const QString before = model.data(value, Qt::DisplayRole).toString();
    EXPECT_FALSE(before.isEmpty());  // shown while locked
    // ... but not the code number itself.
    const QModelIndex codeValue = model.index(model.rowOf("parameter_code"), SettingsModel::Value);
    EXPECT_EQ(model.data(codeValue, Qt::DisplayRole).toString(), QStringLiteral("****"));
    EXPECT_TRUE(page.locked());
    EXPECT_FALSE(model.flags(value) & Qt::ItemIsEditable);
    EXPECT_FALSE(model.setData(value, "750", Qt::EditRole));
    EXPECT_EQ(model.data(value, Qt::DisplayRole).toString(), before);

    // The default 123 is not this machine's code; typed into the page's field it is refused.
    auto* code = page.findChild<QLineEdit*>("settingsCode");
    auto* unlockButton = page.findChild<QPushButton*>("settingsUnlock");
    ASSERT_NE(code, nullptr);
    ASSERT_NE(unlockButton, nullptr);
    code->setText("123");
    unlockButton->click();
    EXPECT_TRUE(page.locked());
    EXPECT_TRUE(anyMessageContains(messages, "Wrong code number"));
    EXPECT_FALSE(page.unlock("abc"));

    code->setText("4711");
    unlockButton->click();
    EXPECT_FALSE(page.locked());
    EXPECT_TRUE(model.flags(value) & Qt::ItemIsEditable);
    EXPECT_EQ(model.data(codeValue, Qt::DisplayRole).toString(), QStringLiteral("4711"));
    EXPECT_TRUE(model.setData(value, "750", Qt::EditRole));
    EXPECT_EQ(model.config().rapidVelocityMmPerS, 750.0);
}

}  // namespace
}  // namespace kerf::ui
