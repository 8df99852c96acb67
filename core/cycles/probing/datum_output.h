#pragma once

#include "core/cycles/probing/probe_sequence.h"

namespace kerf::cycles::probing {

// What the datum cycles 408-419 share (spec 1.12.1): the Q303/Q305 check before anything
// moves, the optional touch in the tool axis (Q381..Q384, Q333) and the datum they hand over.
std::optional<CycleError> checkTransfer(int cycle, const CycleValues& values);
void setDatum(const CycleValues& values, ProbingResults& results, DatumResult datum);
std::optional<CycleError> toolAxisDatum(ProbeSequence& sequence, const CycleValues& values,
                                        DatumResult& datum);

}  // namespace kerf::cycles::probing
