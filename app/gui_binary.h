#pragma once

namespace kerf::app {

// Replaces this process by kerf-gui, found relative to this binary (KERF_GUI_FROM_BIN: the same
// relative path in the build tree and in an installation), with the same arguments, argv[0]
// included. Returns only when that fails: the exit code, after a message on standard error.
int execGuiBinary(char** argv);

}  // namespace kerf::app
