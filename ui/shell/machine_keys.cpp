#include "ui/shell/machine_keys.h"

#include <QPushButton>
#include <QVBoxLayout>

#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"

namespace kerf::ui {

namespace {

constexpr task::MachineMode kMachineModes[] = {
    task::MachineMode::Manual, task::MachineMode::Handwheel, task::MachineMode::Mdi,
    task::MachineMode::SingleBlock, task::MachineMode::FullSequence};
constexpr task::ProgrammingMode kProgrammingModes[] = {task::ProgrammingMode::Programming,
                                                       task::ProgrammingMode::TestRun};

QPushButton* makeModeKey(QWidget* parent, const QString& name) {
    auto* key = new QPushButton(parent);
    key->setObjectName(name);
    key->setCheckable(true);
    key->setMinimumSize(120, SoftkeyBar::kMinimumKeyHeight);
    key->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Expanding);
    key->setFocusPolicy(Qt::NoFocus);
    return key;
}

// Long mode names do not fit the narrow column: break them into lines of about 16 characters
// at spaces, in any language.
QString wrapLabel(const QString& text) {
    constexpr int kLineLength = 16;
    QString wrapped;
    int lineLength = 0;
    for (const QString& word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        if (lineLength > 0 && lineLength + 1 + word.size() > kLineLength) {
            wrapped += QLatin1Char('\n');
            lineLength = 0;
        } else if (lineLength > 0) {
            wrapped += QLatin1Char(' ');
            ++lineLength;
        }
        wrapped += word;
        lineLength += static_cast<int>(word.size());
    }
    return wrapped;
}

}  // namespace

MachineKeys::MachineKeys(ModeController& modes, QWidget* parent) : QWidget(parent), m_modes(modes) {
    setObjectName("machineKeys");
    // The active modes must be recognisable at a glance, also from a distance.
    setStyleSheet(
        QStringLiteral("QPushButton:checked { background: #1f4e79; color: white; "
                       "border: 1px solid #0f2e49; border-radius: 3px; }"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    for (task::MachineMode mode : kMachineModes) {
        QPushButton* key = makeModeKey(this, QStringLiteral("machineKey%1").arg(int(mode)));
        connect(key, &QPushButton::clicked, this, [this, mode] {
            m_modes.requestMachineMode(mode);
            refresh();  // a refused request must not leave the key pressed
        });
        layout->addWidget(key);
        m_machineKeys.push_back(key);
    }
    layout->addSpacing(16);
    for (task::ProgrammingMode mode : kProgrammingModes) {
        QPushButton* key = makeModeKey(this, QStringLiteral("programmingKey%1").arg(int(mode)));
        connect(key, &QPushButton::clicked, this,
                [this, mode] { m_modes.requestProgrammingMode(mode); });
        layout->addWidget(key);
        m_programmingKeys.push_back(key);
    }
    layout->addSpacing(16);
    m_machineOn = makeModeKey(this, QStringLiteral("machineOn"));
    m_machineOn->setCheckable(false);
    connect(m_machineOn, &QPushButton::clicked, this, &MachineKeys::machineOnPressed);
    layout->addWidget(m_machineOn);
    m_emergencyStop = makeModeKey(this, QStringLiteral("emergencyStop"));
    m_emergencyStop->setCheckable(false);
    // Red and bold as the mushroom button on the machine; it never changes with the modes.
    applyEmergencyStopLook();
    connect(m_emergencyStop, &QPushButton::clicked, this, [this] {
        if (m_emergencyStopLatched)
            emit emergencyStopReleased();
        else
            emit emergencyStopPressed();
    });
    layout->addWidget(m_emergencyStop);
    connect(&m_modes, &ModeController::modesChanged, this, &MachineKeys::refresh);
    retranslate();
}

QPushButton* MachineKeys::machineKey(task::MachineMode mode) const {
    return m_machineKeys.at(static_cast<size_t>(mode));
}

QPushButton* MachineKeys::programmingKey(task::ProgrammingMode mode) const {
    return m_programmingKeys.at(static_cast<size_t>(mode));
}

void MachineKeys::retranslate() {
    for (task::MachineMode mode : kMachineModes) {
        machineKey(mode)->setText(wrapLabel(m_modes.machineModeText(mode)));
    }
    for (task::ProgrammingMode mode : kProgrammingModes) {
        programmingKey(mode)->setText(m_modes.programmingModeText(mode));
    }
    m_machineOn->setText(wrapLabel(tr("Machine on")));
    m_emergencyStop->setText(
        wrapLabel(m_emergencyStopLatched ? tr("Release EMERGENCY STOP") : tr("EMERGENCY STOP")));
    refresh();
}

void MachineKeys::setEmergencyStopPressed(bool pressed) {
    if (pressed == m_emergencyStopLatched) return;
    m_emergencyStopLatched = pressed;
    applyEmergencyStopLook();
    retranslate();
}

void MachineKeys::applyEmergencyStopLook() {
    // Pressed, the button is darker and sunk, as a latched mushroom button looks.
    m_emergencyStop->setStyleSheet(
        m_emergencyStopLatched
            ? QStringLiteral("QPushButton { background: #700000; color: white; font-weight: "
                             "bold; border: 4px inset #300000; border-radius: 3px; }")
            : QStringLiteral("QPushButton { background: #c00000; color: white; font-weight: "
                             "bold; border: 2px solid #600000; border-radius: 3px; }"));
}

void MachineKeys::refresh() {
    for (task::MachineMode mode : kMachineModes) {
        machineKey(mode)->setChecked(m_modes.machineConnected() && mode == m_modes.machineMode());
        machineKey(mode)->setEnabled(m_modes.machineConnected());
    }
    for (task::ProgrammingMode mode : kProgrammingModes) {
        programmingKey(mode)->setChecked(mode == m_modes.programmingMode());
    }
    // A programming station has no machine to stop or switch on.
    m_machineOn->setVisible(m_modes.machineConnected());
    m_emergencyStop->setVisible(m_modes.machineConnected());
}

}  // namespace kerf::ui
