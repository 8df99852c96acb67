#include "ui/testrun/test_run_controller.h"

#include <QMetaObject>
#include <QTimer>
#include <algorithm>
#include <limits>

#include <sys/resource.h>
#include <unistd.h>

#include "graphics/stock/progressive_stock.h"
#include "ui/common/diagnostic_text.h"

namespace kerf::ui {

namespace {

constexpr int kPreparationNice = 10;

}  // namespace

double speedFactor(TestRunSpeed speed) {
    switch (speed) {
        case TestRunSpeed::Real:
            return 1.0;
        case TestRunSpeed::Times10:
            return 10.0;
        case TestRunSpeed::Times100:
            return 100.0;
        case TestRunSpeed::Max:
            break;
    }
    return std::numeric_limits<double>::infinity();
}

QString speedText(TestRunSpeed speed) {
    switch (speed) {
        case TestRunSpeed::Real:
            return QStringLiteral("x1");
        case TestRunSpeed::Times10:
            return QStringLiteral("x10");
        case TestRunSpeed::Times100:
            return QStringLiteral("x100");
        case TestRunSpeed::Max:
            break;
    }
    return TestRunController::tr("max");
}

TestRunController::TestRunController(machine::MachineConfig machine, std::filesystem::path ncRoot,
                                     QObject* parent)
    : QObject(parent), m_machine(std::move(machine)), m_ncRoot(std::move(ncRoot)) {
    registerDiagnosticMetaTypes();
    m_timer = new QTimer(this);
    m_timer->setInterval(50);  // 20 frames a second: enough for software OpenGL
    connect(m_timer, &QTimer::timeout, this, &TestRunController::tick);
}

TestRunController::~TestRunController() {
    stopWorker();
}

void TestRunController::setWorkAreaCheck(task::MoveCheckFactory checkMoves,
                                         std::function<Pose()> presetInMachine) {
    m_checkMoves = std::move(checkMoves);
    m_presetInMachine = std::move(presetInMachine);
}

Pose TestRunController::currentOrigin() const {
    return m_presetInMachine ? m_presetInMachine() : Pose{};
}

bool TestRunController::playable() const {
    return m_program && (m_program->ran || m_program->refusedAt);
}

void TestRunController::stopWorker() {
    m_cancel = true;
    if (m_worker.joinable()) m_worker.join();
    m_cancel = false;
}

void TestRunController::prepare(const QString& text, const std::filesystem::path& path,
                                program::Dialect dialect, const Pose& start) {
    stopWorker();
    m_timer->stop();
    m_follower.reset();
    m_preparedText = text;
    m_preparedPath = path;
    TestRunInput input;
    input.text = text.toStdString();
    input.path = path.empty() ? std::filesystem::path("PROGRAM") : path;
    m_preparedFile = input.path.string();
    input.dialect = dialect;
    input.machine = m_machine;
    input.ncRoot = m_ncRoot;
    input.clock = m_machiningClock;
    input.startPosition = start;
    m_preparedStart = start;
    m_preparedDialect = dialect;
    m_preparedOrigin = currentOrigin();
    input.presetInMachine = m_preparedOrigin;
    input.checkMoves = m_checkMoves;
    const uint64_t generation = ++m_generation;
    setState(State::Interpreting);
    m_worker = std::thread([this, input = std::move(input), generation] {
        // Below the panel and the machine's threads: Program run prepares while the axes move.
        setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kPreparationNice);
        auto program =
            std::make_shared<const TestRunProgram>(interpretForTestRun(input, &m_cancel));
        if (program->cancelled) return;
        // Queued to the UI thread; dropped by Qt if this object is gone by then.
        QMetaObject::invokeMethod(
            this, [this, program, generation] { onInterpreted(program, generation); },
            Qt::QueuedConnection);
    });
}

