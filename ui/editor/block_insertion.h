#pragma once

#include <QString>
#include <optional>
#include <vector>

#include "core/program/dialect.h"
#include "ui/editor/block_numbers.h"
#include "ui/editor/label_references.h"

class QTextCursor;
class QTextDocument;

namespace kerf::ui {

// What Enter does to the block numbers. The new line takes the next number and the lines after it
// that no longer ascend are renumbered (Klartext: every following block). With the cursor on the
// line's number (or before its words) the new block opens before the line, which moves down whole:
// splitting there would carry the number into the new line's words.
//
// FAGOR block numbers are labels: when the renumbering would change which block a GOTO, an RPT or
// a profile cycle names (a label named through a parameter, a profile label of more than 4
// digits, a label beyond N99999999, a label another block carries), no number changes and the new
// line gets none; `problem` says why.
struct BlockInsertion {
    bool before = false;  // the new line goes before the cursor's line
    QString prefix;       // the new line's number ("N30 ", "13 "); empty: none
    struct Move {
        int line = 0;  // 0-based, in the document before the insertion
        BlockNumber current;
        long long wanted = 0;
    };
    std::vector<Move> moves;
    RenamedLabels renamed;  // FAGOR: the labels that move, old -> new
    std::optional<RenumberProblem> problem;
};

// `renumberFollowing`: false for programs too long to renumber on every Enter (only the new
// line's number is chosen then).
BlockInsertion planBlockInsertion(const QTextDocument& document, const QTextCursor& cursor,
                                  program::Dialect dialect, bool renumberFollowing);

}  // namespace kerf::ui
