#include "core/task/tool_length_touch_off.h"

#include <string>

#include "core/base/translate.h"
#include "core/program/nc_root.h"
#include "core/tables/tool_table.h"

namespace kerf::task {

Expected<double> touchOffToolLength(const std::filesystem::path& ncRoot,
                                    const ToolLengthTouch& touch) {
    if (touch.tool < 0) {
        return Diagnostic::make(Severity::Error, "touch-off", "", 0, 0,
                                KERF_TR_NOOP("tool length touch-off: no tool in the spindle"));
    }
    const program::NcRoot root(ncRoot);
    const std::filesystem::path file = root.path() / "TOOL.T";
    auto bytes = root.read(file);
    if (!bytes) return bytes.error();
    auto tools = tables::ToolTable::parse(*bytes, file.filename().string());
    if (!tools) return tools.error();
    const tables::ToolData* tool = tools->byNumber(touch.tool);
    if (tool == nullptr) {
        return Diagnostic::make(Severity::Error, "touch-off", file.string(), 0, 0,
                                KERF_TR_NOOP("tool length touch-off: tool {1} is not in TOOL.T"),
                                std::to_string(touch.tool));
    }
    const double length = tool->length + (touch.shownMm - touch.knownMm);
    if (MaybeError failed = tools->setNumber(touch.tool, "L", length)) return *failed;
    if (MaybeError failed = root.replace(file, tools->serialize())) return *failed;
    return length;
}

}  // namespace kerf::task
