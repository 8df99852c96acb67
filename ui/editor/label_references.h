#pragma once

#include <QString>
#include <QStringView>
#include <optional>
#include <unordered_map>

#include "ui/editor/block_numbers.h"

class QTextCursor;
class QTextDocument;

namespace kerf::ui {

// FAGOR block numbers are labels: (GOTO N..) and (RPT N.., N..) jump to them, and the profile
// cycles G66, G68 and G69 name their profile's first and last block with S and E (seed 002:
// labels N0-N99999999, the profile's of 4 digits). CALL, SUB, PCALL and MCALL name subroutines
// and programs by numbers of their own, not labels. When blocks are renumbered, the references
// must follow their labels.
using RenamedLabels = std::unordered_map<long long, long long>;

constexpr long long kFagorMaxLabel = 99'999'999;
constexpr long long kFagorMaxProfileLabel = 9'999;

// `line` with every reference to a renamed label rewritten (an RPT of another program, P, and a
// cycle that takes its profile from another program, Q, are left alone); unchanged when it has
// none.
QString withRenamedLabels(QStringView line, const RenamedLabels& renamed);

// Why renumbering a FAGOR program would break it; nothing is renumbered then.
struct RenumberProblem {
    enum class Kind {
        ComputedReference,    // a GOTO, RPT or profile cycle names its label by a parameter
        ProfileLabelTooLong,  // a profile's label would get more than 4 digits
        LabelTooLong,         // a block number would pass N99999999
        LabelInUse,           // a block would get the label another block carries
    };
    Kind kind = Kind::ComputedReference;
    int line = 0;         // 1-based
    long long label = 0;  // the number that would be too long or is in use
    int otherLine = 0;    // LabelInUse: the line that carries the label (1-based)
};
std::optional<RenumberProblem> fagorRenumberProblem(const QTextDocument& document,
                                                    BlockNumbering numbering);

// Why moving labels as `renamed` says would break what refers to them: a jump, repetition or
// profile naming its label through a parameter anywhere in the program (no one knows where it
// lands), or a profile label that would get more than 4 digits. Lines are the document's.
std::optional<RenumberProblem> fagorReferenceProblem(const QTextDocument& document,
                                                     const RenamedLabels& renamed);

// Rewrites the references of every line of `document` through `edit` (inside the caller's edit
// block); true if any line changed.
bool renameLabelReferences(QTextDocument& document, QTextCursor& edit,
                           const RenamedLabels& renamed);

}  // namespace kerf::ui
