#include "ui/session/machine_session.h"

#include <QTimer>
#include <algorithm>

#include "core/cycles/probing/manual_probing.h"
#include "core/interp/fagor/tables/tool_touch_off.h"
#include "core/program/nc_root.h"
#include "core/task/program_loader.h"
#include "core/task/shifted_motion_port.h"
#include "ui/common/diagnostic_text.h"
#include "ui/session/program_origin.h"

namespace kerf::ui {

namespace {

// How long an information on a key press (MessageCause::Moment) stays on the message line.
constexpr std::chrono::seconds kMomentShown{3};

}  // namespace

MachineSession::MachineSession(machine::MachineConfig machine,
                               std::unique_ptr<task::MotionPort> motion,
                               std::filesystem::path ncRoot, QObject* parent)
    : QObject(parent),
      m_machine(std::move(machine)),
      m_motion(std::make_unique<task::ShiftedMotionPort>(std::move(motion))),
      m_ncRoot(std::move(ncRoot)),
      m_presets(m_ncRoot),
      m_run(std::make_unique<task::ProgramRun>(*m_motion)) {
    registerDiagnosticMetaTypes();
    applyPresetTable();
    setManualSpindleRpm(m_manualSpindleRpm);
    m_status = m_motion->status();
    m_timer = new QTimer(this);
    m_timer->setInterval(kServiceIntervalMs);
    connect(m_timer, &QTimer::timeout, this, &MachineSession::service);
    m_timer->start();
}

MachineSession::~MachineSession() {
    // The run refers to the interpreter's sources and the motion port: it goes first.
    m_run.reset();
}

task::MotionPort& MachineSession::motion() {
    return *m_motion;
}

bool MachineSession::busy() const {
    return m_run->moving() || m_run->state() == task::RunState::Held ||
           m_run->state() == task::RunState::Stopped;
}

bool MachineSession::refuseWhenBusy() {
    if (!busy() && m_status.state == task::MachineState::Idle) return false;
    if (m_emergencyStopPressed) {
        emit message(Severity::Error,
                     tr("The emergency stop button is pressed: release it, then Machine on"), 0,
                     MessageCause::EmergencyStop);
        return true;
    }
    if (m_status.state == task::MachineState::EmergencyStop ||
        m_status.state == task::MachineState::Fault) {
        emit message(Severity::Error,
                     tr("The machine is off (emergency stop or drive fault): switch it on with "
                        "Machine on"),
                     0, MessageCause::MachineOff);
        return true;
    }
    emit message(Severity::Error,
                 tr("The machine is busy: stop the program or wait until the axes stand still"), 0,
                 MessageCause::Busy);
    return true;
}

bool MachineSession::referenced() const {
    // Before the machine's first status no axis is enabled: not referenced yet either.
    bool anyAxis = false;
    for (const task::AxisStatus& axis : m_status.axes) {
        if (!axis.enabled) continue;
        if (!axis.homed) return false;
        anyAxis = true;
    }
    return anyAxis;
}

bool MachineSession::causeHolds(MessageCause cause) const {
    switch (cause) {
        case MessageCause::None:
            return true;
        case MessageCause::NotReferenced:
            return m_machine.referenceRequired && !referenced();
        case MessageCause::EmergencyStop:
            return m_emergencyStopPressed;
        case MessageCause::MachineOff:
            return m_status.state == task::MachineState::EmergencyStop ||
                   m_status.state == task::MachineState::Fault;
        case MessageCause::Busy:
            return busy() || m_status.state != task::MachineState::Idle;
        case MessageCause::ProgramRefused:
            return m_lastStartRefused;
        case MessageCause::Moment:
            return std::chrono::steady_clock::now() < m_momentEnds;
    }
    return true;
}

bool MachineSession::refuseWhenNotReferenced() {
    if (!m_machine.referenceRequired || referenced()) return false;
    emit message(Severity::Error,
                 tr("The axes are not referenced: run Home all in Manual operation first"), 0,
                 MessageCause::NotReferenced);
    return true;
}

void MachineSession::showRunWarnings() {
    // Warnings of the running program as it finds them (a rapid into the blank: a collision).
    const interp::Interpreter* interpreter = m_run->interpreter();
    if (interpreter == nullptr) return;
    const DiagnosticList& all = interpreter->diagnostics();
    for (; m_runDiagnosticsShown < all.size(); ++m_runDiagnosticsShown) {
        const Diagnostic& d = all[m_runDiagnosticsShown];
        if (d.severity == Severity::Warning)
            emit message(d.severity, translatedMessage(d), static_cast<int>(d.line));
    }
}

void MachineSession::report(const DiagnosticList& diagnostics) {
    for (const Diagnostic& d : diagnostics)
        emit message(d.severity, translatedMessage(d), static_cast<int>(d.line));
}

bool MachineSession::startProgram(const QString& program, const std::filesystem::path& path,
                                  std::optional<uint32_t> startLine,
                                  const std::vector<std::pair<int, double>>& operatorInputs) {
    if (refuseWhenBusy() || refuseWhenNotReferenced()) return false;
    applyPresetTable();
    task::ProgramRequest request;
    request.text = program.toStdString();
    request.path = path;
    request.ncRoot = m_ncRoot;
    m_programStart.values = m_motion->world().position.values;
    request.startPosition = m_programStart;
    request.presetInMachine = presetInMachine();
    request.basicRotationDeg = basicRotationDeg();
    request.operatorInputs = operatorInputs;
    request.touchesFromMachine = m_motion->latchesProbe();
    m_programName = task::programName(path);
    return start(task::loadProgram(m_machine, request), startLine, m_singleBlock);
}

bool MachineSession::executeMdi(const QString& block) {
    if (refuseWhenBusy() || refuseWhenNotReferenced()) return false;
    applyPresetTable();
    task::ProgramRequest request;
    request.text = task::mdiProgram(m_machine, block.trimmed().toStdString());
    request.ncRoot = m_ncRoot;
    request.startPosition = Pose{};
    request.startPosition->values = m_motion->world().position.values;
    request.presetInMachine = presetInMachine();
    request.basicRotationDeg = basicRotationDeg();
    // A TNC's MDI keeps S, the spindle and the coolant from one block to the next.
    request.mdi = true;
    request.touchesFromMachine = m_motion->latchesProbe();
    request.spindleRpm = m_modalSpindleRpm;
    if (m_status.programmedSpindleRpm > 0.0) {
        request.spindle = m_status.actualSpindleRpm < 0.0
                              ? canon::SpindleDirection::CounterClockwise
                              : canon::SpindleDirection::Clockwise;
    }
    m_programName.clear();
    if (!start(task::loadProgram(m_machine, request), std::nullopt, false)) return false;
    constexpr qsizetype kMaxMdiHistory = 50;
    m_mdiHistory.removeAll(block.trimmed());
    m_mdiHistory.prepend(block.trimmed());
    if (m_mdiHistory.size() > kMaxMdiHistory) m_mdiHistory.removeLast();
    return true;
}

bool MachineSession::start(task::LoadedProgram loaded, std::optional<uint32_t> startLine,
                           bool singleBlock) {
    m_lastStartRefused = !loaded.ready;
    if (!loaded.ready) {
        for (const Diagnostic& d : loaded.diagnostics())
            emit message(d.severity, translatedMessage(d), static_cast<int>(d.line),
                         MessageCause::ProgramRefused);
        emit message(Severity::Error, tr("The program has errors and cannot be started"), 0,
                     MessageCause::ProgramRefused);
        return false;
    }
    task::StartOptions options;
    options.startLine = startLine;
    options.toolAxis = m_machine.kind == machine::MachineKind::Lathe ? Axis::X : Axis::Z;
    if (loaded.streamOrigin) {
        // A FAGOR zero offset (G54-G59 from the table) moves the origin the axes are shown from.
        Pose shift = *loaded.streamOrigin;
        const Pose own = presetInMachine();
        for (size_t i = 0; i < shift.values.size(); ++i)
            shift.values[i] += m_motion->shift().values[i] - own.values[i];
        m_motion->setShift(shift);
    }
    m_motion->setSingleBlock(singleBlock);
    // FAGOR 8035: single block stops after every block, one without a move too.
    m_motion->setSingleBlockEveryBlock(loaded.dialect == program::Dialect::Fagor);
    m_motion->setProgramCuts(loaded.removedMaterial);
    m_runDiagnosticsShown = loaded.interpreter->diagnostics().size();
    m_runDiagnosticsStart = m_runDiagnosticsShown;
    m_run->start(std::move(loaded.interpreter), options);
    // The previous run's interpreter is gone: its sources and tools may go too.
    m_sources = std::move(loaded.sources);
    m_tools = std::move(loaded.tools);
    service();
    return true;
}

void MachineSession::cycleStart() {
    m_run->cycleStart();
}

void MachineSession::feedHold() {
    m_run->feedHold();
}

void MachineSession::stop() {
    m_run->abort();
    // Also without a program: the stop ends a jog or a reference run and turns the spindle and
    // the coolant off (a second stop while a program's stop is under way changes nothing).
    m_motion->quickStop();
}

void MachineSession::emergencyStop() {
    m_motion->emergencyStop();
    m_emergencyStopPressed = m_motion->setEmergencyStopButton(true);
    m_run->abort();
    service();
}

void MachineSession::releaseEmergencyStop() {
    if (!m_emergencyStopPressed) return;
    m_motion->setEmergencyStopButton(false);
    m_emergencyStopPressed = false;
    service();
}

bool MachineSession::machineOn() {
    if (m_emergencyStopPressed) {
        emit message(Severity::Warning, tr("Release the emergency stop button first"), 0,
                     MessageCause::EmergencyStop);
        return false;
    }
    if (m_motion->machineOn()) return true;
    // The servo cycle may not have seen the released button yet: one cycle later it has.
    if (m_motion->status().emergencyStopOpen) {
        emit message(Severity::Warning, tr("The emergency stop chain is still open"), 0,
                     MessageCause::MachineOff);
        return false;
    }
    // Nothing is wrong: an information, read at a glance, that does not stick to the line.
    m_momentEnds = std::chrono::steady_clock::now() + kMomentShown;
    emit message(Severity::Note, tr("The machine is on already"), 0, MessageCause::Moment);
    return false;
}

void MachineSession::setSingleBlock(bool on) {
    m_singleBlock = on;
    m_motion->setSingleBlock(on);
}

bool MachineSession::jogAllowed() const {
    // A held or stopped run may be left by jogging; while the axes jog away from it the run
    // follows motion and shows as running, but the machine state says it jogs.
    const task::RunState run = m_run->state();
    if (run == task::RunState::Held || run == task::RunState::Stopped) return true;
    return !busy() || m_status.state == task::MachineState::Jogging;
}

bool MachineSession::jog(Axis axis, int direction) {
    if (!jogAllowed()) return false;
    return m_motion->jogContinuous(axis, direction >= 0 ? 0.2 : -0.2);
}

void MachineSession::jogStop(Axis axis) {
    m_motion->jogStop(axis);
}

bool MachineSession::jogIncrement(Axis axis, int direction) {
    if (!jogAllowed()) return false;
    return m_motion->jogIncrement(axis, direction >= 0 ? m_incrementMm : -m_incrementMm);
}

bool MachineSession::jogDistance(Axis axis, double mm) {
    if (!jogAllowed()) return false;
    return m_motion->jogIncrement(axis, mm);
}

bool MachineSession::turnHandwheel(int detents) {
    return jogDistance(m_handwheelAxis, detents * m_handwheelFactor * kHandwheelDetentMm);
}

bool MachineSession::coolant(bool on) {
    if (refuseWhenBusy()) return false;
    canon::CoolantControl control;
    control.flood = on;
    return m_motion->manualCoolant(control);
}

bool MachineSession::setPresetByEntry(Axis axis, double shownValue) {
    double value = shownValue;
    for (const machine::AxisConfig& config : m_machine.axes) {
        if (axisFromLetter(config.letter) == axis && config.diameterMode) value /= 2.0;
    }
    return movePreset(axis, shownActual(axis), value);
}

double MachineSession::shownActual(Axis axis) const {
    const task::MachineStatus now = m_motion->status();
    const double b = basicRotationDeg();
    if (b == 0.0 || (axis != Axis::X && axis != Axis::Y))
        return now.axes[static_cast<size_t>(axisIndex(axis))].actual;
    // X and Y of the system turned by the basic rotation, as the position display shows them.
    const Vec3 shown = cycles::probing::turnedProbingDirection(
        Vec3(now.axes[0].actual, now.axes[1].actual, 0.0), -b);
    return axis == Axis::X ? shown.x() : shown.y();
}

bool MachineSession::movePreset(Axis axis, double current, double value) {
    if (refuseWhenBusy()) return false;
    // The origin moves by what the axis shows now minus what it should show, along the axis
    // turned by the basic rotation for X and Y (the display's axes).
    Pose shift = m_motion->shift();
    const double b = basicRotationDeg();
    if (b != 0.0 && (axis == Axis::X || axis == Axis::Y)) {
        const Vec3 along = cycles::probing::turnedProbingDirection(
            axis == Axis::X ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0), b);
        shift[Axis::X] += (current - value) * along.x();
        shift[Axis::Y] += (current - value) * along.y();
    } else {
        shift[axis] += current - value;
    }
    m_motion->setShift(shift);
    m_status = m_motion->status();
    emit statusChanged(m_status);
    if (m_machine.kind != machine::MachineKind::Lathe) {
        // The whole origin, so that a new table does not put the other axes at machine zero.
        AxisMask axes = 0;
        for (const machine::AxisConfig& config : m_machine.axes) {
            if (const auto a = axisFromLetter(config.letter)) axes |= axisBit(*a);
        }
        if (const MaybeError failed = m_presets.write(presetInMachine(), axes)) {
            emit message(Severity::Error,
                         tr("The preset could not be saved in PRESET.PR, so the next program "
                            "uses the table's preset again: %1")
                             .arg(translatedMessage(*failed)),
                         0);
        }
    }
    return true;
}

