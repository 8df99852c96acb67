#include "ui/settings/mod_page.h"

#include <QComboBox>
#include <QLabel>
#include <QSignalSpy>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"

namespace kerf::ui {
namespace {

TEST(ModPage, EmitsTheChosenDisplayAndKeepsItForTheNextStart) {
    test::testApp();
    const QString file =
        QString::fromStdString((kerf::test::uniqueTempDir("hmi_mod") / "hmi.ini").string());
    const machine::MachineConfig lathe = *machine::loadMachine("lathe");
    {
        ModPage page(lathe, file);
        EXPECT_EQ(page.displaySettings().positionKind, PositionKind::Actual);
        EXPECT_FALSE(page.displaySettings().inch);
        QSignalSpy changed(&page, &ModPage::displaySettingsChanged);
        auto* position = page.findChild<QComboBox*>("modPosition");
        ASSERT_NE(position, nullptr);
        ASSERT_EQ(position->count(), 6);
        EXPECT_EQ(position->itemText(2), QStringLiteral("REF ACTL"));
        EXPECT_EQ(position->itemText(4), QStringLiteral("LAG"));
        // The operator picks DIST in the list.
        position->setCurrentIndex(5);
        emit position->activated(5);
        ASSERT_EQ(changed.count(), 1);
        const auto chosen = changed.at(0).at(0).value<DisplaySettings>();
        EXPECT_EQ(chosen.positionKind, PositionKind::DistanceToGo);
        EXPECT_FALSE(chosen.inch);
        page.setInch(true);
        ASSERT_EQ(changed.count(), 2);
        EXPECT_TRUE(changed.at(1).at(0).value<DisplaySettings>().inch);
        page.setInch(true);  // no change, no signal
        EXPECT_EQ(changed.count(), 2);
        const QString info = page.findChild<QLabel*>("modInfo")->text();
        EXPECT_TRUE(info.contains(QString::fromStdString(lathe.name))) << info.toStdString();
        EXPECT_TRUE(info.contains("Kerf 0.")) << info.toStdString();
        // The licence, as an About box would show it (the LICENSE file is GPL-3.0).
        EXPECT_TRUE(info.contains("GNU General Public License, version 3 or later"))
            << info.toStdString();
    }
    ModPage again(lathe, file);
    EXPECT_EQ(again.displaySettings().positionKind, PositionKind::DistanceToGo);
    EXPECT_TRUE(again.displaySettings().inch);
}

TEST(ModPage, LanguageChoiceIsRequestedFromTheShell) {
    test::testApp();
    const QString file = QString::fromStdString(
        (kerf::test::uniqueTempDir("hmi_mod_language") / "hmi.ini").string());
    ModPage page(*machine::loadMachine("mill"), file);
    page.setLanguages({"en", "pt", "pl"}, "en");
    QSignalSpy requested(&page, &ModPage::languageRequested);
    auto* language = page.findChild<QComboBox*>("modLanguage");
    ASSERT_NE(language, nullptr);
    EXPECT_EQ(language->currentText(), QStringLiteral("EN"));
    emit language->activated(2);
    ASSERT_EQ(requested.count(), 1);
    EXPECT_EQ(requested.at(0).at(0).toString(), QStringLiteral("pl"));
}

}  // namespace
}  // namespace kerf::ui
