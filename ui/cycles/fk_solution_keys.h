#pragma once

#include "ui/shell/softkey_bar.h"

namespace kerf::ui {

class ProgramPanel;

// Writes `FSELECT n` for the FK element the panel offers (ProgramPanel::fkOffer): after the
// block that made the choice necessary, or in place of the FSELECT written before; one undo
// step. False without an offer, while the offer is stale (the text changed since its check) or
// with n out of range.
bool writeFkSelect(ProgramPanel& panel, int solution);

// The keys of the FK programming graphics, as on the TNC: "Show solution" draws the next
// solution highlighted, "Select solution" writes the one shown as FSELECT.
SoftkeyRow fkSolutionRow(ProgramPanel& panel);

}  // namespace kerf::ui
