#pragma once

#include <QApplication>

namespace kerf::ui::test {

// One QApplication for the whole test process, on the offscreen platform: widget tests need no
// display. Created on first use and kept until the process ends.
inline QApplication& testApp() {
    static int argc = 1;
    static char name[] = "kerf_ui_test";
    static char* argv[] = {name, nullptr};
    static QApplication* app = [] {
        qputenv("QT_QPA_PLATFORM", "offscreen");
        return new QApplication(argc, argv);
    }();
    return *app;
}

}  // namespace kerf::ui::test