bool MachineSession::touchOffTool(int offset, Axis axis, double knownValue) {
    if (refuseWhenBusy()) return false;
    if (offset < 1 || offset > fagor::ToolOffsetTable::kMaxOffset) {
        emit message(Severity::Error, tr("The tool offset must be D1 to D255"), 0);
        return false;
    }
    fagor::TouchOff touch;
    touch.offset = offset;
    touch.axis = axis;
    touch.knownMm = knownValue;
    for (const machine::AxisConfig& config : m_machine.axes) {
        if (axisFromLetter(config.letter) == axis && config.diameterMode) touch.knownMm /= 2.0;
    }
    touch.shownMm = m_motion->status().axes[static_cast<size_t>(axisIndex(axis))].actual;
    if (m_activeLatheOffset) {
        touch.activeMm = axis == Axis::X ? m_activeLatheOffset->xMm + m_activeLatheOffset->wearXMm
                                         : m_activeLatheOffset->zMm + m_activeLatheOffset->wearZMm;
    }
    const std::filesystem::path path = m_ncRoot / "fagor_tool_offsets.tab";
    const program::NcRoot root(m_ncRoot);
    fagor::ToolOffsetTable table = fagor::ToolOffsetTable::createDefault();
    if (std::filesystem::exists(path)) {
        Expected<std::string> bytes = root.read(path);
        Expected<fagor::ToolOffsetTable> parsed =
            bytes ? fagor::ToolOffsetTable::parse(*bytes, path.filename().string())
                  : Expected<fagor::ToolOffsetTable>(bytes.error());
        if (!parsed) {
            emit message(Severity::Error,
                         tr("Tool calibration: %1").arg(translatedMessage(parsed.error())), 0);
            return false;
        }
        table = std::move(*parsed);
    }
    if (!fagor::touchOff(table, touch)) {
        emit message(Severity::Error, tr("Tool calibration works on X and Z only"), 0);
        return false;
    }
    if (const MaybeError failed = root.replace(path, table.serialize())) {
        emit message(Severity::Error, tr("Tool calibration: %1").arg(translatedMessage(*failed)),
                     0);
        return false;
    }
    const fagor::ToolOffset written = table.get(offset);
    // The table holds X as a radius, whatever the display shows.
    const QString text = axis == Axis::X ? tr("Tool offset D%1: X = %2 mm (radius)")
                                         : tr("Tool offset D%1: Z = %2 mm");
    emit message(Severity::Note,
                 text.arg(offset).arg(axis == Axis::X ? written.x : written.z, 0, 'f', 4), 0);
    return true;
}

