#pragma once

#include <vector>

#include "ui/cycles/programming_softkeys.h"

namespace kerf::ui {

// The programming keys of a FAGOR program: "Canned cycles" (its rows list G66-G89, each key
// opening that cycle's dialog) and "Edit cycle" for the cycle block under the cursor.
std::vector<SoftkeyRow> fagorProgrammingRows(ProgramEditor* editor, QWidget* dialogParent,
                                             SoftkeyPaging paging);

}  // namespace kerf::ui