void TestRunController::onInterpreted(std::shared_ptr<const TestRunProgram> program,
                                      uint64_t generation) {
    if (generation != m_generation) return;  // a newer text is being interpreted
    if (m_worker.joinable()) m_worker.join();
    m_program = std::move(program);
    m_shownStatus = nullptr;
    for (const Diagnostic& d : m_program->diagnostics) {
        // Only lines of the program in the editor can be jumped to.
        const bool inEditor = d.file.empty() || d.file == m_preparedFile;
        emit diagnostic(d.severity, tr("Test run: %1").arg(translatedMessage(d)),
                        inEditor ? static_cast<int>(d.line) : 0);
    }
    m_timeS = 0.0;
    newStock();
    emit programReady();
    emit progressChanged(m_timeS);
    publishStatus();
    if (!playable() && !m_followingMachine) {
        m_playWhenReady = false;
        setState(State::Failed);
        return;
    }
    setState(State::Ready);
    if (m_followingMachine) return startFollowing();
    if (m_playWhenReady) {
        m_playWhenReady = false;
        play();
    }
}

void TestRunController::start(const QString& text, const std::filesystem::path& path,
                              program::Dialect dialect) {
    m_followingMachine = false;
    m_machinePlayback = false;
    m_follower.reset();
    if (m_state == State::Interpreting) {
        m_playWhenReady = true;
        return;
    }
    // A preset set or edited since the preparation moves the work area under the program.
    if (!m_program || text != m_preparedText || path != m_preparedPath ||
        currentOrigin().values != m_preparedOrigin.values || m_preparedStart != Pose{}) {
        m_playWhenReady = true;
        prepare(text, path, dialect);
        return;
    }
    if (m_state == State::Finished || (m_state == State::Failed && playable())) reset();
    play();
}

void TestRunController::play() {
    if (m_state != State::Ready && m_state != State::Stopped) return;
    setState(State::Playing);
    m_clock.start();
    if (m_speed == TestRunSpeed::Max) return advance(0.0);
    if (m_timer->interval() > 0) m_timer->start();
}

void TestRunController::stop() {
    m_playWhenReady = false;
    if (m_state != State::Playing) return;
    m_timer->stop();
    setState(State::Stopped);
}

void TestRunController::reset() {
    m_timer->stop();
    m_followingMachine = false;
    m_follower.reset();
    m_playWhenReady = false;
    if (!m_program || m_state == State::Interpreting) return;
    m_timeS = 0.0;
    newStock();
    emit progressChanged(m_timeS);
    m_shownStatus = nullptr;
    publishStatus();
    setState(playable() ? State::Ready : State::Failed);
}

void TestRunController::clear() {
    m_followingMachine = false;
    m_machinePlayback = false;
    m_follower.reset();
    stopWorker();
    ++m_generation;  // a result already queued belongs to the program before
    m_timer->stop();
    m_playWhenReady = false;
    m_program.reset();
    m_preparedText.clear();
    m_preparedPath.clear();
    m_preparedFile.clear();
    m_shownStatus = nullptr;
    m_timeS = 0.0;
    newStock();
    emit programReady();
    emit progressChanged(m_timeS);
    setState(State::Empty);
}

void TestRunController::setSpeed(TestRunSpeed speed) {
    if (speed == m_speed) return;
    m_speed = speed;
    emit speedChanged();
    if (m_state == State::Playing && speed == TestRunSpeed::Max) advance(0.0);
    if (m_state == State::Playing && m_timer->interval() > 0) m_timer->start();
}

void TestRunController::setTickMs(int milliseconds) {
    m_timer->setInterval(milliseconds);
    if (milliseconds <= 0) m_timer->stop();
}

double TestRunController::machiningTimeS() const {
    return m_program ? m_program->machiningTimeS() : 0.0;
}

Vec3 TestRunController::toolPosition() const {
    if (m_follower && m_actual) {
        const auto& frame = m_program ? m_program->stockOptions.workpieceFrame : std::nullopt;
        return frame ? frame->toPart(*m_actual).tip : m_actual->xyz();
    }
    return m_program ? m_program->toolPositionAt(m_timeS) : Vec3(0.0, 0.0, 0.0);
}

Vec3 TestRunController::toolAxis() const {
    if (!m_program) return Vec3::UnitZ();
    if (m_follower && m_actual) {
        const auto& frame = m_program->stockOptions.workpieceFrame;
        return frame ? frame->toPart(*m_actual).axis : Vec3::UnitZ();
    }
    return m_program->toolAxisAt(m_timeS);
}

