#include "ui/status/position_display.h"

#include <QCoreApplication>
#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <cmath>
#include <numbers>

#include "core/task/machine_state_name.h"
#include "core/task/working_plane_position.h"
#include "ui/common/block_name.h"
#include "ui/status/override_controls.h"

namespace kerf::ui {

namespace {

constexpr double kMmPerInch = 25.4;

double pick(const task::AxisStatus& axis, PositionKind kind) {
    switch (kind) {
        case PositionKind::Actual:
            return axis.actual;
        case PositionKind::Nominal:
            return axis.nominal;
        case PositionKind::ReferenceActual:
            return axis.machineActual;
        case PositionKind::ReferenceNominal:
            return axis.machineNominal;
        case PositionKind::Lag:
            return axis.followingError;
        case PositionKind::DistanceToGo:
            return axis.distanceToGo;
    }
    return 0.0;
}

std::array<double, kAxisCount> kindValuesOf(const task::MachineStatus& status, PositionKind kind) {
    std::array<double, kAxisCount> values{};
    for (size_t i = 0; i < values.size(); ++i)
        values[i] = pick(status.axes[i], kind);
    return values;
}

}  // namespace

PositionDisplay::PositionDisplay(const machine::MachineConfig& machine, QWidget* parent)
    : QWidget(parent),
      m_dialect(machine.kind == machine::MachineKind::Lathe ? program::Dialect::Fagor
                                                            : program::Dialect::Klartext),
      m_kinematics(machine::TableKinematics::of(machine)) {
    setObjectName("positionsPanel");  // the workspace panel's name in the shell
    auto* layout = new QVBoxLayout(this);
    auto* header = new QHBoxLayout();
    m_kind = new QLabel(this);
    m_kind->setObjectName("positionKind");
    m_state = new QLabel(this);
    m_state->setObjectName("runState");
    m_state->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    header->addWidget(m_kind);
    header->addWidget(m_state, 1);
    layout->addLayout(header);

    QFont digits = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    digits.setPointSizeF(digits.pointSizeF() * 2.0);
    digits.setBold(true);
    auto* grid = new QGridLayout();
    int row = 0;
    for (const machine::AxisConfig& config : machine.axes) {
        if (!config.enabled) continue;
        const auto axis = axisFromLetter(config.letter);
        if (!axis) continue;
        AxisRow& r = m_axes[static_cast<size_t>(axisIndex(*axis))];
        r.present = true;
        r.rotary = config.type == machine::AxisType::Rotary;
        r.diameter = config.diameterMode;
        r.name = new QLabel(r.diameter ? QStringLiteral("%1 \u2300").arg(config.letter)
                                       : QString(QChar(config.letter)),
                            this);
        r.name->setFont(digits);
        r.value = new QLabel(this);
        r.value->setObjectName(QStringLiteral("position%1").arg(config.letter));
        r.value->setFont(digits);
        r.value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        // A warning sign next to the letter until the axis is homed (not a circle: the lathe's X
        // shows the diameter sign ⌀ there).
        r.notReferenced = new QLabel(QStringLiteral("\u26A0"), this);
        r.notReferenced->setObjectName(QStringLiteral("notReferenced%1").arg(config.letter));
        r.notReferenced->setFont(digits);
        r.notReferenced->setStyleSheet(QStringLiteral("color: #b00000;"));
        grid->addWidget(r.name, row, 0);
        grid->addWidget(r.notReferenced, row, 1);
        grid->addWidget(r.value, row, 2);
        ++row;
    }
    grid->setColumnStretch(2, 1);
    layout->addLayout(grid);

    m_tool = new QLabel(this);
    m_tool->setObjectName("activeTool");
    m_feed = new QLabel(this);
    m_feed->setObjectName("feedRate");
    m_spindle = new QLabel(this);
    m_spindle->setObjectName("spindleSpeed");
    layout->addWidget(m_tool);
    layout->addWidget(m_feed);
    m_coolant = new QLabel(this);
    m_coolant->setObjectName("coolant");
    layout->addWidget(m_spindle);
    layout->addWidget(m_coolant);
    layout->addStretch(1);
    m_overrides = new OverrideControls(this);
    layout->addWidget(m_overrides);
    retranslate();
}

double PositionDisplay::shownValue(const task::AxisStatus& axis, PositionKind kind, bool diameter,
                                   bool inch, bool rotary) {
    double value = pick(axis, kind);
    if (diameter) value *= 2.0;
    if (inch && !rotary) value /= kMmPerInch;
    return value;
}

std::array<double, kAxisCount> PositionDisplay::kindValues(
    const task::MachineStatus& status, PositionKind kind, const std::optional<WorkingPlane>& plane,
    const std::optional<machine::TableKinematics>& kinematics, double basicRotationDeg) {
    std::array<double, kAxisCount> values = kindValuesOf(status, kind);
    const bool reference =
        kind == PositionKind::ReferenceActual || kind == PositionKind::ReferenceNominal;
    if (reference) return values;
    if (!plane) {
        // Positions are relative to the preset, about which the basic rotation turns; lag and
        // distance to go turn alike.
        const double a = -basicRotationDeg * std::numbers::pi / 180.0;
        const double x = values[0];
        const double y = values[1];
        values[0] = std::cos(a) * x - std::sin(a) * y;
        values[1] = std::sin(a) * x + std::cos(a) * y;
        return values;
    }
    // Positions map with the origin (and, under TCPM, the tables' turn where they stand); lag and
    // distance to go are differences: they only turn, at the nominal pose.
    const bool position = kind == PositionKind::Actual || kind == PositionKind::Nominal;
    Vec3 shown;
    if (position) {
        shown = task::positionInWorkingPlane(*plane, kinematics, values);
    } else {
        shown = task::differenceInWorkingPlane(*plane, kinematics,
                                               Vec3{values[0], values[1], values[2]},
                                               kindValuesOf(status, PositionKind::Nominal));
    }
    for (size_t row = 0; row < 3; ++row)
        values[row] = shown[static_cast<Eigen::Index>(row)];
    return values;
}

QString PositionDisplay::kindText(PositionKind kind) {
    switch (kind) {
        case PositionKind::Actual:
            return tr("ACTL.");
        case PositionKind::Nominal:
            return tr("NOML.");
        case PositionKind::ReferenceActual:
            return tr("REF ACTL.");
        case PositionKind::ReferenceNominal:
            return tr("REF NOML.");
        case PositionKind::Lag:
            return tr("LAG");
        case PositionKind::DistanceToGo:
            return tr("DIST.");
    }
    return {};
}

void PositionDisplay::setDisplaySettings(const DisplaySettings& settings) {
    m_settings = settings;
    refresh();
}

void PositionDisplay::setStatus(const task::MachineStatus& status) {
    m_status = status;
    refresh();
}

void PositionDisplay::setWorkingPlane(const std::optional<WorkingPlane>& plane) {
    if (plane == m_workingPlane) return;
    m_workingPlane = plane;
    refresh();
}

void PositionDisplay::setBasicRotation(double degrees) {
    if (degrees == m_basicRotationDeg) return;
    m_basicRotationDeg = degrees;
    refresh();
}

void PositionDisplay::setProgrammedFeed(std::optional<ProgrammedFeed> feed) {
    if (feed == m_programmedFeed) return;
    m_programmedFeed = feed;
    refresh();
}

QString PositionDisplay::feedText() const {
    return m_feed->text();
}

void PositionDisplay::setRunState(const QString& text) {
    m_runState = text;
    refresh();
}

QString PositionDisplay::axisText(Axis axis) const {
    const AxisRow& r = m_axes[static_cast<size_t>(axisIndex(axis))];
    return r.present ? r.value->text() : QString();
}

bool PositionDisplay::notReferencedShown(Axis axis) const {
    const AxisRow& r = m_axes[static_cast<size_t>(axisIndex(axis))];
    return r.present && !r.notReferenced->isHidden();
}

QString PositionDisplay::toolText() const {
    return m_tool->text();
}

QString PositionDisplay::kindLabel() const {
    return m_kind->text();
}

QString PositionDisplay::coolantText() const {
    return m_coolant->text();
}

QString PositionDisplay::spindleText() const {
    return m_spindle->text();
}

void PositionDisplay::refresh() {
    const bool inch = m_settings.inch;
    const std::array<double, kAxisCount> values = kindValues(
        m_status, m_settings.positionKind, m_workingPlane, m_kinematics, m_basicRotationDeg);
    for (size_t i = 0; i < m_axes.size(); ++i) {
        const AxisRow& r = m_axes[i];
        if (!r.present) continue;
        double value = values[i];
        if (r.diameter) value *= 2.0;
        if (inch && !r.rotary) value /= kMmPerInch;
        const int decimals = inch && !r.rotary ? 4 : 3;
        // The sign of the value as shown: -0.0002 is +0.000, never -0.000.
        const double scale = std::pow(10.0, decimals);
        const double shown = std::round(value * scale) / scale;
        r.value->setText(QStringLiteral("%1%2")
                             .arg(shown < 0.0 ? QStringLiteral("-") : QStringLiteral("+"))
                             .arg(std::abs(shown), 0, 'f', decimals));
        r.name->setStyleSheet(m_status.axes[i].homed ? QString()
                                                     : QStringLiteral("color: #b00000;"));
        r.notReferenced->setVisible(!m_status.axes[i].homed);
        r.notReferenced->setToolTip(tr("Not referenced: Home all in Manual operation"));
    }
    // "3D ROT": the TNC's name of the tilted working plane, an NC word (not translated).
    const bool tilted = m_workingPlane &&
                        m_settings.positionKind != PositionKind::ReferenceActual &&
                        m_settings.positionKind != PositionKind::ReferenceNominal;
    // "ROT": the basic rotation turns X and Y (an NC word as well).
    const bool turned = !m_workingPlane && m_basicRotationDeg != 0.0 &&
                        m_settings.positionKind != PositionKind::ReferenceActual &&
                        m_settings.positionKind != PositionKind::ReferenceNominal;
    m_kind->setText(kindText(m_settings.positionKind) +
                    (inch ? QStringLiteral("  inch") : QStringLiteral("  mm")) +
                    (tilted ? QStringLiteral("  3D ROT") : QString()) +
                    (turned ? QStringLiteral("  ROT") : QString()));
    QString state = QCoreApplication::translate("kerf", task::machineStateName(m_status.state),
                                                task::kMachineStateDisambiguation);
    if (!m_runState.isEmpty()) state = tr("Program: %1   Machine: %2").arg(m_runState, state);
    if (m_status.block.line > 0) {
        state +=
            QStringLiteral("   ") +
            blockName(m_status.block.blockNumber, static_cast<int>(m_status.block.line), m_dialect);
    }
    m_state->setText(state);
    m_tool->setText(tr("T %1").arg(m_status.toolNumber));
    const double feedScale = inch ? 1.0 / kMmPerInch : 1.0;
    if (m_programmedFeed && m_programmedFeed->perRevolution) {
        // Per revolution as programmed; the actual one from the path speed and the spindle's.
        const double rpm = m_status.actualSpindleRpm;
        const double actual = rpm > 0.0 ? m_status.actualFeedMmPerMin / rpm : 0.0;
        const int decimals = inch ? 4 : 3;
        m_feed->setText(tr("F %1 (actual %2) %3")
                            .arg(m_programmedFeed->mm * feedScale, 0, 'f', decimals)
                            .arg(actual * feedScale, 0, 'f', decimals)
                            .arg(inch ? tr("inch/rev") : tr("mm/rev")));
    } else {
        const double programmed =
            m_programmedFeed ? m_programmedFeed->mm : m_status.programmedFeedMmPerMin;
        const int decimals = inch ? 1 : 0;
        m_feed->setText(tr("F %1 (actual %2) %3")
                            .arg(programmed * feedScale, 0, 'f', decimals)
                            .arg(m_status.actualFeedMmPerMin * feedScale, 0, 'f', decimals)
                            .arg(inch ? tr("inch/min") : tr("mm/min")));
    }
    if (m_status.programmedSurfaceSpeedMPerMin > 0.0) {
        // Constant surface speed (G96): S as programmed, the speed it gives now in rpm.
        constexpr double kFeetPerMetre = 1000.0 / (kMmPerInch * 12.0);
        m_spindle->setText(
            (inch ? tr("S %1 ft/min (actual %2 rpm)") : tr("S %1 m/min (actual %2 rpm)"))
                .arg(m_status.programmedSurfaceSpeedMPerMin * (inch ? kFeetPerMetre : 1.0), 0, 'f',
                     0)
                .arg(m_status.actualSpindleRpm, 0, 'f', 0));
    } else {
        m_spindle->setText(tr("S %1 (actual %2) rpm")
                               .arg(m_status.programmedSpindleRpm, 0, 'f', 0)
                               .arg(m_status.actualSpindleRpm, 0, 'f', 0));
    }
    m_coolant->setText(m_status.coolant ? tr("Coolant on") : tr("Coolant off"));
}

void PositionDisplay::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void PositionDisplay::retranslate() {
    refresh();
}

}  // namespace kerf::ui
