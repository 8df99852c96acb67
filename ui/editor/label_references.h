#pragma once

#include <QString>
#include <QStringView>
#include <unordered_map>

class QTextCursor;
class QTextDocument;

namespace kerf::ui {

// FAGOR block numbers are labels: (GOTO N..) and (RPT N.., N..) jump to them, and the profile
// cycles G66, G68 and G69 name their profile's first and last block with S and E. When blocks
// are renumbered, the references must follow their labels.
using RenamedLabels = std::unordered_map<long long, long long>;

// `line` with every reference to a renamed label rewritten (a cycle that takes its profile from
// another program, Q, is left alone); unchanged when it has none.
QString withRenamedLabels(QStringView line, const RenamedLabels& renamed);

// Rewrites the references of every line of `document` through `edit` (inside the caller's edit
// block); true if any line changed.
bool renameLabelReferences(QTextDocument& document, QTextCursor& edit,
                           const RenamedLabels& renamed);

}  // namespace kerf::ui
