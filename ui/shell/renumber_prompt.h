#pragma once

#include <QString>

class QWidget;

namespace kerf::ui {

class MessagePanel;
class ProgramEditor;
struct RenumberProblem;

// The Renumber blocks softkey. A FAGOR program is renumbered as the 8035 does it: the operator
// chooses the first label and the step (seed 002 §1.3), and the jumps, repetitions and profile
// cycles follow their labels; when they could not (a label named by a parameter, a profile label
// beyond 4 digits, a label beyond N99999999) nothing changes and `messages` says why. Other
// programs are renumbered at once.
void renumberBlocks(QWidget* parent, ProgramEditor& editor, MessagePanel& messages);

// Why a FAGOR program's blocks were not renumbered, for the message line.
QString renumberProblemText(const RenumberProblem& problem);

}  // namespace kerf::ui
