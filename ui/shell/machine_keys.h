#pragma once

#include <QWidget>
#include <vector>

#include "core/task/operating_mode.h"

class QPushButton;

namespace kerf::ui {

class ModeController;

// The vertical column of mode keys beside the screen: the five machine modes and the two
// programming modes, each a touch-sized key; the active modes are shown pressed. Below them, on a
// machine, the red emergency stop key and Machine on.
class MachineKeys : public QWidget {
    Q_OBJECT

public:
    MachineKeys(ModeController& modes, QWidget* parent = nullptr);

    QPushButton* machineKey(task::MachineMode mode) const;
    QPushButton* programmingKey(task::ProgrammingMode mode) const;
    QPushButton* emergencyStopKey() const { return m_emergencyStop; }
    QPushButton* machineOnKey() const { return m_machineOn; }
    // A latching emergency stop button (the simulated machine's) shows pressed until released.
    void setEmergencyStopPressed(bool pressed);
    void retranslate();

signals:
    void emergencyStopPressed();
    void emergencyStopReleased();
    void machineOnPressed();

private:
    void refresh();
    void applyEmergencyStopLook();

    ModeController& m_modes;
    std::vector<QPushButton*> m_machineKeys;      // indexed by MachineMode
    std::vector<QPushButton*> m_programmingKeys;  // indexed by ProgrammingMode
    QPushButton* m_emergencyStop = nullptr;
    QPushButton* m_machineOn = nullptr;
    bool m_emergencyStopLatched = false;
};

}  // namespace kerf::ui
