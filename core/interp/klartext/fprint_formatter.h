#pragma once

#include <ctime>
#include <string>
#include <string_view>

#include "core/base/expected.h"
#include "core/interp/klartext/formula.h"

namespace kerf::klartext {

struct FPrintOutput {
    std::string text;
    bool append = false;  // M_APPEND: add to the file instead of replacing it
};

// Formats an FN 16 F-PRINT mask file. Each line is a quoted format with printf-like fields
// (%F, %LF, %D, %I, %S with width and precision) followed by the values (Q, QL, QR, QS, DAY, MONTH,
// YEAR2, YEAR4, HOUR, MIN, SEC) and a ';'; M_APPEND, M_CLOSE and language lines (L_ENGLISH,
// L_ALL, L_GERMAN ...; only English and all-language lines are printed) are keywords.
Expected<FPrintOutput> formatFPrint(std::string_view mask, const std::string& maskName,
                                    FormulaEnvironment& environment, const std::tm& now);

}  // namespace kerf::klartext
