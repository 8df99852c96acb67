#pragma once

#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <memory>

#include "core/machine/machine_config.h"
#include "ui/common/display_settings.h"

class QComboBox;
class QLabel;
class QSettings;

namespace kerf::ui {

// The MOD functions: what the position display shows (ACTL, NOML, REF ACTL, REF NOML, LAG,
// DIST), mm or inch, the HMI language, and what software runs on which machine. The display
// choices are kept in QSettings and come back at the next start.
class ModPage : public QWidget {
    Q_OBJECT

public:
    // `settingsFile`: an INI file for the choices; empty: the user's Kerf settings.
    ModPage(const machine::MachineConfig& machine, const QString& settingsFile = {},
            QWidget* parent = nullptr);
    ~ModPage() override;

    const DisplaySettings& displaySettings() const { return m_display; }
    void setPositionKind(PositionKind kind);
    void setInch(bool inch);
    // The languages offered and the one in use (the shell owns switching).
    void setLanguages(const QStringList& codes, const QString& current);

    // "ACTL", "REF NOML" ...: the TNC's names, not translated.
    static QString positionKindName(PositionKind kind);

signals:
    void displaySettingsChanged(const kerf::ui::DisplaySettings& settings);
    void languageRequested(const QString& code);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void store();

    DisplaySettings m_display;
    std::unique_ptr<QSettings> m_settings;
    QString m_machineText;
    QComboBox* m_position = nullptr;
    QComboBox* m_unit = nullptr;
    QComboBox* m_language = nullptr;
    QLabel* m_title = nullptr;
    QLabel* m_positionLabel = nullptr;
    QLabel* m_unitLabel = nullptr;
    QLabel* m_languageLabel = nullptr;
    QLabel* m_info = nullptr;
};

}  // namespace kerf::ui

Q_DECLARE_METATYPE(kerf::ui::DisplaySettings)
