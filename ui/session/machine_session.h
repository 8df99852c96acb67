#pragma once

#include <QObject>
#include <QString>
#include <QStringList>
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/cycles/probing/manual_probing.h"
#include "core/interp/program_status.h"
#include "core/machine/machine_config.h"
#include "core/task/machine_status.h"
#include "core/task/motion_port.h"
#include "core/task/preset_store.h"
#include "core/task/program_run.h"
#include "ui/common/message_cause.h"

class QTimer;

namespace kerf::program {
class SourceRegistry;
}
namespace kerf::tables {
class ToolTable;
}
namespace kerf::task {
class ShiftedMotionPort;
struct LoadedProgram;
}  // namespace kerf::task

namespace kerf::ui {

// Makes the connection to the machine (app/ decides: simulated or real drives). The programming
// station has none.
using MotionFactory = std::function<std::unique_ptr<task::MotionPort>()>;

// The machine as the HMI drives it: owns the MotionPort and the program run (task::ProgramRun),
// serviced by a timer in the UI thread. Program run (start, start at a block, cycle start, feed
// hold, stop, single block), MDI, manual operation (jog, increment, home, spindle) and the
// overrides; it publishes the machine status, the run state and messages naming the block.
class MachineSession : public QObject {
    Q_OBJECT

public:
    static constexpr int kServiceIntervalMs = 20;

    MachineSession(machine::MachineConfig machine, std::unique_ptr<task::MotionPort> motion,
                   std::filesystem::path ncRoot, QObject* parent = nullptr);
    ~MachineSession() override;

    const machine::MachineConfig& machine() const { return m_machine; }
    // The machine as the programs see it: from the workpiece origin the operator set.
    task::MotionPort& motion();

    // Program run. False (and a message) when the program cannot start: errors in it, or the
    // machine is busy. startLine: start in mid-program at the first block on or after it, with
    // the tool, spindle and position the blocks before it leave.
    // operatorInputs: FAGOR IBn values for the run (n, value).
    bool startProgram(const QString& text, const std::filesystem::path& path,
                      std::optional<uint32_t> startLine = std::nullopt,
                      const std::vector<std::pair<int, double>>& operatorInputs = {});
    bool executeMdi(const QString& block);
    // The MDI blocks started in this session, the latest first, each once (a rerun moves it up).
    const QStringList& mdiHistory() const { return m_mdiHistory; }
    // Resumes after feed hold, a program stop or a single-block stop; after a jog away from the
    // interrupted program it first returns to where the program stopped (return to the contour).
    void cycleStart();
    void feedHold();
    // Stops on the path and aborts the program; in every state the machine then returns to
    // idle, with the spindle and the coolant off.
    void stop();
    // The emergency stop key (or the machine's input): the drives stop at once and are
    // disabled, a program is aborted; nothing moves until machineOn(). On the simulated
    // machine the key is the machine's latching button: it stays pressed until released.
    void emergencyStop();
    void releaseEmergencyStop();
    bool emergencyStopPressed() const { return m_emergencyStopPressed; }
    // Switches the machine on again after an emergency stop or a drive fault; false (and a
    // message) when it is on already (an information that stands a few seconds) or the
    // emergency stop button is still pressed.
    bool machineOn();
    void setSingleBlock(bool on);
    bool singleBlock() const { return m_singleBlock; }

    // Manual operation: while no program or MDI block runs, or while one is held or stopped
    // (the jogs leave its path; cycleStart() returns to it). Homing and the spindle only without.
    bool jog(Axis axis, int direction);  // continuous until jogStop()
    void jogStop(Axis axis);
    bool jogIncrement(Axis axis, int direction);
    void setIncrementMm(double mm) { m_incrementMm = mm; }
    double incrementMm() const { return m_incrementMm; }
    // Moves one axis by a distance (the handwheel's detents).
    bool jogDistance(Axis axis, double mm);
    bool homeAll();
    // Without `rpm` the spindle starts at the manual speed (the S entry of Manual operation).
    bool spindle(bool on, std::optional<double> rpm = std::nullopt);
    // Sets the manual speed, limited to the machine's spindle range; returns the speed kept.
    double setManualSpindleRpm(double rpm);
    double manualSpindleRpm() const { return m_manualSpindleRpm; }

    // Electronic handwheel (simulated): each detent moves the selected axis by the factor
    // (1, 10 or 100) times 0.001 mm.
    static constexpr double kHandwheelDetentMm = 0.001;
    void setHandwheelAxis(Axis axis) { m_handwheelAxis = axis; }
    Axis handwheelAxis() const { return m_handwheelAxis; }
    void setHandwheelFactor(int factor) { m_handwheelFactor = factor; }
    int handwheelFactor() const { return m_handwheelFactor; }
    bool turnHandwheel(int detents);
    bool coolant(bool on);

