#include "graphics/headless/virtual_display.h"

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string_view>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/base/translate.h"

extern char** environ;

namespace kerf::graphics {

namespace {

Diagnostic displayError(std::string message) {
    return Diagnostic::make(Severity::Error, "display", "", 0, 0, std::move(message));
}

}  // namespace

std::string findXvfb() {
    const char* path = std::getenv("PATH");
    std::string_view dirs = path != nullptr ? path : "/usr/bin:/bin";
    while (!dirs.empty()) {
        const size_t colon = dirs.find(':');
        const std::string_view dir = dirs.substr(0, colon);
        if (!dir.empty()) {
            std::filesystem::path candidate = std::filesystem::path(dir) / "Xvfb";
            if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
        }
        if (colon == std::string_view::npos) break;
        dirs.remove_prefix(colon + 1);
    }
    return {};
}

Expected<std::shared_ptr<VirtualDisplay>> VirtualDisplay::ensure() {
    std::shared_ptr<VirtualDisplay> display(new VirtualDisplay());
    if (const char* current = std::getenv("DISPLAY"); current != nullptr && *current != '\0') {
        display->m_display = current;
        return display;
    }
    const std::string xvfb = findXvfb();
    if (xvfb.empty()) {
        return displayError(KERF_TR_NOOP(
            "no X display: DISPLAY is not set and Xvfb is not installed (apt-get install xvfb, "
            "or run under xvfb-run)"));
    }
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) return displayError(KERF_TR_NOOP("cannot start Xvfb: pipe"));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    // The child keeps the pipe's write end (dup2 clears close-on-exec) and gets no stdin/stdout.
    posix_spawn_file_actions_adddup2(&actions, fds[1], 3);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    std::vector<std::string> args{xvfb,           "-displayfd", "3",   "-screen", "0",
                                  "1920x1080x24", "-nolisten",  "tcp", "-noreset"};
    std::vector<char*> argv;
    for (auto& arg : args)
        argv.push_back(arg.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, xvfb.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (spawned != 0) {
        ::close(fds[0]);
        return displayError(KERF_TR_NOOP("cannot start Xvfb"));
    }
    display->m_pid = pid;
    // Xvfb writes the display number and a newline once it accepts connections.
    std::string number;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (number.find('\n') == std::string::npos) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) break;
        pollfd pfd{fds[0], POLLIN, 0};
        const int ready = ::poll(&pfd, 1, static_cast<int>(left.count()));
        if (ready < 0 && errno == EINTR) continue;
        if (ready <= 0) break;
        char buffer[32];
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n <= 0) break;
        number.append(buffer, static_cast<size_t>(n));
    }
    ::close(fds[0]);
    while (!number.empty() && (number.back() == '\n' || number.back() == '\r'))
        number.pop_back();
    if (number.empty() || number.find_first_not_of("0123456789") != std::string::npos) {
        return displayError(KERF_TR_NOOP("Xvfb did not start (no display number within 10 s)"));
    }
    display->m_display = ":" + number;
    ::setenv("DISPLAY", display->m_display.c_str(), 1);
    return display;
}

VirtualDisplay::~VirtualDisplay() {
    if (m_pid > 0) {
        ::unsetenv("DISPLAY");
        ::kill(m_pid, SIGTERM);
        int status = 0;
        ::waitpid(m_pid, &status, 0);
    }
}

}  // namespace kerf::graphics
