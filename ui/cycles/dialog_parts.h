#pragma once

#include "ui/touch/touch_size.h"

class QBoxLayout;
class QDialog;
class QLabel;
class QPushButton;

namespace kerf::ui {

// Parts the cycle and path-function dialogs share.

// The red line under the fields that says why a value is refused; added to `layout`.
QLabel* addRefusalLine(QDialog& dialog, QBoxLayout& layout, const char* objectName);

// OK and Cancel (texts set by the dialog's retranslate), wired to accept and reject. Neither is
// a default button: Enter belongs to the fields (next parameter).
void addOkCancel(QDialog& dialog, QBoxLayout& layout, QPushButton*& ok, QPushButton*& cancel);

// Most of the window the dialog opens over: at its own size hint the descriptions of the long
// languages (Portuguese, Polish) got a column a word wide and the ranges were cut off.
void sizeToWindow(QDialog& dialog);

}  // namespace kerf::ui
