#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include "core/base/diagnostic.h"
#include "ui/common/diagnostic_text.h"
#include "ui/testrun/machine_follower.h"
#include "ui/testrun/test_run_program.h"

class QTimer;

namespace kerf::graphics {
class ProgressiveStock;
}

namespace kerf::ui {

// Playback speeds of the test run, in machining time per wall-clock time.
enum class TestRunSpeed { Real, Times10, Times100, Max };
double speedFactor(TestRunSpeed speed);  // Max: infinity
QString speedText(TestRunSpeed speed);   // "x1", "x10", "x100", "max"

// What the machine does, as the graphics of Program run follow it (MachineStatus, read by the
// session from motion's status snapshot).
struct MachineSample {
    SourceLocation block;  // the block being executed
    Vec3 nominal{0.0, 0.0, 0.0};
    Pose actual;   // the tool tip from the drives, workpiece coordinates
    Pose machine;  // the same point in machine coordinates
    // The program moves the axes along its path (not held, stopped or jogged away).
    bool onPath = false;
    double feedOverride = 1.0;  // fractions: 1 = 100 %
    double rapidOverride = 1.0;
};

// The test run (programming mode Test run): interprets the editor's program off the UI thread,
// then plays it back by machining time at a selectable speed, removing material from the stock
// on the stock worker as the playback passes each command. Diagnostics of the run are reported
// with their line. UI thread only.
//
// The same playback follows the machine in Program run (follow()): the program the machine
// runs is prepared alike, and the point reached comes from the machine (MachineFollower)
// instead of the clock; the tool is drawn where the drives say and the stock is cut along the
// positions the drives report.
class TestRunController : public QObject {
    Q_OBJECT

public:
    enum class State { Empty, Interpreting, Ready, Playing, Following, Stopped, Finished, Failed };

    TestRunController(machine::MachineConfig machine, std::filesystem::path ncRoot,
                      QObject* parent = nullptr);
    ~TestRunController() override;

    // Checks the work area as Program run does: `checkMoves` is the machine's check (soft limits,
    // planner rules), `presetInMachine` says where the workpiece origin lies now. A program the
    // machine would refuse plays up to the refused block and ends Failed, the message naming
    // the block. The origin is asked again at every start: a moved preset prepares anew.
    void setWorkAreaCheck(task::MoveCheckFactory checkMoves, std::function<Pose()> presetInMachine);
    // Times the programs prepared from now on as the machine runs them (see TestRunInput);
    // none: no machining time.
    void setMachiningClock(task::MachiningClockFactory clock) {
        m_machiningClock = std::move(clock);
    }

    // Interprets a program (replacing the one prepared); programReady() or failed() follows.
    void prepare(const QString& text, const std::filesystem::path& path, program::Dialect dialect,
                 const Pose& start = {});
    // Plays this program: prepares it first when the text differs from the prepared one, and
    // starts from the beginning when the last playback had finished.
    void start(const QString& text, const std::filesystem::path& path, program::Dialect dialect);
    // Plays the prepared program from where it stopped.
    void play();
    void stop();
    // Back to the beginning: the untouched blank, time zero.
    void reset();
    // Forgets the prepared program (another one is in the editor now): an interpretation under
    // way is cancelled and its result dropped; the graphics go empty (programReady() with no
    // program).
    void clear();
    void setSpeed(TestRunSpeed speed);
    TestRunSpeed speed() const { return m_speed; }
    // Moves the playback on by this much wall-clock time at the chosen speed (the timer calls
    // it; tests call it to drive the playback without waiting).
    void advance(double wallSeconds);
    // Tick of the playback timer in milliseconds (tests set 0 to drive advance() themselves).
    void setTickMs(int milliseconds);

    // Program run: shows the program the machine runs from now on (prepared when the text, file
    // or origin differ from the prepared one), from the uncut blank; followMachine() moves it on.
    // `start`: where the machine stands (workpiece coordinates), as the machine's program starts.
    void follow(const QString& text, const std::filesystem::path& path, program::Dialect dialect,
                const Pose& start);
    // A look at the machine. Looks closer together than `followIntervalMs` are left out (the
    // session looks every 20 ms, the graphics need less); while the program is prepared they
    // are kept and followed once it is ready.
    void followMachine(const MachineSample& sample);
    // The machine's run ended; completed: it ran to its end (100 %, nothing remaining).
    void endFollowing(bool completed);
    bool following() const { return m_followingMachine; }
    // This playback shows the machine's runs (set, or follow() was its last start): the
    // graphics show its progress, not a playback speed.
    bool followsMachine() const { return m_machinePlayback; }
    void setFollowsMachine(bool on) { m_machinePlayback = on; }
    // Of the machining time (the planner's): the part done, 0..100, and the time left, under
    // the overrides of the machine followed (infinite when one that matters is 0 %).
    double progressPercent() const;
    double remainingTimeS() const;
    // Following the machine: the feed of the command it executes (0 for a rapid), per minute or
    // per revolution as the block's feed mode says, in mm. None otherwise.
    struct Feed {
        double mm = 0.0;
        bool perRevolution = false;
    };
    std::optional<Feed> followedFeed() const;
    void setFollowIntervalMs(int milliseconds) { m_followIntervalMs = milliseconds; }
    static constexpr int kFollowIntervalMs = 40;  // 25 pictures a second at most

