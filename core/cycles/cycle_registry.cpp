#include "core/cycles/cycle_registry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/cycles/detail/cycle_list.h"

namespace kerf::cycles {

namespace {

const std::array<const CycleDescriptor*, 55> kCycles = {
    &kCycle7,   &kCycle8,   &kCycle9,   &kCycle10,  &kCycle11,  &kCycle12,  &kCycle13,  &kCycle14,
    &kCycle18,  &kCycle19,  &kCycle20,  &kCycle21,  &kCycle22,  &kCycle23,  &kCycle24,  &kCycle26,
    &kCycle32,  &kCycle200, &kCycle201, &kCycle202, &kCycle203, &kCycle204, &kCycle205, &kCycle206,
    &kCycle207, &kCycle208, &kCycle209, &kCycle220, &kCycle221, &kCycle225, &kCycle232, &kCycle240,
    &kCycle241, &kCycle247, &kCycle251, &kCycle252, &kCycle253, &kCycle254, &kCycle256, &kCycle257,
    &kCycle258, &kCycle262, &kCycle263, &kCycle264, &kCycle265, &kCycle267, &kCycle25,  &kCycle270,
    &kCycle275, &kCycle233, &kCycle276, &kCycle27,  &kCycle28,  &kCycle29,  &kCycle39};

// Run for old programs, not offered in the menus.
const std::array<const CycleDescriptor*, 8> kObsoleteCycles = {
    &kCycle210, &kCycle211, &kCycle212, &kCycle213, &kCycle214, &kCycle215, &kCycle230, &kCycle231};

}  // namespace

const ParameterDescriptor* CycleDescriptor::parameter(uint16_t q) const {
    for (const ParameterDescriptor& p : parameters) {
        if (p.q == q && q != 0) return &p;
    }
    return nullptr;
}

std::span<const CycleDescriptor* const> allCycles() {
    return kCycles;
}

const CycleDescriptor* findCycle(int number) {
    const auto numbered = [number](const CycleDescriptor* c) { return c->number == number; };
    auto it = std::find_if(kCycles.begin(), kCycles.end(), numbered);
    if (it != kCycles.end()) return *it;
    auto old = std::find_if(kObsoleteCycles.begin(), kObsoleteCycles.end(), numbered);
    return old == kObsoleteCycles.end() ? nullptr : *old;
}

std::optional<CycleError> checkParameter(const CycleDescriptor& cycle, const ParameterDescriptor& p,
                                         double value) {
    const bool whole = !p.integer || std::fabs(value - std::round(value)) < 1e-9;
    if (value >= p.min - 1e-9 && value <= p.max + 1e-9 && whole) return std::nullopt;
    const std::string name = p.q != 0 ? "Q" + std::to_string(p.q) : std::string(p.word);
    return CycleError{"cycle-range",
                      p.integer ? KERF_TR_NOOP("cycle {1}: {2} ({3}) = {4} must be a whole number "
                                               "from {5} to {6}")
                                : KERF_TR_NOOP("cycle {1}: {2} ({3}) = {4} is outside {5} to {6}"),
                      {std::to_string(cycle.number), name, p.description,
                       formatForMessage(value, 4), formatFixed(p.min, 4), formatFixed(p.max, 4)}};
}

}  // namespace kerf::cycles
