#include "ui/shell/machine_rows.h"

#include <QCoreApplication>
#include <QInputDialog>
#include <QLineEdit>

#include "ui/session/machine_session.h"
#include "ui/shell/manual_rows.h"
#include "ui/shell/mdi_dialog.h"
#include "ui/shell/probing_rows.h"

namespace kerf::ui {

namespace {

// The texts' translation context.
class MachineRows {
    Q_DECLARE_TR_FUNCTIONS(kerf::ui::MachineRows)
};

QString incrementText(double mm) {
    if (mm <= 0.0) return MachineRows::tr("Increment\ncontinuous");
    return MachineRows::tr("Increment\n%1 mm").arg(mm);
}

// Continuous jog: a touch starts the axis, the next touch of any jog key stops it.
SoftkeyRow jogRow(const MachineRowContext& c) {
    MachineSession* session = c.session;
    SoftkeyRow row;
    int keys = 0;
    for (const machine::AxisConfig& axis : session->machine().axes) {
        if (!axis.enabled || keys + 2 > 6) continue;
        const auto letter = axisFromLetter(axis.letter);
        if (!letter) continue;
        for (int direction : {-1, 1}) {
            const QString name =
                QStringLiteral("%1%2").arg(axis.letter).arg(direction < 0 ? '-' : '+');
            row.push_back({QStringLiteral("jog") + name, name, [session, letter, direction] {
                               if (session->incrementMm() > 0.0) {
                                   session->jogIncrement(*letter, direction);
                               } else if (session->status().state == task::MachineState::Jogging) {
                                   session->jogStop(*letter);
                               } else {
                                   session->jog(*letter, direction);
                               }
                           }});
        }
        keys += 2;
    }
    row.push_back({QStringLiteral("increment"), incrementText(session->incrementMm()),
                   [session, refresh = c.refresh] {
                       const std::vector<double>& steps = jogIncrementsMm();
                       size_t next = 0;
                       for (size_t i = 0; i < steps.size(); ++i)
                           if (steps[i] == session->incrementMm()) next = (i + 1) % steps.size();
                       session->setIncrementMm(steps[next]);
                       if (refresh) refresh();
                   }});
    row.push_back({QStringLiteral("homeAll"), MachineRows::tr("Home\nall"),
                   [session] { session->homeAll(); }});
    return row;
}

SoftkeyRow runRow(const MachineRowContext& c) {
    MachineSession* session = c.session;
    auto start = c.startProgram;
    return {
        {QStringLiteral("ncStart"), MachineRows::tr("NC\nstart"),
         [session, start] {
             if (session->busy()) {
                 session->cycleStart();
             } else if (start) {
                 start(std::nullopt);
             }
         }},
        {QStringLiteral("ncStop"), MachineRows::tr("NC stop\n(feed hold)"),
         [session] { session->feedHold(); }},
        {QStringLiteral("resume"), MachineRows::tr("Resume"), [session] { session->cycleStart(); }},
        {QStringLiteral("abort"), MachineRows::tr("Stop"), [session] { session->stop(); }},
        {QStringLiteral("startAtBlock"), MachineRows::tr("Start at\nblock"),
         [start, ask = c.askStartBlock] {
             if (!start || !ask) return;
             if (const auto line = ask()) start(static_cast<uint32_t>(*line));
         }},
        {QStringLiteral("singleBlock"),
         session->singleBlock() ? MachineRows::tr("Single block\non")
                                : MachineRows::tr("Single block\noff"),
         [session, refresh = c.refresh] {
             session->setSingleBlock(!session->singleBlock());
             if (refresh) refresh();
         }},
    };
}

SoftkeyRow mdiRow(const MachineRowContext& c) {
    MachineSession* session = c.session;
    QWidget* parent = c.dialogParent;
    return {
        {QStringLiteral("mdiExecute"), MachineRows::tr("Execute\nblock"),
         [session, parent] {
             MdiDialog dialog(session->mdiHistory(), parent);
             if (dialog.exec() == QDialog::Accepted && !dialog.block().isEmpty())
                 session->executeMdi(dialog.block());
         }},
        {QStringLiteral("ncStop"), MachineRows::tr("NC stop\n(feed hold)"),
         [session] { session->feedHold(); }},
        {QStringLiteral("resume"), MachineRows::tr("Resume"), [session] { session->cycleStart(); }},
        {QStringLiteral("abort"), MachineRows::tr("Stop"), [session] { session->stop(); }},
    };
}

}  // namespace

const std::vector<double>& jogIncrementsMm() {
    static const std::vector<double> steps{0.0, 0.001, 0.01, 0.1, 1.0, 10.0};
    return steps;
}

std::vector<SoftkeyRow> machineModeRows(task::MachineMode mode, const MachineRowContext& context) {
    if (context.session == nullptr) return {};
    switch (mode) {
        case task::MachineMode::Manual:
            // The lathe probes with its G75/G76 in programs.
            if (context.session->machine().kind == machine::MachineKind::Lathe)
                return {jogRow(context), manualFunctionsRow(context)};
            return {jogRow(context), manualFunctionsRow(context), probingRow(context)};
        case task::MachineMode::Handwheel:
            return {handwheelRow(context), jogRow(context), manualFunctionsRow(context)};
        case task::MachineMode::Mdi:
            return {mdiRow(context)};
        case task::MachineMode::SingleBlock:
        case task::MachineMode::FullSequence:
            return {runRow(context)};
    }
    return {};
}

}  // namespace kerf::ui