void MachineSession::applyPresetTable() {
    const Pose origin = programOrigin(m_machine, m_presets, m_motion->shift());
    const Pose own = machineFilePreset(m_machine);
    Pose shift;
    for (size_t i = 0; i < shift.values.size(); ++i)
        shift.values[i] = origin.values[i] - own.values[i];
    m_motion->setShift(shift);
    showBasicRotation();
}

void MachineSession::showBasicRotation() {
    const double b = basicRotationDeg();
    if (b == m_shownBasicRotationDeg) return;
    m_shownBasicRotationDeg = b;
    emit basicRotationChanged(b);
}

Pose MachineSession::presetInMachine() const {
    Pose preset = machineFilePreset(m_machine);
    for (size_t i = 0; i < preset.values.size(); ++i)
        preset.values[i] += m_motion->shift().values[i];
    return preset;
}

double MachineSession::basicRotationDeg() const {
    if (m_machine.kind == machine::MachineKind::Lathe) return 0.0;
    return m_presets.basicRotationDeg();
}

Pose MachineSession::nextProgramOrigin() {
    if (!busy()) applyPresetTable();
    return presetInMachine();
}

std::optional<int> MachineSession::executingLine() const {
    if (!busy() || m_programName.empty() || !m_sources) return std::nullopt;
    const SourceLocation& block = m_status.block;
    if (block.line == 0 || block.fileId >= m_sources->size() ||
        m_sources->path(block.fileId) != m_programName)
        return std::nullopt;
    return static_cast<int>(block.line);
}

