#pragma once

#include <string>

#include "core/base/diagnostic.h"
#include "core/interp/klartext/statements.h"
#include "core/program/line_reader.h"

namespace kerf::klartext {

// The parameter errors of a CYCL DEF block that show before the run, with the checks the run
// makes (core/cycles/parameter_check.h): a required parameter missing (at the CYCL DEF line) and
// a literal value outside its range (at the parameter's own line). Values given by Q parameters
// are known only when the block runs and are left to the run.
void checkCycleParameters(const CycleDefinition& def, const program::LogicalLine& line,
                          const std::string& file, DiagnosticList& out);

}  // namespace kerf::klartext
