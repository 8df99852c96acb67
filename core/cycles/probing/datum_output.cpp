#include "core/cycles/probing/datum_output.h"

#include "core/base/translate.h"

namespace kerf::cycles::probing {

std::optional<CycleError> checkTransfer(int cycle, const CycleValues& values) {
    if (values.integer(305) != 0 && values.integer(303) == -1) {
        return probingError(cycle, "PRB-004",
                            KERF_TR_NOOP("cycle {1}: define the measured-value transfer (Q303)"));
    }
    return std::nullopt;
}

void setDatum(const CycleValues& values, ProbingResults& results, DatumResult datum) {
    results.tableRow = values.integer(305);
    results.transfer = values.integer(303);
    results.datum = datum;
}

std::optional<CycleError> toolAxisDatum(ProbeSequence& sequence, const CycleValues& values,
                                        DatumResult& datum) {
    if (values.integer(381) != 1) return std::nullopt;
    double surface = 0.0;
    if (auto e = sequence.touchDown(Vec2(values.number(382), values.number(383)),
                                    values.number(384), surface)) {
        return e;
    }
    datum.measured[2] = surface;
    datum.nominal[2] = values.number(333);
    return std::nullopt;
}

}  // namespace kerf::cycles::probing
