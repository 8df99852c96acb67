#pragma once

#include <QString>
#include <QStringList>

#include "ui/cycles/iso_blocks.h"

// The old cycles (7, 8, 9, 10, 11, 12, 13, 14, 18, 19, 32) that a TNC DIN/ISO program writes as one
// G block (docs/tnciso.md, "Cycles"): G54/G53, G28, G04, G73, G72, G39, G36, G37, G18, G80, G62.
namespace kerf::ui {

// The ISO block of the old cycle `cycle` from the words of its Klartext sub-blocks ("X+10 IY-5",
// "DWELL 1.5", "DEPTH = -20 PITCH = +1.5"), or why it has none (cycle 26; words ISO cannot hold).
IsoResult isoOldCycleBlock(int cycle, const QString& klartextWords);
// Back: the Klartext blocks ("CYCL DEF 7.0 DATUM SHIFT", "CYCL DEF 7.1 X+10 IY-5") of an ISO
// old-cycle block without number and '*', for readCycleBlocks; empty when it is none.
QStringList klartextOldCycleBlocks(const QString& isoBlock);

}  // namespace kerf::ui
