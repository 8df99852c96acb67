#pragma once

#include <optional>
#include <string>

#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_parameter.h"
#include "core/cycles/cycle_values.h"
#include "core/geometry/axes.h"

// What the 14xx probing cycles share beyond the 4xx cycles' parameters (spec 8.8): nominal
// positions written "nominal@actual" or "?", and cycle 1493 PROBING EXTRUSION.
namespace kerf::cycles::probing {

// --- Actual positions -------------------------------------------------------------------------
// A nominal position may be written "nominal@actual" (Q1100=+50@+50.05): the position is known,
// the cycle does not probe it and takes the actual value for its results.
bool takesActualPosition(int cycle, uint16_t q);
// `d` was written "nominal@actual" but takes no actual position.
CycleError actualPositionError(const std::string& owner, const ParameterDescriptor& d);
// The actual value travels with the cycle's values as an entry of its own.
void setActualPosition(CycleValues& values, uint16_t q, double actual);
std::optional<double> actualPosition(const CycleValues& values, uint16_t q);

// --- Unknown positions (semi-automatic mode) -----------------------------------------------
// A nominal position written "?" (Q1100=?) is not known: at each touch the program stops, the
// operator positions the probe, and the touched coordinate counts as nominal and actual. The
// same parameters as "nominal@actual" take it.
// `d` was written "?" but cannot be unknown.
CycleError unknownPositionError(const std::string& owner, const ParameterDescriptor& d);
void setUnknownPosition(CycleValues& values, uint16_t q);
bool unknownPosition(const CycleValues& values, uint16_t q);

// --- Extrusion (cycle 1493) -------------------------------------------------------------------
// 1493 probes nothing itself. The interpreter keeps its parameters and copies them into the next
// 14xx cycle's values (with Q1149 = 1 into every following one), which repeats each of its touch
// points along a straight line.
inline constexpr int kExtrusionCycle = 1493;

struct Extrusion {
    Vec3 step{0.0, 0.0, 0.0};  // from one repetition to the next, local coordinates
    int repeats = 0;           // further touches for each touch point
};

// The extrusion a 14xx cycle's values carry, or none (no 1493 before it, or one with Q1145 = 0).
std::optional<Extrusion> extrusionOf(const CycleValues& values);
// Copies 1493's parameters into the values of the 14xx cycle it modifies.
void addExtrusion(const CycleValues& extrusion, CycleValues& cycle);
// Q1149 = 1: the extrusion stays for the following 14xx cycles too.
bool extrusionStays(const CycleValues& extrusion);

}  // namespace kerf::cycles::probing
