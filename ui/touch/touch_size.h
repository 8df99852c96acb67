#pragma once

#include <QMessageBox>
#include <QString>
#include <optional>

class QAbstractItemView;
class QComboBox;
class QDialog;
class QWidget;

namespace kerf::ui {

// The height of everything an operator touches: a finger's target, as high as a softkey.
inline constexpr int kTouchHeight = 48;

// Makes a dialog's fields, buttons and list rows at least kTouchHeight high so each can be hit
// with a finger. Call it when the dialog has all its widgets, before it is shown.
void makeTouchSized(QDialog& dialog);
// The rows of a combo box's list as high as a softkey.
void makeTouchSizedRows(QComboBox& combo);
// The rows of a list, tree or table view as high as a softkey (its own rows, not its header).
void makeTouchSizedRows(QAbstractItemView& view);

// The prompts of the panel, touch-sized (QMessageBox's own statics make ~25 px buttons).
QMessageBox::StandardButton askTouch(QWidget* parent, const QString& title, const QString& text,
                                     QMessageBox::StandardButtons buttons,
                                     QMessageBox::StandardButton defaultButton);
// Yes / No; true for Yes.
bool confirmTouch(QWidget* parent, const QString& title, const QString& question);
// A note with OK.
void informTouch(QWidget* parent, const QString& title, const QString& text);
// One line of text (nullopt: cancelled).
std::optional<QString> askTextTouch(QWidget* parent, const QString& title, const QString& label,
                                    const QString& initial);

}  // namespace kerf::ui
