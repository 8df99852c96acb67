#pragma once

class QComboBox;
class QDialog;

namespace kerf::ui {

// Makes a dialog's fields, buttons and list rows at least as high as a softkey (48 px) so each
// can be hit with a finger. Call it when the dialog has all its widgets, before it is shown.
void makeTouchSized(QDialog& dialog);
// The rows of a combo box's list as high as a softkey.
void makeTouchSizedRows(QComboBox& combo);

}  // namespace kerf::ui