    // Set a preset by entry: the axis's current (actual) position becomes `shownValue`, given as
    // the position display shows it (a lathe's diameter-mode X as a diameter). It moves the
    // workpiece origin; programs started afterwards use it. On a mill it is written to row 0 of
    // the NC root's PRESET.PR. False (and a message) while the machine moves.
    bool setPresetByEntry(Axis axis, double shownValue);
    // Manual probing (mill, Manual operation): choose a function (which clears its touches), then
    // touch from where the probe stands along an axis direction, turned by the active basic
    // rotation (row 0's SPC) as the TNC does. The touch is decided on the simulated part (the
    // last BLK FORM, else [simulation.blank], placed with [simulation.setup]) and the probe
    // moves to the trigger at the probe table's F and back. False (and a message) on a miss within
    // DIST, a deflected stylus, no probe in the spindle, or while the machine moves.
    void startManualProbing(cycles::probing::ManualProbingFunction function);
    cycles::probing::ManualProbingFunction manualProbingFunction() const { return m_probing; }
    int manualTouchesDone() const { return static_cast<int>(m_touches.size()); }
    bool probeTouch(const Vec3& axisDirection);
    // The direction the panel's touch key probes in (the operator's choice, kept while the
    // softkey rows are rebuilt).
    void setProbeDirection(const Vec3& direction) { m_probeDirection = direction; }
    const Vec3& probeDirection() const { return m_probeDirection; }
    // Once the function has its touches: what they give (workpiece coordinates of the origin
    // the touches were made from).
    std::optional<cycles::probing::ManualProbingResult> manualProbingResult() const;
    // The origin moves so that the probed coordinate `measured` of `axis` reads `value`, written
    // to row 0 of PRESET.PR as setPresetByEntry does.
    bool setPresetFromProbing(Axis axis, double measured, double value);
    // The probed misalignment becomes the basic rotation of row 0 of PRESET.PR (its SPC column).
    bool setBasicRotation(double degrees);

    // Tool calibration (lathe, FAGOR): the tool touches the part where the axis really stands at
    // `knownValue` (X as the display shows it: a diameter in diameter mode). The length of
    // offset D on that axis in the NC root's fagor_tool_offsets.tab becomes the one that puts the
    // tip there, with the offset the last program left active as the one the tip is shown with
    // (fagor::touchOff); the file is replaced atomically. False (and a message) while the
    // machine moves, for D outside 1-255 or when the table cannot be read or written.
    bool touchOffTool(int offset, Axis axis, double knownValue);
    // Tool length touch-off (mill): the tool in the spindle touches a surface whose Z is
    // `knownZ`; its L in the NC root's TOOL.T becomes the one that makes the display show that
    // (task::touchOffToolLength; DL kept), from the next TOOL CALL on. False (and a message)
    // while the machine moves, without a tool or when TOOL.T cannot be read or written.
    bool touchOffToolLength(double knownZ);
    // The FAGOR offset D the last program left active (none before the first program).
    const std::optional<interp::ProgramStatus::Tool::LatheOffset>& activeLatheOffset() const {
        return m_activeLatheOffset;
    }
    // The workpiece origin in machine coordinates: the machine file's preset, then (mill) the
    // axes row 0 of PRESET.PR sets, then the entries of a lathe.
    Pose presetInMachine() const;
    // The basic rotation programs and MDI start with: row 0's SPC on the mill.
    double basicRotationDeg() const;
    // The origin the next program will start from (the table's row 0 read again while nothing
    // runs): what the test run checks the work area with.
    Pose nextProgramOrigin();

    // Fractions: 1 = 100 %.
    void setFeedOverride(double fraction);
    void setRapidOverride(double fraction);
    void setSpindleOverride(double fraction);

    task::RunState runState() const { return m_run->state(); }
    // A program or MDI block moves the machine (the machine mode must not change).
    bool busy() const;
    const task::MachineStatus& status() const { return m_status; }
    // Every axis has been homed since power-on (or the machine counts as referenced from the
    // start: reference_required = false).
    bool referenced() const;
    // Whether the cause of a message still holds (None: an event, never "gone").
    bool causeHolds(MessageCause cause) const;
    const task::ProgramRun& run() const { return *m_run; }
    // The line of the main program whose block is executing, while a program runs (none in a
    // called program's file or in MDI).
    std::optional<int> executingLine() const;
    // The name (programName()) of the program started last; empty after MDI.
    const std::string& runningProgramName() const { return m_programName; }
    // Where the tool tip stood when the program started last (workpiece coordinates, before a
    // FAGOR zero offset moved the origin): its interpreter began there.
    const Pose& programStart() const { return m_programStart; }

