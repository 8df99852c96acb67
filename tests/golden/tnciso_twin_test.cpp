// Every case under tests/golden/tnciso/<case>/ with a `twin` file (naming a conversational golden
// case, or a program of the source tree such as examples/probing/SETUP.H) or a `twin.H` (a
// conversational program next to it) is a DIN/ISO program written by hand from the manuals as the
// twin of a conversational one: both must give the same canonical trace. The ISO program runs in a
// copy of the conversational case's folder (its tables and called programs) with the same options.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "app/runner/headless_run.h"

namespace kerf::app {
namespace {

namespace fs = std::filesystem;

const fs::path kGoldenRoot = fs::path(KERF_SOURCE_DIR) / "tests" / "golden";

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

std::vector<std::string> twinCases() {
    std::vector<std::string> names;
    for (const auto& c : fs::directory_iterator(kGoldenRoot / "tnciso")) {
        if (fs::exists(c.path() / "twin") || fs::exists(c.path() / "twin.H")) {
            names.push_back(c.path().filename().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

struct RunResult {
    std::string trace;
    std::string diagnostics;
    int exitCode = 0;
};

RunResult runIn(const fs::path& dir, const fs::path& program, const fs::path& out) {
    RunOptions options;
    options.program = program;
    std::istringstream args(readText(dir / "args"));
    std::string line;
    while (std::getline(args, line)) {
        std::istringstream words(line);
        std::string key, value;
        words >> key >> value;
        if (key == "--machine")
            options.machine = value.find('.') != std::string::npos ? (dir / value).string() : value;
        if (key == "--work-offset") options.workOffset = value;
        if (key == "--tool-table") options.toolTable = dir / value;
        if (key == "--max-blocks") options.maxBlocks = std::stoull(value);
    }
    options.traceFile = out / (program.filename().string() + ".trace");
    options.stateDir = out / "state";
    std::ostringstream diagnostics;
    RunResult run;
    run.exitCode = runProgramCommand(options, diagnostics);
    run.trace = readText(*options.traceFile);
    run.diagnostics = diagnostics.str();
    return run;
}

class IsoTwin : public testing::TestWithParam<std::string> {};

TEST_P(IsoTwin, GivesTheSameCanonicalTraceAsItsConversationalTwin) {
    const fs::path iso = kGoldenRoot / "tnciso" / GetParam();
    const fs::path out = fs::temp_directory_path() / ("kerf_twin_" + std::to_string(::getpid()));
    fs::remove_all(out);
    const fs::path dir = out / "case";
    fs::create_directories(dir);
    fs::path conversational = dir / "twin.H";
    if (fs::exists(iso / "twin")) {
        std::string name = readText(iso / "twin");
        name.erase(name.find_last_not_of(" \n") + 1);
        if (name.ends_with(".H")) {
            // A program of the source tree (examples/...): the case holds its tables.
            fs::copy(fs::path(KERF_SOURCE_DIR) / name, conversational);
        } else {
            fs::copy(kGoldenRoot / "klartext" / name, dir, fs::copy_options::recursive);
            conversational = dir / "program.H";
        }
    }
    fs::copy(iso, dir, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    const RunResult expected = runIn(dir, conversational, out);
    const RunResult actual = runIn(dir, dir / "program.I", out);
    EXPECT_FALSE(expected.trace.empty());
    EXPECT_EQ(expected.trace, actual.trace) << actual.diagnostics;
    EXPECT_EQ(expected.exitCode, actual.exitCode) << actual.diagnostics;
    fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(Cases, IsoTwin, testing::ValuesIn(twinCases()));

}  // namespace
}  // namespace kerf::app
