// Cycle 1493 PROBING EXTRUSION. The seeds name it only (seed 004, spec 8.8 rule 12); the
// parameters are those of HEIDENHAIN's 14xx manuals as far as Kerf knows them, the rest
// docs/probing.md marks [choice].
#include "core/cycles/probing/probing_14xx.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor kParameters[] = {
    choice(1140, KERF_TR_NOOP("Direction of the extrusion: 1 main axis, 2 secondary, 3 tool axis"),
           1, 3, 3),
    length(1145, KERF_TR_NOOP("Length of the extrusion (incremental, the sign gives the way)")),
    choice(1146, KERF_TR_NOOP("Number of further touch points along the extrusion"), 1, 99, 1),
    choice(1149, KERF_TR_NOOP("Extrusion active for: 0 the next 14xx cycle, 1 all following"), 0, 1,
           0)};

constexpr uint16_t kCopied[] = {1140, 1145, 1146};

}  // namespace

std::optional<Extrusion> extrusionOf(const CycleValues& values) {
    if (!values.has(1145) || values.number(1145) == 0.0) return std::nullopt;
    Extrusion e;
    e.repeats = values.integer(1146);
    e.step[values.integer(1140) - 1] = values.number(1145) / e.repeats;
    return e;
}

void addExtrusion(const CycleValues& extrusion, CycleValues& cycle) {
    for (uint16_t q : kCopied)
        cycle.set(q, extrusion.number(q));
}

bool extrusionStays(const CycleValues& extrusion) {
    return extrusion.integer(1149) == 1;
}

// No run: the interpreter keeps the values for the next 14xx cycle.
const ProbingCycleDescriptor kProbe1493{
    kExtrusionCycle, KERF_TR_NOOP("PROBING EXTRUSION"), kParameters, nullptr, {}};

}  // namespace kerf::cycles::probing
