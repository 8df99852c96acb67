#pragma once

#include <QString>
#include <QWidget>
#include <array>
#include <optional>

#include "core/interp/program_status.h"
#include "core/machine/machine_config.h"
#include "core/machine/table_kinematics.h"
#include "core/program/dialect.h"
#include "core/task/machine_status.h"
#include "ui/common/display_settings.h"

class QLabel;

namespace kerf::ui {

class OverrideControls;

// The feed of the block the machine executes, as its program gives it: mm per minute, or per
// revolution (G95, FU).
struct ProgrammedFeed {
    double mm = 0.0;
    bool perRevolution = false;
    friend bool operator==(const ProgrammedFeed&, const ProgrammedFeed&) = default;
};

// The position display of the machine modes: the machine's axes with the kind of position chosen
// in MOD (ACTL, NOML, REF ACTL, REF NOML, LAG, DIST), in mm or inch, lathe X as a diameter where
// the machine says so; the run state, active tool, S and F (programmed and actual), the coolant as
// the machine executes it, and the override controls. While a working plane is tilted (cycle 19,
// PLANE) X, Y and Z of every kind but REF are in the program's coordinates of the tilted plane,
// as a TNC shows them ("3D ROT" beside the kind), also while TCPM turns the tables away from the
// plane's angles; REF keeps the machine's axes, rotary axes are always their angles in degrees.
class PositionDisplay : public QWidget {
    Q_OBJECT

public:
    explicit PositionDisplay(const machine::MachineConfig& machine, QWidget* parent = nullptr);

    void setDisplaySettings(const DisplaySettings& settings);
    const DisplaySettings& displaySettings() const { return m_settings; }
    void setStatus(const task::MachineStatus& status);
    using WorkingPlane = interp::ProgramStatus::Transformations::WorkingPlane;
    // The tilted plane of the program the machine runs (its status), or none.
    void setWorkingPlane(const std::optional<WorkingPlane>& plane);
    // The active preset's basic rotation (degrees): while no plane is tilted, X and Y of every
    // kind but REF are shown in the system it turns (about the preset), as a TNC shows them
    // ("ROT" beside the kind). A tilted plane's map already holds it.
    void setBasicRotation(double degrees);
    // While a program runs: its feed at the block the machine executes (inside a cycle the
    // cycle's move), shown instead of the machine's; the actual feed is then shown in the same
    // unit. None: the machine's feed in mm/min.
    void setProgrammedFeed(std::optional<ProgrammedFeed> feed);
    QString feedText() const;
    // The program run's state next to the machine's ("running", "feed hold", ...).
    void setRunState(const QString& text);

    OverrideControls* overrides() const { return m_overrides; }
    // The text shown for an axis (e.g. "+12.500"); empty for an axis the machine lacks.
    QString axisText(Axis axis) const;
    // The axis shows the not-referenced symbol (it has not been homed since power-on).
    bool notReferencedShown(Axis axis) const;
    QString toolText() const;
    // The kind shown above the axes ("NOML.  mm  3D ROT").
    QString kindLabel() const;
    QString coolantText() const;
    QString spindleText() const;

    // The value of one axis as the settings show it: the kind of position, lathe diameter, unit.
    static double shownValue(const task::AxisStatus& axis, PositionKind kind, bool diameter,
                             bool inch, bool rotary);
    // Every axis's value of the kind in mm and degrees; X, Y and Z in the tilted plane's
    // coordinates when a plane is given and the kind is not REF (under TCPM the tool tip through
    // the machine's `kinematics` at the rotary axes' angles); without a plane X and Y turned by
    // -basicRotationDeg (not for REF).
    static std::array<double, kAxisCount> kindValues(
        const task::MachineStatus& status, PositionKind kind,
        const std::optional<WorkingPlane>& plane,
        const std::optional<machine::TableKinematics>& kinematics, double basicRotationDeg = 0.0);
    static QString kindText(PositionKind kind);

protected:
    void changeEvent(QEvent* event) override;

private:
    struct AxisRow {
        bool present = false;
        bool rotary = false;
        bool diameter = false;
        QLabel* name = nullptr;
        QLabel* value = nullptr;
        QLabel* notReferenced = nullptr;  // the TNC's symbol of an axis not yet homed
    };

    void refresh();
    void retranslate();

    DisplaySettings m_settings;
    program::Dialect m_dialect;  // how the machine's programs number their blocks
    std::optional<machine::TableKinematics> m_kinematics;
    task::MachineStatus m_status;
    std::optional<WorkingPlane> m_workingPlane;
    double m_basicRotationDeg = 0.0;
    std::optional<ProgrammedFeed> m_programmedFeed;
    QString m_runState;
    std::array<AxisRow, kAxisCount> m_axes{};
    QLabel* m_kind = nullptr;
    QLabel* m_state = nullptr;
    QLabel* m_tool = nullptr;
    QLabel* m_feed = nullptr;
    QLabel* m_coolant = nullptr;
    QLabel* m_spindle = nullptr;
    OverrideControls* m_overrides = nullptr;
};

}  // namespace kerf::ui