bool MachineSession::homeAll() {
    if (refuseWhenBusy()) return false;
    return m_motion->home(std::nullopt);
}

double MachineSession::setManualSpindleRpm(double rpm) {
    const machine::SpindleConfig& spindle = m_machine.spindle;
    m_manualSpindleRpm = std::clamp(rpm, static_cast<double>(spindle.minRpm),
                                    static_cast<double>(std::max(spindle.minRpm, spindle.maxRpm)));
    return m_manualSpindleRpm;
}

bool MachineSession::spindle(bool on, std::optional<double> rpm) {
    if (refuseWhenBusy()) return false;
    canon::SpindleControl control;
    control.direction = on ? canon::SpindleDirection::Clockwise : canon::SpindleDirection::Stopped;
    control.speedRpm = on ? rpm.value_or(m_manualSpindleRpm) : 0.0;
    if (!m_motion->manualSpindle(control)) return false;
    if (on) m_modalSpindleRpm = control.speedRpm;
    return true;
}

void MachineSession::setFeedOverride(double fraction) {
    m_motion->setFeedOverride(fraction);
}

void MachineSession::setRapidOverride(double fraction) {
    m_motion->setRapidOverride(fraction);
}

void MachineSession::setSpindleOverride(double fraction) {
    m_motion->setSpindleOverride(fraction);
}

