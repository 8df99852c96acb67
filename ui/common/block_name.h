#pragma once

#include <QString>
#include <cstdint>

#include "core/program/dialect.h"

namespace kerf::ui {

// How the operator names a place in a program, as the control does: by the block number written
// at the start of the line (Klartext "17", ISO "N30"); by the file line only where the line has
// none (an ISO line without N, a line continuing a Klartext block). `blockNumber` < 0: none.

// "17", "N30" or "line 18": for a column or a row headed "Block".
QString blockShortName(int64_t blockNumber, int line, program::Dialect dialect);
// "Block 17", "N30" or "Line 18": in running text.
QString blockName(int64_t blockNumber, int line, program::Dialect dialect);

}  // namespace kerf::ui
