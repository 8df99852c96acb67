// `kerf`: checks and runs programs without loading Qt or VTK (their dynamic linking alone costs
// about as much CPU as interpreting 200,000 blocks, docs/benchmarks.md); the operator panel and
// pictures are kerf-gui's, started in this process's place with the same arguments.
#include <iostream>

#include "app/command_line.h"
#include "app/gui_binary.h"

int main(int argc, char** argv) {
    kerf::app::CommandLine commandLine;
    if (auto exitCode = commandLine.parse(argc, argv)) return *exitCode;
    if (!commandLine.needsGraphics()) return commandLine.runHeadless(nullptr);
#ifndef KERF_WITH_UI
    if (!commandLine.headless()) {
        std::cerr << "kerf: built without the HMI; use 'kerf check' or 'kerf run'\n";
        return 2;
    }
#endif
    return kerf::app::execGuiBinary(argv);
}
