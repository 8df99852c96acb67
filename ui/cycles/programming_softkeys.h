#pragma once

#include <functional>
#include <vector>

#include "ui/cycles/program_reference.h"
#include "ui/shell/softkey_bar.h"

class QWidget;

namespace kerf::ui {

class ProgramEditor;

// What the programming rows need from the window: showing other rows on the softkey bar (the
// cycle groups and their cycles), going back to the normal rows and, for the file list of SEL PGM
// and CALL PGM, where the program being edited lies (unset: no file list).
struct SoftkeyPaging {
    std::function<void(std::vector<SoftkeyRow>)> show;
    std::function<void()> back;
    std::function<ProgramPlace()> place = {};
};

// The programming keys of the TNC: CYCL DEF (its groups, then the group's cycles), CYCL CALL,
// TOOL CALL, the path functions L CC C CR CT RND CHF, the cycle overview, editing the cycle under
// the cursor and SPEC FCT (PLANE, FUNCTION TCPM, M128/M129, SEL PGM, CALL SELECTED PGM, CALL
// PGM). The dialogs open over `dialogParent` and write into `editor` in the program's dialect
// (Klartext or TNC ISO); a FAGOR program gets the FAGOR canned cycles (fagor_softkeys.h).
std::vector<SoftkeyRow> programmingEntryRows(ProgramEditor* editor, QWidget* dialogParent,
                                             SoftkeyPaging paging);

}  // namespace kerf::ui
