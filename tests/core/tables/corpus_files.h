#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/base/atomic_file.h"
#include "test_paths.h"

namespace kerf::tables::test {

// The shared corpus of real TNC files; tests read it in place, never copy it.
inline std::filesystem::path corpusDir() {
    const std::filesystem::path shared = kerf::test::sharedDir();
    return shared.empty() ? std::filesystem::path() : shared / "corpus" / "heidenhain";
}

inline std::filesystem::path corpusFile(const std::string& name) {
    return corpusDir() / name;
}

inline std::string readCorpus(const std::string& name) {
    auto bytes = readWholeFile(corpusFile(name));
    return bytes.ok() ? *bytes : std::string();
}

inline const std::string kAamorimTool = "aamorim1913__AptPostProcessor__machine-code__TOOL.T";
inline const std::string kPyLsv2Tool = "drunsinn__pyLSV2__tests__test_files__tool.t";
inline const std::string kPalletMag = "drunsinn__pyLSV2__tests__test_files__palletmag.tab";
inline const std::string kCuttingData = "drunsinn__pyLSV2__tests__test_files__FRAES_GB.CDT";

// A fresh empty folder under the system temporary folder.
inline std::filesystem::path freshTempDir(const std::string& name) {
    return kerf::test::uniqueTempDir("tables_" + name);
}

}  // namespace kerf::tables::test
