#pragma once

#include <QString>
#include <optional>

class QWidget;

namespace kerf::ui {

class MessagePanel;
class ProgramEditor;

// Asks for a place in the editor's program the way the operator names it (Go to, Start at
// block): the block number when the program numbers its blocks (Klartext "17", ISO "N30", typed
// as 30), the file line when it does not. Returns the line of that block; nullopt when the
// operator cancels or no line carries the number (a message in `messages` says so).
std::optional<int> askForBlockLine(QWidget* parent, const QString& title,
                                   const ProgramEditor& editor, MessagePanel& messages);

}  // namespace kerf::ui
