#include "core/tables/probe_type.h"

#include <array>
#include <cctype>
#include <string>

namespace kerf::tables {

namespace {

// HEIDENHAIN's workpiece probes: the cable probes orient to two directions, the infrared and
// radio ones to any. FIXED stands for a third-party probe the spindle cannot turn (on a TNC the
// machine builder configures such a probe; Kerf has no configuration for it).
constexpr std::array<ProbeType, 10> kTypes = {{
    {"TS220", ProbeOrientation::TwoDirections, SignalTransmission::Cable, true},
    {"TS230", ProbeOrientation::TwoDirections, SignalTransmission::Cable, true},
    {"TS260", ProbeOrientation::TwoDirections, SignalTransmission::Cable, true},
    {"TS440", ProbeOrientation::Any, SignalTransmission::Infrared, true},
    {"TS444", ProbeOrientation::Any, SignalTransmission::Infrared, true},
    {"TS460", ProbeOrientation::Any, SignalTransmission::Infrared, true},
    {"TS640", ProbeOrientation::Any, SignalTransmission::Infrared, true},
    {"TS642", ProbeOrientation::Any, SignalTransmission::Infrared, true},
    {"TS740", ProbeOrientation::Any, SignalTransmission::Infrared, true},
    {"FIXED", ProbeOrientation::None, SignalTransmission::Cable, false},
}};

}  // namespace

std::span<const ProbeType> probeTypes() {
    return kTypes;
}

const ProbeType* findProbeType(std::string_view typeText) {
    std::string name;
    for (char c : typeText) {
        if (c != ' ') name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    for (const ProbeType& type : kTypes) {
        if (type.name == name) return &type;
    }
    return nullptr;
}

bool canReverse(const ProbeType& type) {
    return type.supportsCentreOffset && (type.orientation == ProbeOrientation::TwoDirections ||
                                         type.orientation == ProbeOrientation::Any);
}

}  // namespace kerf::tables
