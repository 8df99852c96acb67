// Manual probing in Manual operation: the touches on the simulated part, the moves to the
// trigger and back, and the results written to PRESET.PR.
#include <cstdio>
#include <string>

#include "core/cycles/probing/probing_log_html.h"
#include "core/program/nc_root.h"
#include "core/task/manual_probe.h"
#include "core/task/program_loader.h"
#include "core/task/shifted_motion_port.h"
#include "core/task/tool_length_touch_off.h"
#include "core/workpiece/simulated_part.h"
#include "ui/common/diagnostic_text.h"
#include "ui/session/machine_session.h"

namespace kerf::ui {

namespace {

std::string klartextPoint(const Vec3& p) {
    char text[96];
    std::snprintf(text, sizeof text, "X%+.4f Y%+.4f Z%+.4f", p.x(), p.y(), p.z());
    return text;
}

}  // namespace

void MachineSession::startManualProbing(cycles::probing::ManualProbingFunction function) {
    m_probing = function;
    m_touches.clear();
    emit manualProbingChanged();
}

bool MachineSession::probeTouch(const Vec3& axisDirection) {
    if (refuseWhenBusy() || refuseWhenNotReferenced()) return false;
    // Under a basic rotation the touch goes along the turned axis, as on the TNC.
    const double rotation = basicRotationDeg();
    const Vec3 direction = cycles::probing::turnedProbingDirection(axisDirection, rotation);
    const auto probe = task::manualProbe(m_ncRoot, m_status.toolNumber);
    if (!probe) {
        report({probe.error()});
        return false;
    }
    if (static_cast<int>(m_touches.size()) >= cycles::probing::manualTouchCount(m_probing))
        m_touches.clear();  // a new measurement of the same function
    // The part lies where the last program's blank was clamped, in that program's frame, as
    // that program machined it; the axes show the tip from the operator's origin now. Before
    // any BLK FORM: the machine's simulated blank at the machine file's preset (no shift).
    const task::ShiftedMotionPort::PassedBlank blank =
        m_motion->lastBlank().value_or(task::ShiftedMotionPort::PassedBlank{
            workpiece::simulationBlank(m_machine), Pose{}, nullptr});
    const Vec3 partOffset = m_motion->shift().xyz() - blank.shift.xyz();
    const Vec3 up(0.0, 0.0, probe->ballRadius);
    // Where the probe was sent: the drives may still be settling into it.
    const task::MachineStatus now = m_motion->status();
    const Vec3 tip(now.axes[0].nominal, now.axes[1].nominal, now.axes[2].nominal);
    const Vec3 ball = tip + partOffset + up;
    const workpiece::SimulatedWorkpiece part =
        task::manualProbingPart(m_machine, blank.stock, blank.removed);
    if (part.touches(ball, probe->ballRadius)) {
        emit message(Severity::Error, tr("Probing: the stylus is deflected already"), 0);
        return false;
    }
    const auto hit = part.touch(ball, direction, probe->maxPath, probe->ballRadius);
    if (!hit) {
        emit message(Severity::Error, tr("Probing: no touch within %1 mm").arg(probe->maxPath), 0);
        return false;
    }
    const Vec3 trigger = *hit - partOffset - up;  // the tip, workpiece coordinates
    char feed[32];
    std::snprintf(feed, sizeof feed, " F%.0f", probe->probingFeed);
    const std::string text = "0 BEGIN PGM PROBE MM\n1 L " + klartextPoint(trigger) + feed +
                             "\n2 L " + klartextPoint(tip) + " FMAX\n3 END PGM PROBE MM\n";
    if (!runGeneratedProgram(text)) return false;
    m_probeBallRadius = probe->ballRadius;
    m_touches.push_back({*hit - partOffset, direction, rotation});
    if (static_cast<int>(m_touches.size()) == cycles::probing::manualTouchCount(m_probing))
        writeManualProbingLog();
    emit manualProbingChanged();
    return true;
}

void MachineSession::writeManualProbingLog() {
    // TCHPRMAN.html in the NC root (the TNC's TNC:\), replaced by each completed function.
    const program::NcRoot root(m_ncRoot);
    const std::string text = cycles::probing::manualProbingLogHtml(
        m_probing, m_touches, m_probeBallRadius, manualProbingResult());
    if (const MaybeError failed = root.replace(root.path() / "TCHPRMAN.html", text)) {
        emit message(Severity::Warning,
                     tr("The probing log TCHPRMAN.html could not be written: %1")
                         .arg(translatedMessage(*failed)),
                     0);
    }
}

bool MachineSession::touchOffToolLength(double knownZ) {
    if (refuseWhenBusy()) return false;
    task::ToolLengthTouch touch;
    touch.tool = m_status.toolNumber > 0 ? m_status.toolNumber : -1;  // 0: none
    touch.shownMm = m_motion->status().axes[static_cast<size_t>(axisIndex(Axis::Z))].actual;
    touch.knownMm = knownZ;
    const auto length = task::touchOffToolLength(m_ncRoot, touch);
    if (!length) {
        emit message(Severity::Error, translatedMessage(length.error()), 0);
        return false;
    }
    emit message(Severity::Note, tr("Tool %1: L = %2 mm").arg(touch.tool).arg(*length, 0, 'f', 4),
                 0);
    emit toolLengthTouchedOff(touch.tool, *length);
    return true;
}

bool MachineSession::runGeneratedProgram(const std::string& text) {
    applyPresetTable();
    task::ProgramRequest request;
    request.text = text;
    request.ncRoot = m_ncRoot;
    request.startPosition = Pose{};
    request.startPosition->values = m_motion->world().position.values;
    request.presetInMachine = presetInMachine();
    m_programName.clear();
    return start(task::loadProgram(m_machine, request), std::nullopt, false);
}

std::optional<cycles::probing::ManualProbingResult> MachineSession::manualProbingResult() const {
    return cycles::probing::evaluateManualProbing(m_probing, m_touches, m_probeBallRadius);
}

bool MachineSession::setPresetFromProbing(Axis axis, double measured, double value) {
    return movePreset(axis, measured, value);
}

bool MachineSession::setBasicRotation(double degrees) {
    if (refuseWhenBusy()) return false;
    // Row 0 is the whole active preset: a table created for the rotation alone would give its
    // axes 0 (machine zero), and the next program or touch would run from there. So the
    // origin goes in with it.
    AxisMask axes = 0;
    for (const machine::AxisConfig& config : m_machine.axes) {
        if (const auto a = axisFromLetter(config.letter)) axes |= axisBit(*a);
    }
    MaybeError failed = m_presets.write(presetInMachine(), axes);
    if (!failed) failed = m_presets.writeBasicRotation(degrees);
    if (failed) {
        emit message(Severity::Error,
                     tr("The basic rotation could not be saved in PRESET.PR: %1")
                         .arg(translatedMessage(*failed)),
                     0);
        return false;
    }
    showBasicRotation();
    return true;
}

}  // namespace kerf::ui
