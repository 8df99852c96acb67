#pragma once

#include <QObject>
#include <functional>
#include <optional>
#include <vector>

#include "core/task/operating_mode.h"
#include "ui/shell/softkey_bar.h"

class QWidget;

namespace kerf::ui {

class MachineSession;

// What the machine-mode softkeys need from the window.
struct MachineRowContext {
    MachineSession* session = nullptr;
    QWidget* dialogParent = nullptr;
    // Starts the editor's program (at a line, for a start in mid-program).
    std::function<void(std::optional<uint32_t> startLine)> startProgram;
    // Asks for the block to start at (its number, or a line); the line, or nullopt.
    std::function<std::optional<int>()> askStartBlock;
    std::function<void()> refresh;  // the keys' labels follow the session (single block on/off)
};

// The softkey rows of a machine mode: Manual (jog, increment, home, spindle, coolant, set
// preset; on a mill manual probing), Electronic handwheel (the handwheel first, then Manual's
// rows), MDI (execute a block) and program run (NC start, NC stop, resume, stop, start at block,
// single block).
std::vector<SoftkeyRow> machineModeRows(task::MachineMode mode, const MachineRowContext& context);

// The jog increments the increment key steps through; 0 = continuous jog.
const std::vector<double>& jogIncrementsMm();

}  // namespace kerf::ui
