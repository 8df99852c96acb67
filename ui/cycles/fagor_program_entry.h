#pragma once

class QPlainTextEdit;
class QWidget;

namespace kerf::ui {

// Writes FAGOR canned cycles into a FAGOR program through FagorCycleDialog, one undo step each.

// The dialog of cycle G<g>; its block goes on a new line after the cursor's (or into the
// cursor's line when that is empty), numbered N.. when the program numbers its blocks and the
// number is free.
bool defineFagorCycle(QPlainTextEdit& editor, QWidget* dialogParent, int g);
// The dialog of the cycle block under the cursor, filled with its values; the cycle's words are
// replaced, the label before them and a comment after them stay. False (nothing opened) when
// the cursor's line holds no canned cycle.
bool editFagorCycleAtCursor(QPlainTextEdit& editor, QWidget* dialogParent);

}  // namespace kerf::ui