void MachineSession::service() {
    m_run->service();
    showRunWarnings();
    m_status = m_motion->status();
    emit statusChanged(m_status);
    const task::RunState state = m_run->state();
    // The status tabs need no more than a few pictures a second.
    if (const interp::Interpreter* interpreter = m_run->interpreter();
        interpreter && busy() && ++m_servicesSinceProgramStatus >= kProgramStatusEvery) {
        m_servicesSinceProgramStatus = 0;
        const interp::ProgramStatus status = interpreter->programStatus();
        m_activeLatheOffset = status.tool.lathe;
        emit programStatusChanged(status);
    }
    if (state == m_lastState) return;
    m_lastState = state;
    if (const interp::Interpreter* interpreter = m_run->interpreter();
        interpreter && (state == task::RunState::Finished || state == task::RunState::Failed)) {
        const interp::ProgramStatus status = interpreter->programStatus();
        m_activeLatheOffset = status.tool.lathe;
        if (status.motion.spindleRpm > 0.0) m_modalSpindleRpm = status.motion.spindleRpm;
        emit programStatusChanged(status);
    }
    // A probing cycle may have written row 0's basic rotation.
    if (state != task::RunState::Running) showBasicRotation();
    if (state == task::RunState::Failed) {
        // All but the warnings shown while it ran.
        const DiagnosticList& all = m_run->diagnostics();
        for (size_t i = 0; i < all.size(); ++i) {
            const bool shown = all[i].severity == Severity::Warning && i >= m_runDiagnosticsStart &&
                               i < m_runDiagnosticsShown;
            if (!shown) report({all[i]});
        }
    }
    if (state == task::RunState::Finished) emit message(Severity::Note, tr("Program finished"), 0);
    if (state == task::RunState::Aborted) emit message(Severity::Warning, tr("Program stopped"), 0);
    emit runStateChanged(state);
}

}  // namespace kerf::ui
