#include "ui/shell/hmi_main.h"

#include <QApplication>

#include <iostream>

#include "core/machine/machine_loader.h"
#include "ui/shell/main_window.h"

namespace kerf::ui {

int runHmi(int argc, char** argv, const std::string& machineName) {
    QApplication application(argc, argv);
    DiagnosticList problems;
    auto machine = machine::loadMachine(machineName, &problems);
    if (!machine) {
        for (const Diagnostic& d : problems) std::cerr << d.format() << '\n';
        if (problems.empty()) std::cerr << machine.error().format() << '\n';
        return 1;
    }
    MainWindow window(QString::fromStdString(machine->name));
    window.show();
    return application.exec();
}

}  // namespace kerf::ui
