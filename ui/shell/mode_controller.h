#pragma once

#include <QObject>
#include <QString>
#include <functional>

#include "core/task/operating_mode.h"

namespace kerf::ui {

// Which of the two active modes fills the screen: a TNC shows one machine mode and one
// programming mode, and the operator switches the screen between them.
enum class ScreenMode { Machine, Programming };

// The UI side of core/task's ModeMachine: forwards the operator's mode requests, reports refusals
// as translated messages and tells the window what to show.
class ModeController : public QObject {
    Q_OBJECT

public:
    // A programming station has no machine: the machine modes are refused and the
    // programming mode fills the screen.
    explicit ModeController(bool machineConnected = true, QObject* parent = nullptr);

    bool machineConnected() const { return m_modes.machineConnected(); }

    // Asked on every machine-mode request: is a program or MDI block moving the machine?
    void setMovingQuery(std::function<bool()> moving) { m_moving = std::move(moving); }

    task::MachineMode machineMode() const { return m_modes.machineMode(); }
    task::ProgrammingMode programmingMode() const { return m_modes.programmingMode(); }
    ScreenMode screen() const { return m_screen; }

    // Both bring the requested mode to the screen. False (and refused()) if the task refuses.
    bool requestMachineMode(task::MachineMode mode);
    void requestProgrammingMode(task::ProgrammingMode mode);

    // A FAGOR lathe shows the 8035's mode names (fagor_mode_names.h) instead of the TNC's; set
    // before the mode keys are made.
    void setFagorNames(bool fagor) { m_fagorNames = fagor; }
    QString machineModeText(task::MachineMode mode) const;
    QString programmingModeText(task::ProgrammingMode mode) const;

signals:
    void modesChanged();
    void refused(const QString& message);

private:
    task::ModeMachine m_modes;
    ScreenMode m_screen = ScreenMode::Machine;
    std::function<bool()> m_moving;
    bool m_fagorNames = false;
};

}  // namespace kerf::ui
