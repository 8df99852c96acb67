// docs/machine-config.md holds blocks generated from the schema and the preset files. This test
// fails when they drift; run it with KERF_UPDATE_DOCS=1 to rewrite the blocks in place.

#include <cstdlib>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/builtin_machines.h"
#include "core/machine/machine_loader.h"
#include "core/machine/machine_schema.h"

namespace kerf::machine {
namespace {

const std::string kDocPath = std::string(KERF_SOURCE_DIR) + "/docs/machine-config.md";

std::string cell(std::string_view text) {
    return text.empty() ? "" : " " + std::string(text);
}

void appendRow(std::string& out, const std::string& key, const ParameterDescriptor& d) {
    std::string unit(d.unit);
    if (d.scope == ParameterScope::Axis && d.rotaryUnit != d.unit) {
        unit += " or " + std::string(d.rotaryUnit);
    }
    std::string allowed;
    if (d.type == ParameterType::Number || d.type == ParameterType::Integer) {
        allowed = formatNumber(d.minimum) + " … " + formatNumber(d.maximum);
    } else if (d.type == ParameterType::String) {
        allowed = "text";
    } else {
        allowed = formatAllowedValues(d);
    }
    out += "| `" + key + "` | " + std::string(parameterTypeName(d.type)) + " |" + cell(unit) +
           " | `" + formatParameterValue(d.defaultValue) + "` | " + allowed + " | " +
           d.description + " |\n";
}

std::string parameterTable() {
    std::string out =
        "| Key | Type | Unit | Default | Allowed | Description |\n"
        "|---|---|---|---|---|---|\n";
    for (const auto& d : machineParameters())
        appendRow(out, std::string(d.key), d);
    for (const auto& d : axisParameters())
        appendRow(out, "axes.<L>." + std::string(d.key), d);
    return out;
}

std::string presetBlock(std::string_view name) {
    return "```toml\n" + std::string(builtinMachineToml(name)) + "```\n";
}

// Replaces the text between "<!-- BEGIN GENERATED: name -->\n" and "<!-- END GENERATED -->";
// returns false when the markers are missing.
bool replaceBlock(std::string& doc, const std::string& name, const std::string& content) {
    std::string begin = "<!-- BEGIN GENERATED: " + name + " -->\n";
    size_t start = doc.find(begin);
    if (start == std::string::npos) return false;
    start += begin.size();
    size_t end = doc.find("<!-- END GENERATED -->", start);
    if (end == std::string::npos) return false;
    doc.replace(start, end - start, content);
    return true;
}

TEST(MachineDocs, GeneratedBlocksMatchTheSchemaAndPresets) {
    Expected<std::string> doc = readWholeFile(kDocPath);
    ASSERT_TRUE(doc.ok()) << doc.error().format();
    std::string expected = *doc;
    ASSERT_TRUE(replaceBlock(expected, "parameters", parameterTable()));
    for (std::string_view name : builtinMachineNames()) {
        ASSERT_TRUE(replaceBlock(expected, "preset " + std::string(name), presetBlock(name)))
            << name;
    }
    if (expected != *doc && std::getenv("KERF_UPDATE_DOCS")) {
        ASSERT_FALSE(writeFileAtomically(kDocPath, expected));
        GTEST_SKIP() << "rewrote " << kDocPath;
    }
    EXPECT_EQ(*doc, expected) << kDocPath << " is out of date; run this test with "
                              << "KERF_UPDATE_DOCS=1 to regenerate it";
}

// The text between the first "```<language>\n" after `from` and the closing fence.
std::string fencedBlock(const std::string& doc, size_t from, std::string_view language) {
    std::string open = "```" + std::string(language) + "\n";
    size_t start = doc.find(open, from);
    if (start == std::string::npos) return "";
    start += open.size();
    size_t end = doc.find("```", start);
    return end == std::string::npos ? "" : doc.substr(start, end - start);
}

TEST(MachineDocs, ErrorExampleIsWhatTheLoaderPrints) {
    Expected<std::string> doc = readWholeFile(kDocPath);
    ASSERT_TRUE(doc.ok()) << doc.error().format();
    size_t example = doc->find("For this file, `mylathe.toml`:");
    ASSERT_NE(example, std::string::npos);
    std::string toml = fencedBlock(*doc, example, "toml");
    std::string printed = fencedBlock(*doc, example, "text");
    DiagnosticList problems;
    EXPECT_FALSE(parseMachine(toml, "mylathe.toml", &problems).ok());
    std::string actual;
    for (const Diagnostic& d : problems)
        actual += d.format() + "\n";
    EXPECT_EQ(printed, actual);
}

}  // namespace
}  // namespace kerf::machine
