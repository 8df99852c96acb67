#include "core/interp/fagor/location_codes.h"

#include <array>

namespace kerf::fagor {

TipDirection tipDirection(int locationCode) {
    // X upwards, Z to the right (tool above the centreline); numbered counter-clockwise from the
    // upper-left corner.
    static constexpr std::array<TipDirection, 10> kTable = {{
        {0.0, 0.0},    // F0: centre
        {1.0, -1.0},   // F1: upper left
        {0.0, -1.0},   // F2: left
        {-1.0, -1.0},  // F3: lower left (external turning)
        {-1.0, 0.0},   // F4: bottom
        {-1.0, 1.0},   // F5: lower right
        {0.0, 1.0},    // F6: right
        {1.0, 1.0},    // F7: upper right
        {1.0, 0.0},    // F8: top
        {0.0, 0.0},    // F9: centre
    }};
    if (locationCode < 0 || locationCode > 9) return {};
    return kTable[static_cast<size_t>(locationCode)];
}

}  // namespace kerf::fagor
