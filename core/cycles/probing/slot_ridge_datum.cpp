// Datum cycles 408 SLOT CENTER REF PT and 409 RIDGE CENTER REF PT (spec 3): two touches across
// the measuring axis; the centre line gets the datum Q405.
#include "core/cycles/probing/datum_output.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor kWidth =
    length(311, KERF_TR_NOOP("Width of the slot or ridge, whatever its orientation"), 0.0);
constexpr ParameterDescriptor kDatumInMeasuringAxis =
    length(405, KERF_TR_NOOP("New datum in the measuring axis for the centre"));

constexpr ParameterDescriptor kSlotParameters[] = {
    length(321, KERF_TR_NOOP("Centre in the main axis")),
    length(322, KERF_TR_NOOP("Centre in the secondary axis")),
    kWidth,
    kMeasuringAxis,
    kMeasuringHeight,
    kSetUpClearance,
    kClearanceHeight,
    kMoveToClearance,
    kTableRow,
    kDatumInMeasuringAxis,
    kTransfer,
    kProbeToolAxis,
    kToolAxisPointMain,
    kToolAxisPointSecondary,
    kToolAxisSurface,
    kDatumToolAxis};

constexpr ParameterDescriptor kRidgeParameters[] = {
    length(321, KERF_TR_NOOP("Centre in the main axis")),
    length(322, KERF_TR_NOOP("Centre in the secondary axis")),
    kWidth,
    kMeasuringAxis,
    kMeasuringHeight,
    kSetUpClearance,
    kClearanceHeight,
    kTableRow,
    kDatumInMeasuringAxis,
    kTransfer,
    kProbeToolAxis,
    kToolAxisPointMain,
    kToolAxisPointSecondary,
    kToolAxisSurface,
    kDatumToolAxis};

constexpr uint16_t kResults[] = {157, 166};

// Touch 1 on the +e wall, touch 2 on the -e wall: outward from inside the slot (408), inward
// from outside the ridge (409). A slot too narrow to pre-position near its walls is probed from
// its centre both times, without rising in between; the ridge is always passed over at the
// clearance height (409 has no Q301).
std::optional<CycleError> centreLine(int cycle, bool slot, const CycleValues& given,
                                     const ProbeData& probe, ProbingMachine& machine,
                                     ProbingResults& results) {
    if (auto e = checkTransfer(cycle, given)) return e;
    CycleValues v = given;
    const int axis = v.integer(272) - 1;
    Vec2 e(0.0, 0.0);
    e[axis] = 1.0;
    const Vec2 centre(v.number(321), v.number(322));
    const double half = v.number(311) / 2.0;
    ProbeSequence sizing(cycle, v, probe, machine);
    const bool fromCentre = slot && half - sizing.standOff() <= 0.0;
    if (!slot || fromCentre) v.set(301, slot ? 0.0 : 1.0);
    ProbeSequence sequence(cycle, v, probe, machine);
    const Vec2* start = fromCentre ? &centre : nullptr;
    const double inward = slot ? 1.0 : -1.0;
    Vec2 plus, minus;
    if (auto err = sequence.touchInPlane(centre + half * e, inward * e, plus, start)) return err;
    if (auto err = sequence.touchInPlane(centre - half * e, -inward * e, minus, start)) return err;
    const double line = (plus.dot(e) + minus.dot(e)) / 2.0;
    results.set(157, line);
    results.set(166, plus.dot(e) - minus.dot(e));
    DatumResult datum;
    datum.measured[static_cast<size_t>(axis)] = line;
    datum.nominal[static_cast<size_t>(axis)] = v.number(405);
    if (auto err = toolAxisDatum(sequence, v, datum)) return err;
    sequence.retract();
    setDatum(v, results, datum);
    return std::nullopt;
}

std::optional<CycleError> run408(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return centreLine(408, true, v, p, m, r);
}
std::optional<CycleError> run409(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return centreLine(409, false, v, p, m, r);
}

}  // namespace

const ProbingCycleDescriptor kProbe408{408, KERF_TR_NOOP("SLOT CENTER REF PT"), kSlotParameters,
                                       run408, kResults};
const ProbingCycleDescriptor kProbe409{409, KERF_TR_NOOP("RIDGE CENTER REF PT"), kRidgeParameters,
                                       run409, kResults};

}  // namespace kerf::cycles::probing
