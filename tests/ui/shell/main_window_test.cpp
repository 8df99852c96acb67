#include "ui/shell/main_window.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QLabel>
#include <QPushButton>

namespace kerf::ui {
namespace {

int argc = 1;
char name[] = "test_ui_shell";
char* argv[] = {name, nullptr};

TEST(MainWindow, HeaderNamesModesAndSoftkeysAreTouchSized) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    MainWindow window("Kerf vertical mill");
    window.show();
    app.processEvents();
    auto* machineMode = window.findChild<QLabel*>("machineMode");
    auto* programmingMode = window.findChild<QLabel*>("programmingMode");
    ASSERT_NE(machineMode, nullptr);
    ASSERT_NE(programmingMode, nullptr);
    EXPECT_FALSE(machineMode->text().isEmpty());
    const auto keys = window.findChildren<QPushButton*>();
    ASSERT_EQ(keys.size(), 8);
    for (const QPushButton* key : keys) EXPECT_GE(key->height(), 48);
    EXPECT_TRUE(window.windowTitle().contains("Kerf vertical mill"));
}

}  // namespace
}  // namespace kerf::ui
