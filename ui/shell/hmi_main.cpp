#include "ui/shell/hmi_main.h"

#include <QApplication>

#include <iostream>

#include "core/machine/machine_loader.h"
#include "ui/shell/main_window.h"

namespace kerf::ui {

int runHmi(int argc, char** argv, const HmiOptions& options) {
    QApplication application(argc, argv);
    DiagnosticList problems;
    auto machine = machine::loadMachine(options.machine, &problems);
    if (!machine) {
        for (const Diagnostic& d : problems) std::cerr << d.format() << '\n';
        if (problems.empty()) std::cerr << machine.error().format() << '\n';
        return 1;
    }
    MainWindow window(QString::fromStdString(machine->name));
    window.resize(options.width, options.height);
    window.show();
    if (!options.screenshot.empty()) {
        // Let the window lay itself out and paint before taking the picture.
        for (int i = 0; i < 5; ++i) application.processEvents();
        const QString file = QString::fromStdString(options.screenshot);
        if (!window.grab().save(file)) {
            std::cerr << "kerf: cannot write " << options.screenshot << '\n';
            return 1;
        }
        return 0;
    }
    return application.exec();
}

}  // namespace kerf::ui
