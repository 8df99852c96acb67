#include "core/interp/fagor/tables/tool_touch_off.h"

#include <cmath>

namespace kerf::fagor {

bool touchOff(ToolOffsetTable& table, const TouchOff& touch) {
    if (touch.offset < 1 || touch.offset > ToolOffsetTable::kMaxOffset) return false;
    if (touch.axis != Axis::X && touch.axis != Axis::Z) return false;
    if (!std::isfinite(touch.shownMm) || !std::isfinite(touch.knownMm) ||
        !std::isfinite(touch.activeMm)) {
        return false;
    }
    const ToolOffset current = table.get(touch.offset);
    const bool x = touch.axis == Axis::X;
    const double holder = touch.shownMm - touch.activeMm;
    const double length = touch.knownMm - holder - (x ? current.wearX : current.wearZ);
    return table.set(touch.offset, x ? 'X' : 'Z', length);
}

}  // namespace kerf::fagor
