#pragma once

#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::tnciso {

// Lets the TNC engine read DIN/ISO programs: called programs named `.I`, and the main program
// when `mainProgramIso` (the loader decides it from the file name or the --dialect option).
void enableIso(klartext::KlartextSettings& settings, bool mainProgramIso);

}  // namespace kerf::tnciso
