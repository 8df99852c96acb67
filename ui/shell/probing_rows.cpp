#include "ui/shell/probing_rows.h"

#include <QCoreApplication>
#include <QInputDialog>
#include <QPointer>
#include <QTimer>
#include <array>

#include "ui/session/machine_session.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

namespace {

using cycles::probing::ManualProbingFunction;
using cycles::probing::ManualProbingResult;

// The texts' translation context: the same as machine_rows.cpp's.
class MachineRows {
    Q_DECLARE_TR_FUNCTIONS(kerf::ui::MachineRows)
};

struct Direction {
    const char* name;
    Vec3 vector;
};
const std::array<Direction, 5> kDirections{{{"X+", {1.0, 0.0, 0.0}},
                                            {"X-", {-1.0, 0.0, 0.0}},
                                            {"Y+", {0.0, 1.0, 0.0}},
                                            {"Y-", {0.0, -1.0, 0.0}},
                                            {"Z-", {0.0, 0.0, -1.0}}}};

size_t directionIndex(const Vec3& direction) {
    for (size_t i = 0; i < kDirections.size(); ++i)
        if ((kDirections[i].vector - direction).norm() < 1e-9) return i;
    return 0;
}

// The function's short name, as on its key (the touch key names the function it serves).
const char* functionName(ManualProbingFunction function) {
    switch (function) {
        case ManualProbingFunction::Rotation:
            return "ROT";
        case ManualProbingFunction::Position:
            return "POS";
        case ManualProbingFunction::Corner:
            return "P";
        case ManualProbingFunction::Circle:
            return "CC";
        case ManualProbingFunction::Plane:
            return "PL";
    }
    return "";
}

// A value dialog with the probed value filled in; nothing when the operator cancels.
std::optional<double> askValue(QWidget* parent, const QString& name, const QString& title,
                               const QString& label, double value) {
    QInputDialog dialog(parent);
    dialog.setObjectName(name);
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setInputMode(QInputDialog::DoubleInput);
    dialog.setDoubleRange(-100000.0, 100000.0);
    dialog.setDoubleDecimals(4);
    dialog.setDoubleValue(value);
    makeTouchSized(dialog);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    return dialog.doubleValue();
}

// The result of the finished function; each value is written once the operator confirms it.
void confirmResult(MachineSession* session, QWidget* parent) {
    const std::optional<ManualProbingResult> result = session->manualProbingResult();
    if (!result) {
        emit session->message(Severity::Error,
                              MachineRows::tr("Probing: the touches give no result"), 0);
        return;
    }
    if (session->manualProbingFunction() == ManualProbingFunction::Plane) {
        // Shown in the PROBE status tab; the preset table has no 3D basic rotation yet.
        emit session->message(Severity::Note,
                              MachineRows::tr("Probing PL: A %1 degrees, B %2 degrees")
                                  .arg(*result->planeADeg, 0, 'f', 4)
                                  .arg(*result->planeBDeg, 0, 'f', 4),
                              0);
        return;
    }
    if (session->manualProbingFunction() == ManualProbingFunction::Rotation) {
        if (const auto angle = askValue(
                parent, QStringLiteral("probeRotationPrompt"), MachineRows::tr("Probing ROT"),
                MachineRows::tr("Basic rotation in degrees (OK writes it to the preset "
                                "table)"),
                *result->basicRotationDeg))
            session->setBasicRotation(*angle);
        return;
    }
    const QString title =
        session->manualProbingFunction() == ManualProbingFunction::Circle
            ? MachineRows::tr("Probing CC: diameter %1 mm").arg(*result->diameter, 0, 'f', 4)
            : MachineRows::tr("Probing");
    for (size_t i = 0; i < result->point.size(); ++i) {
        if (!result->point[i]) continue;
        const auto axis = static_cast<Axis>(i);
        const auto value = askValue(parent, QStringLiteral("probeDatumPrompt"), title,
                                    MachineRows::tr("Probed %1 = %2: the datum value there")
                                        .arg(axisLetter(axis))
                                        .arg(*result->point[i], 0, 'f', 4),
                                    0.0);
        if (!value) return;
        session->setPresetFromProbing(axis, *result->point[i], *value);
    }
}

// Once the touch's moves are done, the result (when the function has all its touches).
void confirmWhenBack(MachineSession* session, QWidget* parent) {
    auto* connection = new QMetaObject::Connection;
    *connection = QObject::connect(
        session, &MachineSession::runStateChanged, session,
        [session, parent = QPointer<QWidget>(parent), connection](task::RunState state) {
            if (state == task::RunState::Running || state == task::RunState::Held) return;
            QObject::disconnect(*connection);
            delete connection;
            if (state != task::RunState::Finished) return;
            // Not inside the session's service: the dialog runs an event loop of its own.
            QTimer::singleShot(0, session, [session, parent] { confirmResult(session, parent); });
        });
}

}  // namespace

SoftkeyRow probingRow(const MachineRowContext& c) {
    MachineSession* session = c.session;
    QWidget* parent = c.dialogParent;
    auto refresh = c.refresh;
    auto select = [session, refresh](ManualProbingFunction function) {
        return [session, refresh, function] {
            session->startManualProbing(function);
            if (refresh) refresh();
        };
    };
    const size_t direction = directionIndex(session->probeDirection());
    return {
        {QStringLiteral("probeRotation"), MachineRows::tr("Probing\nROT"),
         select(ManualProbingFunction::Rotation)},
        {QStringLiteral("probePosition"), MachineRows::tr("Probing\nPOS"),
         select(ManualProbingFunction::Position)},
        {QStringLiteral("probeCorner"), MachineRows::tr("Probing\nP"),
         select(ManualProbingFunction::Corner)},
        {QStringLiteral("probeCircle"), MachineRows::tr("Probing\nCC"),
         select(ManualProbingFunction::Circle)},
        {QStringLiteral("probePlane"), MachineRows::tr("Probing\nPL"),
         select(ManualProbingFunction::Plane)},
        {QStringLiteral("probeDirection"),
         MachineRows::tr("Direction\n%1").arg(QLatin1String(kDirections[direction].name)),
         [session, refresh, direction] {
             session->setProbeDirection(kDirections[(direction + 1) % kDirections.size()].vector);
             if (refresh) refresh();
         }},
        {QStringLiteral("probeTouch"),
         MachineRows::tr("Touch %1\n%2/%3")
             .arg(QLatin1String(functionName(session->manualProbingFunction())))
             .arg(session->manualTouchesDone())
             .arg(cycles::probing::manualTouchCount(session->manualProbingFunction())),
         [session, parent, refresh] {
             if (!session->probeTouch(session->probeDirection())) return;
             if (refresh) refresh();
             if (session->manualTouchesDone() ==
                 cycles::probing::manualTouchCount(session->manualProbingFunction()))
                 confirmWhenBack(session, parent);
         }},
    };
}

}  // namespace kerf::ui