    // One step of the task: called by the timer; tests call it directly.
    void service();

signals:
    void statusChanged(const kerf::task::MachineStatus& status);
    void runStateChanged(kerf::task::RunState state);
    // The running program's interpreter state, for the status tabs: a few times a second while
    // it runs, and once when it ends (an MDI block ends before the next picture).
    void programStatusChanged(const kerf::interp::ProgramStatus& status);
    // `cause`: the message leaves the message line once causeHolds(cause) is false.
    void message(kerf::Severity severity, const QString& text, int line,
                 kerf::ui::MessageCause cause = kerf::ui::MessageCause::None);
    // Manual probing chose a function or made a touch (manualProbingResult once complete).
    void manualProbingChanged();
    void toolLengthTouchedOff(int tool, double lengthMm);
    // Row 0's basic rotation changed (probing, a program, the table before a program): the
    // position display turns X and Y by it.
    void basicRotationChanged(double degrees);

private:
    // Program run honours the single-block key; MDI and generated programs (probing) run their
    // blocks to the end.
    bool start(task::LoadedProgram loaded, std::optional<uint32_t> startLine, bool singleBlock);
    bool refuseWhenBusy();
    // Programs and MDI wait for the reference run unless the machine file needs none.
    bool refuseWhenNotReferenced();
    bool jogAllowed() const;
    // Mill: the workpiece origin follows row 0 of PRESET.PR (read at start and before every
    // program, so edits in the table editor count from the next program on).
    void applyPresetTable();
    // Emits basicRotationChanged when row 0's basic rotation is not the one last shown.
    void showBasicRotation();
    // The actual position of `axis` as the display shows it (X and Y turned by the basic
    // rotation).
    double shownActual(Axis axis) const;
    void report(const DiagnosticList& diagnostics);
    void showRunWarnings();
    // The origin moves so that `axis`, now at `current`, shows `value` (workpiece coordinates).
    bool movePreset(Axis axis, double current, double value);
    bool runGeneratedProgram(const std::string& text);
    // Manual probing: the completed function's touches and result to TCHPRMAN.html.
    void writeManualProbingLog();

    machine::MachineConfig m_machine;
    std::unique_ptr<task::ShiftedMotionPort> m_motion;
    std::filesystem::path m_ncRoot;
    task::PresetStore m_presets;
    std::string m_programName;            // the running program's name in m_sources; empty: MDI
    bool m_emergencyStopPressed = false;  // the simulated machine's button latched
    bool m_lastStartRefused = false;      // the last NC start or MDI block had errors
    // Until when the latest MessageCause::Moment information stands.
    std::chrono::steady_clock::time_point m_momentEnds{};
    Pose m_programStart{};
    // The interpreter refers to these: they live as long as the run that uses them.
    std::unique_ptr<program::SourceRegistry> m_sources;
    std::unique_ptr<tables::ToolTable> m_tools;
    std::unique_ptr<task::ProgramRun> m_run;
    QTimer* m_timer = nullptr;
    task::MachineStatus m_status;
    task::RunState m_lastState = task::RunState::Idle;
    // The running program's diagnostics: those it had on start, and how many the messages have
    // shown (showRunWarnings).
    size_t m_runDiagnosticsStart = 0;
    size_t m_runDiagnosticsShown = 0;
    double m_shownBasicRotationDeg = 0.0;
    static constexpr int kProgramStatusEvery = 10;  // services (200 ms)
    int m_servicesSinceProgramStatus = 0;
    double m_incrementMm = 1.0;
    double m_manualSpindleRpm = 1000.0;  // until the operator enters S
    // The modal S an MDI block starts with: the last program's or MDI block's, or the speed the
    // operator started the spindle at (0: none yet).
    double m_modalSpindleRpm = 0.0;
    QStringList m_mdiHistory;
    Axis m_handwheelAxis = Axis::X;
    int m_handwheelFactor = 1;
    bool m_singleBlock = false;
    cycles::probing::ManualProbingFunction m_probing =
        cycles::probing::ManualProbingFunction::Position;
    std::vector<cycles::probing::ManualTouch> m_touches;  // workpiece coordinates
    double m_probeBallRadius = 0.0;                       // of the probe that made them
    Vec3 m_probeDirection{1.0, 0.0, 0.0};
    std::optional<interp::ProgramStatus::Tool::LatheOffset> m_activeLatheOffset;
};

}  // namespace kerf::ui
