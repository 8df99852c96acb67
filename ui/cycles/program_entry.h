#pragma once

#include "core/program/dialect.h"
#include "ui/cycles/path_function.h"
#include "ui/cycles/program_reference.h"
#include "ui/cycles/special_function.h"

class QPlainTextEdit;
class QString;
class QWidget;

namespace kerf::ui {

struct LineRange;

// Opens the cycle and path-function dialogs over a Klartext or TNC ISO program and writes what
// they return at the cursor (one undo step each), as the TNC's programming keys do. An entry
// without an ISO form (an old-style cycle, FAUTO, mixed absolute and incremental coordinates) is
// explained in a message and not written.
class ProgramEntry {
public:
    // `place`: where the program lies, for the file list of SEL PGM and CALL PGM (none when
    // empty).
    ProgramEntry(QPlainTextEdit& editor, QWidget* dialogParent,
                 program::Dialect dialect = program::Dialect::Klartext, ProgramPlace place = {});

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
    // SPEC FCT: the function's dialog (none for a function without words), its block in the
    // program's dialect at the cursor.
    bool specialFunction(SpecialFunction function);

private:
    // Writes the Klartext `blocks` (or their ISO form) at the cursor, or into `replace`.
    bool write(const QStringList& blocks, const LineRange* replace = nullptr);
    bool writePath(PathFunction function, const QStringList& values);
    // Tells the operator why nothing was written; false.
    bool explain(const QString& why);

    QPlainTextEdit& m_editor;
    QWidget* m_parent;
    program::Dialect m_dialect;
    ProgramPlace m_place;
};

}  // namespace kerf::ui
