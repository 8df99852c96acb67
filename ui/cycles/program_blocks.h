#pragma once

#include <QStringList>
#include <optional>

#include "core/program/dialect.h"

class QPlainTextEdit;
class QTextDocument;

namespace kerf::ui {

// Lines (0-based, inclusive) of the NC blocks the dialogs read and write in a Klartext or TNC ISO
// program. A block is its numbered line plus the unnumbered lines after it ("  Q200=+2 ;..." of a
// cycle).
struct LineRange {
    int first = 0;
    int last = 0;
};

LineRange blockAt(const QTextDocument& document, int line,
                  program::Dialect dialect = program::Dialect::Klartext);
// The cycle definition at `line`: a new-style CYCL DEF block, or an old-style "CYCL DEF 7.0"
// with its sub-blocks (the cursor may be on any of them).
std::optional<LineRange> cycleDefinitionAt(const QTextDocument& document, int line,
                                           program::Dialect dialect = program::Dialect::Klartext);
// The blocks of `range` without their block numbers, the lines of a block joined by '\n'; an ISO
// cycle block is given in its Klartext form (readCycleBlocks reads it).
QStringList blockTexts(const QTextDocument& document, LineRange range,
                       program::Dialect dialect = program::Dialect::Klartext);

// "BEGIN PGM ... INCH" or ISO "%NAME G70": lengths in the dialogs are then in inch.
bool programIsInch(const QTextDocument& document);

// Inserts `blocks` (texts without numbers) after the block under the cursor — before END PGM
// when the cursor is on it — numbers them and renumbers the blocks after them, in one undo
// step. The cursor goes to the first inserted block. ISO blocks get "N.." and " *"; they go
// before the program's last block ("N99999999 %NAME G71 *") and only blocks whose numbers
// would no longer increase are renumbered, by the program's step.
void insertBlocks(QPlainTextEdit& editor, const QStringList& blocks,
                  program::Dialect dialect = program::Dialect::Klartext);
// Replaces the blocks of `range` by `blocks`, keeping the first block number; one undo step.
void replaceBlocks(QPlainTextEdit& editor, LineRange range, const QStringList& blocks,
                   program::Dialect dialect = program::Dialect::Klartext);

}  // namespace kerf::ui
