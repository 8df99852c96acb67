#include "app/gui_binary.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <system_error>

#include <unistd.h>

namespace kerf::app {

int execGuiBinary(char** argv) {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) {
        std::cerr << "kerf: cannot find its own binary: " << error.message() << '\n';
        return 2;
    }
    const std::filesystem::path gui = (self.parent_path() / KERF_GUI_FROM_BIN).lexically_normal();
    ::execv(gui.c_str(), argv);
    std::cerr << "kerf: cannot start the operator panel " << gui.string() << ": "
              << std::strerror(errno) << '\n';
    return 2;
}

}  // namespace kerf::app
