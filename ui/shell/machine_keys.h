#pragma once

#include <QWidget>
#include <vector>

#include "core/task/operating_mode.h"

class QPushButton;

namespace kerf::ui {

class ModeController;

// The vertical column of mode keys beside the screen: the five machine modes and the two
// programming modes, each a touch-sized key; the active modes are shown pressed.
class MachineKeys : public QWidget {
    Q_OBJECT

public:
    MachineKeys(ModeController& modes, QWidget* parent = nullptr);

    QPushButton* machineKey(task::MachineMode mode) const;
    QPushButton* programmingKey(task::ProgrammingMode mode) const;
    void retranslate();

private:
    void refresh();

    ModeController& m_modes;
    std::vector<QPushButton*> m_machineKeys;      // indexed by MachineMode
    std::vector<QPushButton*> m_programmingKeys;  // indexed by ProgrammingMode
};

}  // namespace kerf::ui
