#pragma once

#include <QApplication>
#include <memory>

#include "graphics/headless/virtual_display.h"

namespace kerf::ui::test {

// One QApplication for the whole test process, on a virtual X display (the viewport needs
// OpenGL, so not the offscreen platform). Shared by every test file of the binary: each had its
// own, so a run of tests from two files made a second QApplication and crashed at exit.
inline QApplication& viewportTestApp() {
    static std::shared_ptr<graphics::VirtualDisplay> display = [] {
        auto ensured = graphics::VirtualDisplay::ensure();
        return ensured ? *ensured : nullptr;
    }();
    static int argc = 1;
    static char name[] = "test_ui_viewport";
    static char* argv[] = {name, nullptr};
    static QApplication* app = new QApplication(argc, argv);  // kept until the process ends
    return *app;
}

}  // namespace kerf::ui::test
