#include "core/cycles/legacy/legacy_cycles.h"

#include <algorithm>
#include <array>

#include "core/cycles/legacy/legacy_list.h"

namespace kerf::cycles {

namespace {

using K = LegacyWordKind;

// 1.1 SET UP, 1.2 DEPTH, 1.3 PECKG, 1.4 DWELL, 1.5 F
constexpr LegacyWordSlot kPeckingSlots[] = {
    {1, K::Value, 1}, {2, K::Value, 2}, {3, K::Value, 3}, {4, K::Value, 4}, {5, K::Feed, 5}};
// 2.1 SET UP, 2.2 DEPTH, 2.3 DWELL, 2.4 F
constexpr LegacyWordSlot kTappingSlots[] = {
    {1, K::Value, 1}, {2, K::Value, 2}, {3, K::Value, 3}, {4, K::Feed, 4}};
// 17.1 SET UP, 17.2 DEPTH, 17.3 PITCH
constexpr LegacyWordSlot kRigidTappingSlots[] = {
    {1, K::Value, 1}, {2, K::Value, 2}, {3, K::Value, 3}};
// 3.1 SET UP, 3.2 DEPTH, 3.3 PECKG F, 3.4 X (or Y: the slot's axis), 3.5 Y, 3.6 F
constexpr LegacyWordSlot kSlotSlots[] = {{1, K::Value, 1}, {2, K::Value, 2}, {3, K::Value, 3},
                                         {3, K::Feed, 4},  {4, K::Value, 5}, {4, K::Axis, 6},
                                         {5, K::Value, 7}, {6, K::Feed, 8}};
// 4.1 SET UP, 4.2 DEPTH, 4.3 PECKG F, 4.4 X, 4.5 Y, 4.6 F DR RADIUS
constexpr LegacyWordSlot kPocketSlots[] = {
    {1, K::Value, 1}, {2, K::Value, 2}, {3, K::Value, 3},     {3, K::Feed, 4}, {4, K::Value, 5},
    {5, K::Value, 6}, {6, K::Feed, 7},  {6, K::Direction, 8}, {6, K::Value, 9}};
// 5.1 SET UP, 5.2 DEPTH, 5.3 PECKG F, 5.4 RADIUS, 5.5 F DR
constexpr LegacyWordSlot kCircularPocketSlots[] = {
    {1, K::Value, 1}, {2, K::Value, 2}, {3, K::Value, 3},    {3, K::Feed, 4},
    {4, K::Value, 5}, {5, K::Feed, 6},  {5, K::Direction, 7}};

const std::array<LegacyCycle, 6> kLegacyCycles = {{
    {&kCycle1, kPeckingSlots, 5},
    {&kCycle2, kTappingSlots, 4},
    {&kCycle3, kSlotSlots, 6},
    {&kCycle4, kPocketSlots, 6},
    {&kCycle5, kCircularPocketSlots, 5},
    {&kCycle17, kRigidTappingSlots, 3},
}};

}  // namespace

const LegacyCycle* findLegacyCycle(int number) {
    auto it =
        std::find_if(kLegacyCycles.begin(), kLegacyCycles.end(),
                     [number](const LegacyCycle& c) { return c.descriptor->number == number; });
    return it == kLegacyCycles.end() ? nullptr : &*it;
}

}  // namespace kerf::cycles
