#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

#include <unistd.h>

namespace kerf::test {

// The shared folder with the seeds and the corpus of real TNC files: $KERF_SHARED_DIR, the folder
// next to the source tree, or /work/shared. Empty when none exists (tests then skip and say why).
inline std::filesystem::path sharedDir() {
    std::error_code ignored;
    if (const char* env = std::getenv("KERF_SHARED_DIR"); env && *env) {
        if (std::filesystem::is_directory(env, ignored)) return env;
    }
    for (const char* candidate : {KERF_SHARED_DIR, "/work/shared"}) {
        if (std::filesystem::is_directory(candidate, ignored)) return candidate;
    }
    return {};
}

// A fresh empty folder for this test process (tests run in parallel, one process each).
inline std::filesystem::path uniqueTempDir(const std::string& name) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                ("kerf_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace kerf::test