TestRunController::ExecutedPart TestRunController::executedPart() const {
    ExecutedPart part;
    // The test run draws the whole path in its colours; the machine's run what it has done.
    if (!m_program || !m_follower || !m_follower->startPoint()) return part;
    const PathPlace start = m_program->placeAt(*m_follower->startPoint());
    part.fromPoint = start.pointsDone > 0 ? start.pointsDone - 1 : 0;
    part.reached = m_program->placeAt(m_follower->point());
    return part;
}

double TestRunController::progressPercent() const {
    const double total = machiningTimeS();
    if (total <= 0.0) return m_state == State::Finished ? 100.0 : 0.0;
    return std::clamp(100.0 * m_timeS / total, 0.0, 100.0);
}

double TestRunController::remainingTimeS() const {
    if (!m_program) return 0.0;
    return m_program->remainingTimeS(m_program->runPointAt(m_timeS), m_feedOverride,
                                     m_rapidOverride);
}

std::optional<SourceLocation> TestRunController::currentBlock() const {
    if (!m_program) return std::nullopt;
    const size_t index = m_follower ? m_follower->point().command : m_program->commandAt(m_timeS);
    if (index >= m_program->commands.size() || (m_follower && !m_follower->startPoint()))
        return std::nullopt;
    return m_program->commands[index].location;
}

int TestRunController::currentLine() const {
    if (!m_program || m_program->commands.empty()) return 0;
    const size_t index = std::min(m_program->commandAt(m_timeS), m_program->commands.size() - 1);
    return static_cast<int>(m_program->commands[index].location.line);
}

void TestRunController::tick() {
    const double elapsedS = static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
    m_clock.restart();
    advance(elapsedS);
}

void TestRunController::advance(double wallSeconds) {
    if (m_state != State::Playing || !m_program) return;
    const double total = m_program->machiningTimeS();
    m_timeS = m_speed == TestRunSpeed::Max
                  ? total
                  : std::min(total, m_timeS + wallSeconds * speedFactor(m_speed));
    pushUpTo(m_timeS);
    emit progressChanged(m_timeS);
    publishStatus();
    if (m_timeS >= total) {
        m_timer->stop();
        m_stock->finish();
        // The machine would refuse the next block: the run ends here with that error.
        setState(m_program->refusedAt ? State::Failed : State::Finished);
    }
}

void TestRunController::newStock() {
    m_stock.reset();
    m_pushed = 0;
    if (m_program) {
        m_stock = std::make_unique<graphics::ProgressiveStock>(m_program->stockOptions);
        m_stock->setStart(m_program->start);
        pushUpTo(m_timeS);  // BLK FORM and tool call at time zero: the blank shows at once
    }
    emit stockReplaced(m_stock.get());
}

void TestRunController::pushUpTo(double timeS) {
    if (!m_program || !m_stock) return;
    const size_t reached = m_follower ? m_follower->point().command : m_program->commandAt(timeS);
    const size_t end = std::min(reached, m_program->commands.size());
    if (end <= m_pushed) return;
    std::vector<canon::Command> batch;
    for (size_t i = m_pushed; i < end; ++i) {
        // Following the machine the drives' positions cut (cutTo), not the programmed moves.
        if (m_follower && m_program->isMove(i)) continue;
        batch.push_back(m_program->commands[i]);
    }
    m_stock->push(std::move(batch));
    m_pushed = end;
}

void TestRunController::publishStatus() {
    const TestRunProgram::StatusSnapshot* snapshot =
        !m_program   ? nullptr
        : m_follower ? m_program->statusOfCommand(m_follower->point().command)
                     : m_program->statusAt(m_timeS);
    if (snapshot == nullptr || snapshot == m_shownStatus) return;
    m_shownStatus = snapshot;
    emit programStatusChanged(snapshot->status);
}

void TestRunController::setState(State state) {
    if (state == m_state) return;
    m_state = state;
    emit stateChanged();
}

}  // namespace kerf::ui
