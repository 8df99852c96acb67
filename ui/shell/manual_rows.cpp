#include "ui/shell/manual_rows.h"

#include <QCoreApplication>
#include <QInputDialog>
#include <QStringList>
#include <optional>

#include "ui/session/machine_session.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

namespace {

// The texts' translation context: the same as machine_rows.cpp's.
class MachineRows {
    Q_DECLARE_TR_FUNCTIONS(kerf::ui::MachineRows)
};

std::vector<char> machineAxes(const MachineSession& session) {
    std::vector<char> letters;
    for (const machine::AxisConfig& axis : session.machine().axes) {
        if (axis.enabled && axisFromLetter(axis.letter)) letters.push_back(axis.letter);
    }
    return letters;
}

// One axis letter out of `axes`, in a touch-sized dialog; empty when cancelled.
QString askAxis(QWidget* parent, const char* objectName, const QString& title, const QString& label,
                const QStringList& axes) {
    QInputDialog dialog(parent);
    dialog.setObjectName(QLatin1String(objectName));
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setComboBoxItems(axes);
    dialog.setComboBoxEditable(false);
    makeTouchSized(dialog);
    if (dialog.exec() != QDialog::Accepted) return {};
    return dialog.textValue();
}

// A position in mm (0 offered), in a touch-sized dialog; nothing when cancelled.
std::optional<double> askPosition(QWidget* parent, const char* objectName, const QString& title,
                                  const QString& label) {
    QInputDialog dialog(parent);
    dialog.setObjectName(QLatin1String(objectName));
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setInputMode(QInputDialog::DoubleInput);
    dialog.setDoubleRange(-100000.0, 100000.0);
    dialog.setDoubleDecimals(4);
    dialog.setDoubleValue(0.0);
    makeTouchSized(dialog);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    return dialog.doubleValue();
}

// Whether the position display shows `axis` as a diameter (a lathe's X in diameter mode): the
// value asked for is then a diameter too.
bool shownAsDiameter(const MachineSession& session, const QString& axis) {
    for (const machine::AxisConfig& config : session.machine().axes) {
        if (QChar(config.letter) == axis.at(0) && config.diameterMode) return true;
    }
    return false;
}

// Asks for the axis and the value its position should show now, in touch-sized dialogs.
void askPreset(MachineSession* session, QWidget* parent) {
    QStringList axes;
    for (char letter : machineAxes(*session))
        axes << QString(QChar(letter));
    if (axes.isEmpty()) return;
    const QString title = MachineRows::tr("Set preset");
    const QString axis = askAxis(parent, "presetAxisPrompt", title, MachineRows::tr("Axis"), axes);
    if (axis.isEmpty()) return;
    const QString question = shownAsDiameter(*session, axis)
                                 ? MachineRows::tr("Diameter %1 at the current point").arg(axis)
                                 : MachineRows::tr("Position of %1 at the current point").arg(axis);
    const auto value = askPosition(parent, "presetValuePrompt", title, question);
    const auto a = axisFromLetter(axis.at(0).toLatin1());
    if (value && a) session->setPresetByEntry(*a, *value);
}

// Tool calibration (lathe): the offset D, the axis touched and where the tip really is (X as
// the display shows it), in touch-sized dialogs; the session writes the offset table.
void askToolCalibration(MachineSession* session, QWidget* parent) {
    const QString title = MachineRows::tr("Tool calibration");
    QInputDialog offsetDialog(parent);
    offsetDialog.setObjectName(QStringLiteral("touchOffOffsetPrompt"));
    offsetDialog.setWindowTitle(title);
    offsetDialog.setLabelText(MachineRows::tr("Tool offset D"));
    offsetDialog.setInputMode(QInputDialog::IntInput);
    offsetDialog.setIntRange(1, 255);
    const auto& active = session->activeLatheOffset();
    offsetDialog.setIntValue(active && active->number > 0 ? active->number : 1);
    makeTouchSized(offsetDialog);
    if (offsetDialog.exec() != QDialog::Accepted) return;
    const QString axis =
        askAxis(parent, "touchOffAxisPrompt", title, MachineRows::tr("Axis touched"),
                {QStringLiteral("X"), QStringLiteral("Z")});
    if (axis.isEmpty()) return;
    const QString question =
        shownAsDiameter(*session, axis)
            ? MachineRows::tr("Diameter %1 where the tool touches").arg(axis)
            : MachineRows::tr("Position of %1 where the tool touches").arg(axis);
    const auto value = askPosition(parent, "touchOffValuePrompt", title, question);
    const auto a = axisFromLetter(axis.at(0).toLatin1());
    if (value && a) session->touchOffTool(offsetDialog.intValue(), *a, *value);
}

// Asks for the manual spindle speed, offered only within the machine's spindle range.
void askSpindleSpeed(MachineSession* session, QWidget* parent) {
    const machine::SpindleConfig& spindle = session->machine().spindle;
    QInputDialog dialog(parent);
    dialog.setObjectName(QStringLiteral("spindleSpeedPrompt"));
    dialog.setWindowTitle(MachineRows::tr("Spindle speed"));
    dialog.setLabelText(
        MachineRows::tr("S in rpm (%1 to %2)").arg(spindle.minRpm).arg(spindle.maxRpm));
    dialog.setInputMode(QInputDialog::IntInput);
    dialog.setIntRange(spindle.minRpm, spindle.maxRpm);
    dialog.setIntStep(100);
    dialog.setIntValue(static_cast<int>(session->manualSpindleRpm()));
    makeTouchSized(dialog);
    if (dialog.exec() == QDialog::Accepted) session->setManualSpindleRpm(dialog.intValue());
}

}  // namespace

