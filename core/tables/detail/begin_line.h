#pragma once

#include <string>
#include <string_view>

#include "core/base/expected.h"

namespace kerf::tables::detail {

// "BEGIN TOOL.T MM Version: 'Update:110.24'" or "BEGIN TOOL    .T       MM": the TNC pads the
// name, so spaces may stand before the dot. The unit is optional (.CDT files have none).
struct BeginLine {
    std::string name;       // TOOL
    std::string extension;  // T
    std::string unit;       // MM, INCH or empty
    std::string rest;       // whatever follows, e.g. "Version: 'Update:110.24'"
};

Expected<BeginLine> parseBeginLine(std::string_view text, const std::string& fileName);

}  // namespace kerf::tables::detail
