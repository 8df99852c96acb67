#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/base/atomic_file.h"

namespace kerf::tables::test {

// The shared corpus of real TNC files; tests read it in place, never copy it.
inline std::filesystem::path corpusDir() {
    return std::filesystem::path(KERF_SHARED_DIR) / "corpus" / "heidenhain";
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
    std::filesystem::path dir = std::filesystem::temp_directory_path() / ("kerf_tables_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace kerf::tables::test