SoftkeyRow handwheelRow(const MachineRowContext& c) {
    MachineSession* session = c.session;
    auto refresh = c.refresh;
    return {
        {QStringLiteral("handwheelAxis"),
         MachineRows::tr("Handwheel\naxis %1").arg(axisLetter(session->handwheelAxis())),
         [session, refresh] {
             const std::vector<char> axes = machineAxes(*session);
             if (axes.empty()) return;
             size_t next = 0;
             for (size_t i = 0; i < axes.size(); ++i)
                 if (axisFromLetter(axes[i]) == session->handwheelAxis())
                     next = (i + 1) % axes.size();
             session->setHandwheelAxis(*axisFromLetter(axes[next]));
             if (refresh) refresh();
         }},
        {QStringLiteral("handwheelFactor"),
         MachineRows::tr("Step\nx%1").arg(session->handwheelFactor()),
         [session, refresh] {
             const int factor = session->handwheelFactor();
             session->setHandwheelFactor(factor >= 100 ? 1 : factor * 10);
             if (refresh) refresh();
         }},
        {QStringLiteral("handwheelMinus"), MachineRows::tr("Handwheel\n-"),
         [session] { session->turnHandwheel(-1); }},
        {QStringLiteral("handwheelPlus"), MachineRows::tr("Handwheel\n+"),
         [session] { session->turnHandwheel(1); }},
    };
}

SoftkeyRow manualFunctionsRow(const MachineRowContext& c) {
    MachineSession* session = c.session;
    QWidget* parent = c.dialogParent;
    auto refresh = c.refresh;
    SoftkeyRow row{
        {QStringLiteral("spindleSpeed"),
         QStringLiteral("S\n%1").arg(QString::number(session->manualSpindleRpm(), 'f', 0)),
         [session, parent, refresh] {
             askSpindleSpeed(session, parent);
             if (refresh) refresh();
         }},
        {QStringLiteral("spindleOn"), MachineRows::tr("Spindle\non"),
         [session] { session->spindle(true); }},
        {QStringLiteral("spindleOff"), MachineRows::tr("Spindle\noff"),
         [session] { session->spindle(false); }},
        {QStringLiteral("coolantOn"), MachineRows::tr("Coolant\non"),
         [session] { session->coolant(true); }},
        {QStringLiteral("coolantOff"), MachineRows::tr("Coolant\noff"),
         [session] { session->coolant(false); }},
        {QStringLiteral("setPreset"), MachineRows::tr("Set\npreset"),
         [session, parent] { askPreset(session, parent); }},
    };
    // The 8035's manual mode calibrates the tools of a lathe (spec part 1 §11).
    if (session->machine().kind == machine::MachineKind::Lathe) {
        row.push_back({QStringLiteral("toolCalibration"), MachineRows::tr("Tool\ncalibration"),
                       [session, parent] { askToolCalibration(session, parent); }});
    } else {
        // The tool in the spindle touches a surface of known Z: its L in TOOL.T.
        row.push_back({QStringLiteral("toolLengthTouchOff"),
                       MachineRows::tr("Tool length\ntouch-off"), [session, parent] {
                           const auto z = askPosition(
                               parent, "toolLengthPrompt", MachineRows::tr("Tool length touch-off"),
                               MachineRows::tr("Z of the surface the tool touches"));
                           if (z) session->touchOffToolLength(*z);
                       }});
    }
    return row;
}

}  // namespace kerf::ui
