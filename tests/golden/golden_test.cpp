// Runs every case under tests/golden/<dialect>/<case>/ through `kerf run` and compares with the
// expectations written by hand next to the program:
//   program.*       the NC program (any extension; the dialect follows it or the `args` file)
//   args            optional options, one per line: "--machine lathe", "--tool-table TOOL.T",
//                   "--stock" (material removal: the report's "stock" section),
//                   "--work-offset Z-350" ...
//   expected.json   values the report must contain (numbers within 1e-4 unless "tolerance" says
//                   otherwise, whole numbers such as counts exactly; arrays must have the same
//                   length; keys not listed are not checked)
//   expected.trace  the exact canonical trace
//   expected.diag   the exact diagnostics, one per line, paths relative to the case folder
// Each case runs in a temporary copy of its folder, so programs may write files.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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

std::vector<std::string> caseNames() {
    std::vector<std::string> names;
    for (const auto& dialect : fs::directory_iterator(kGoldenRoot)) {
        if (!dialect.is_directory()) continue;
        for (const auto& c : fs::directory_iterator(dialect.path())) {
            // An ISO twin without expectations of its own is the IsoTwin test's.
            const bool expects = fs::exists(c.path() / "expected.json") ||
                                 fs::exists(c.path() / "expected.trace") ||
                                 fs::exists(c.path() / "expected.diag");
            if (c.is_directory() && expects) {
                names.push_back(dialect.path().filename().string() + "/" +
                                c.path().filename().string());
            }
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

fs::path findProgram(const fs::path& dir) {
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().stem() == "program") return entry.path();
    }
    return {};
}

RunOptions optionsFor(const fs::path& dir) {
    RunOptions options;
    options.program = findProgram(dir);
    std::istringstream args(readText(dir / "args"));
    std::string line;
    while (std::getline(args, line)) {
        std::istringstream words(line);
        std::string key, value;
        words >> key >> value;
        if (key == "--machine") {
            options.machine = value.find('.') != std::string::npos ? (dir / value).string() : value;
        } else if (key == "--dialect") {
            options.dialect = value;
        } else if (key == "--tool-table") {
            options.toolTable = dir / value;
        } else if (key == "--max-blocks") {
            options.maxBlocks = std::stoull(value);
        } else if (key == "--stock") {
            options.stock = true;
        } else if (key == "--work-offset") {
            options.workOffset = value;
        } else if (key == "--block-skip") {
            options.blockSkip = true;
        } else if (!key.empty()) {
            ADD_FAILURE() << "unknown option in " << (dir / "args") << ": " << key;
        }
    }
    return options;
}

void compareJson(const nlohmann::json& expected, const nlohmann::json& actual,
                 const std::string& path, double tolerance) {
    if (expected.is_object()) {
        ASSERT_TRUE(actual.is_object()) << path << " is not an object";
        for (const auto& [key, value] : expected.items()) {
            if (path.empty() && key == "tolerance") continue;
            ASSERT_TRUE(actual.contains(key)) << path << "." << key << " is missing";
            compareJson(value, actual.at(key), path + "." + key, tolerance);
        }
    } else if (expected.is_array()) {
        ASSERT_TRUE(actual.is_array()) << path << " is not an array";
        ASSERT_EQ(expected.size(), actual.size()) << path << " length";
        for (size_t i = 0; i < expected.size(); ++i) {
            compareJson(expected[i], actual[i], path + "[" + std::to_string(i) + "]", tolerance);
        }
    } else if (expected.is_number_integer() && actual.is_number_integer()) {
        EXPECT_EQ(expected, actual) << path;  // counts are exact whatever the tolerance
    } else if (expected.is_number() && actual.is_number()) {
        EXPECT_NEAR(expected.get<double>(), actual.get<double>(), tolerance) << path;
    } else {
        EXPECT_EQ(expected, actual) << path;
    }
}

class Golden : public testing::TestWithParam<std::string> {};

TEST_P(Golden, MatchesHandDerivedExpectations) {
    const fs::path source = kGoldenRoot / GetParam();
    const fs::path out = fs::temp_directory_path() / ("kerf_golden_" + std::to_string(::getpid()));
    fs::remove_all(out);
    const fs::path dir = out / "case";
    fs::create_directories(dir);
    fs::copy(source, dir, fs::copy_options::recursive);
    RunOptions options = optionsFor(dir);
    ASSERT_FALSE(options.program.empty()) << "no program.* in " << source;
    options.reportFile = out / "report.json";
    options.traceFile = out / "trace.txt";
    options.stateDir = out / "state";
    std::ostringstream diagnostics;
    runProgramCommand(options, diagnostics);

    if (fs::exists(dir / "expected.json")) {
        nlohmann::json expected = nlohmann::json::parse(readText(dir / "expected.json"));
        double tolerance = expected.value("tolerance", 1e-4);
        nlohmann::json actual = nlohmann::json::parse(readText(options.reportFile.value()));
        compareJson(expected, actual, "", tolerance);
    }
    if (fs::exists(dir / "expected.trace")) {
        EXPECT_EQ(readText(dir / "expected.trace"), readText(options.traceFile.value()));
    }
    if (fs::exists(dir / "expected.diag")) {
        std::string text = diagnostics.str();
        const std::string prefix = dir.string() + "/";
        for (size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix)) {
            text.erase(at, prefix.size());
        }
        EXPECT_EQ(readText(dir / "expected.diag"), text);
    }
    fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(Cases, Golden, testing::ValuesIn(caseNames()),
                         [](const testing::TestParamInfo<std::string>& param) {
                             std::string name = param.param;
                             for (char& c : name) {
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             }
                             return name;
                         });

}  // namespace
}  // namespace kerf::app
