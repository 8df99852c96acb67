#pragma once

#include "ui/cycles/path_function.h"

class QPlainTextEdit;
class QWidget;

namespace kerf::ui {

// Opens the cycle and path-function dialogs over a Klartext program and writes what they
// return at the cursor (one undo step each), as the TNC's programming keys do.
class ProgramEntry {
public:
    ProgramEntry(QPlainTextEdit& editor, QWidget* dialogParent);

    // The cycle overview (as the TNC's GOTO), then the chosen cycle's dialog.
    bool chooseCycle();
    // The dialog of cycle `number`, prefilled with the defaults; the definition goes after the
    // block under the cursor.
    bool defineCycle(int number);
    // The dialog of the CYCL DEF under the cursor, filled with its values; false (and nothing
    // opened) when the cursor is not on a cycle definition.
    bool editCycleAtCursor();
    bool cycleCall();
    bool pathFunction(PathFunction function);

private:
    QPlainTextEdit& m_editor;
    QWidget* m_parent;
};

}  // namespace kerf::ui
