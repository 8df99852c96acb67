#pragma once

#include <QString>
#include <QStringList>

#include "ui/cycles/path_function.h"

// The TNC DIN/ISO forms of what the programming dialogs write (docs/tnciso.md), so that the
// dialogs serve `.I` programs too: a parameter cycle "G200 DRILLING" with its "  Q200=+2 ;..."
// lines, G79 for CYCL CALL, G00/G01/G02/G03/G06/G24/G25 and I/J for the path functions, "T n G17
// S.." for TOOL CALL. Texts without block number and without the closing '*'.
namespace kerf::ui {

// The ISO block, or the message (UI language) why the entry has no ISO form.
struct IsoResult {
    QString block;
    QString error;  // empty: `block` is valid
};

// From the Klartext cycle definition writeCycleBlocks returns: a parameter cycle as "G200 ..."
// (the SL and cylinder-surface cycles 20-39 as G120-G139), an old cycle as its one G block
// (iso_old_cycles.h).
IsoResult isoCycleBlock(const QStringList& klartextBlocks);
// Back: an ISO cycle block (number and '*' removed) as the Klartext block(s) readCycleBlocks
// reads; empty when it is not a cycle definition.
QStringList klartextCycleBlocks(const QString& isoBlock);
// The path function or TOOL CALL from the dialog's values (checked by checkPathFunction).
IsoResult isoPathBlock(PathFunction function, const QStringList& values);

}  // namespace kerf::ui
