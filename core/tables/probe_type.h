#pragma once

#include <cstdint>
#include <span>
#include <string_view>

// The probe models the TYPE column of the touch-probe table names (spec 1.3, impl. note): what
// each can do decides how calibration runs (462/463: the 180-degree reversal that finds the
// centre offset needs a probe that can be oriented) and whether the spindle can turn it to
// each probing direction (TRACK, cycle 441 Q399).
namespace kerf::tables {

enum class ProbeOrientation : uint8_t {
    None,           // the probe cannot be turned with the spindle (its cable or mount holds it)
    OneDirection,   // it can be oriented to CAL_ANG only
    TwoDirections,  // to CAL_ANG and half a turn from it (HEIDENHAIN cable probes)
    Any,            // to any angle (HEIDENHAIN infrared and radio probes)
};

enum class SignalTransmission : uint8_t { Cable, Infrared };

struct ProbeType {
    std::string_view name;  // as the TYPE column holds it, e.g. "TS460"
    ProbeOrientation orientation;
    SignalTransmission signal;
    bool supportsCentreOffset;  // CAL_OF1/CAL_OF2 can be measured (by reversal) and used
};

// The catalogue, in the order the TYPE column offers it.
std::span<const ProbeType> probeTypes();

// The model a TYPE cell names ("TS460", "TS 460" and "ts460" alike); nullptr when unknown.
const ProbeType* findProbeType(std::string_view typeText);

// True when the probe can be turned by half a turn (a reversal measurement).
bool canReverse(const ProbeType& type);

}  // namespace kerf::tables