    // Following the machine, the executed part of the toolpath: from the start of the run (the
    // start block of a run started at a block) to the point reached; empty otherwise.
    struct ExecutedPart {
        size_t fromPoint = 0;
        PathPlace reached;
    };
    ExecutedPart executedPart() const;

    State state() const { return m_state; }
    double playbackTimeS() const { return m_timeS; }
    double machiningTimeS() const;
    // The program as interpreted (null before the first one is ready).
    std::shared_ptr<const TestRunProgram> program() const { return m_program; }
    // The stock being cut (null without a ready program). Replaced by reset() and prepare().
    const graphics::ProgressiveStock* stock() const { return m_stock.get(); }
    Vec3 toolPosition() const;
    Vec3 toolAxis() const;  // the tool's direction on the workpiece (a rotary table tilts it)
    // Line of the block being played (0 before the first command).
    int currentLine() const;
    // The block being played or followed (none before the first command and after the last).
    std::optional<SourceLocation> currentBlock() const;
    program::Dialect dialect() const { return m_preparedDialect; }

signals:
    void stateChanged();
    void programReady();
    void stockReplaced(const kerf::graphics::ProgressiveStock* stock);
    void progressChanged(double timeS);
    void speedChanged();
    // One diagnostic of the run, with the line of the main program it refers to (0: none).
    void diagnostic(kerf::Severity severity, const QString& text, int line);
    // The interpreter's status at the block being played (for the status tabs).
    void programStatusChanged(const kerf::interp::ProgramStatus& status);

private:
    void onInterpreted(std::shared_ptr<const TestRunProgram> program, uint64_t generation);
    void startFollowing();
    void applySample(const MachineSample& sample);
    // The stock follows the drives: a cut from the last position reported to this one.
    // Along the prepared path's points [fromPoint, toPoint) first (the machine passed them).
    void cutTo(const MachineSample& sample, size_t fromPoint, size_t toPoint);
    void newStock();
    void pushUpTo(double timeS);
    void publishStatus();
    void setState(State state);
    void tick();
    void stopWorker();
    // The prepared program may be played (to its end, or to the block the machine refuses).
    bool playable() const;
    Pose currentOrigin() const;

    machine::MachineConfig m_machine;
    std::filesystem::path m_ncRoot;
    task::MachiningClockFactory m_machiningClock;
    std::shared_ptr<const TestRunProgram> m_program;
    std::unique_ptr<graphics::ProgressiveStock> m_stock;
    QString m_preparedText;
    std::filesystem::path m_preparedPath;
    std::string m_preparedFile;  // the name the interpreter knows the program by
    Pose m_preparedOrigin{};
    Pose m_preparedStart{};
    program::Dialect m_preparedDialect = program::Dialect::Klartext;
    task::MoveCheckFactory m_checkMoves;
    std::function<Pose()> m_presetInMachine;
    size_t m_pushed = 0;  // commands handed to the stock
    const TestRunProgram::StatusSnapshot* m_shownStatus = nullptr;
    double m_timeS = 0.0;
    TestRunSpeed m_speed = TestRunSpeed::Times10;
    State m_state = State::Empty;
    bool m_playWhenReady = false;
    QTimer* m_timer = nullptr;
    QElapsedTimer m_clock;
    std::thread m_worker;
    std::atomic<bool> m_cancel{false};
    uint64_t m_generation = 0;
    // Program run (follow()).
    bool m_followingMachine = false;
    bool m_machinePlayback = false;
    std::optional<MachineFollower> m_follower;
    std::vector<MachineSample> m_waitingSamples;  // while the program is prepared
    std::optional<bool> m_endWhenReady;           // the run ended while it was prepared
    std::optional<Pose> m_actual;                 // last position the drives reported
    std::optional<Pose> m_toMachine;              // and from it to machine coordinates
    bool m_lastOnPath = false;
    double m_feedOverride = 1.0;  // of the machine followed (the test run: 100 %)
    double m_rapidOverride = 1.0;
    QElapsedTimer m_sampleClock;
    int m_followIntervalMs = kFollowIntervalMs;
};

}  // namespace kerf::ui
