#include "core/task/program_run.h"

#include "core/base/translate.h"

namespace kerf::task {

const char* runStateName(RunState state) {
    switch (state) {
        case RunState::Idle:
            return KERF_TR_NOOP("idle");
        case RunState::Running:
            return KERF_TR_NOOP("running");
        case RunState::Held:
            return KERF_TR_NOOP("feed hold");
        case RunState::Stopped:
            return KERF_TR_NOOP("stopped");
        case RunState::WaitingForSync:
            return KERF_TR_NOOP("waiting for the machine");
        case RunState::Finished:
            return KERF_TR_NOOP("finished");
        case RunState::Failed:
            return KERF_TR_NOOP("error");
        case RunState::Aborted:
            return KERF_TR_NOOP("aborted");
    }
    return "";
}

// Receives the interpreter's commands: swallows those of a block scan, queues the rest.
class ProgramRun::Collector final : public canon::Sink {
public:
    explicit Collector(ProgramRun& run) : m_run(run) {}
    void consume(const canon::Command& command) override {
        if (m_run.m_scan && !m_run.m_scan->reached()) {
            if (!m_run.m_scan->consume(command)) return;
            for (canon::Command& c :
                 m_run.m_scan->restore(m_run.m_motion.world().position, m_run.m_options.toolAxis)) {
                m_run.m_queue.push_back(std::move(c));
            }
        }
        m_run.m_queue.push_back(command);
    }

private:
    ProgramRun& m_run;
};

ProgramRun::ProgramRun(MotionPort& motion) : m_motion(motion) {}

ProgramRun::~ProgramRun() = default;

void ProgramRun::start(std::unique_ptr<interp::Interpreter> interpreter, StartOptions options) {
    m_interpreter = std::move(interpreter);
    m_options = options;
    m_collector = std::make_unique<Collector>(*this);
    m_queue.clear();
    m_diagnostics.clear();
    m_syncPending = false;
    m_interpreterStatus = interp::RunStatus::BudgetUsed;
    m_scan.reset();
    if (options.startLine) m_scan.emplace(0, *options.startLine);
    m_state = RunState::Running;
}

void ProgramRun::fail(std::string code, std::string messageTemplate, std::vector<std::string> args,
                      std::optional<SourceLocation> at) {
    Diagnostic d;
    d.code = std::move(code);
    d.messageTemplate = std::move(messageTemplate);
    d.args = std::move(args);
    const SourceLocation where = at.value_or(m_motion.progress().block);
    d.line = where.line;
    d.column = where.column;
    m_diagnostics.push_back(std::move(d));
    m_state = RunState::Failed;
}

bool ProgramRun::submitQueued() {
    while (!m_queue.empty() && m_motion.hasRoom()) {
        if (!m_motion.submit(m_queue.front())) {
            // The message names the refused block, not the one motion is executing.
            const SourceLocation refused = m_queue.front().location;
            m_motion.quickStop();
            m_queue.clear();
            fail("motion", KERF_TR_NOOP("motion refused the block: {1}"),
                 {m_motion.progress().fault}, refused);
            return false;
        }
        m_queue.pop_front();
    }
    return m_queue.empty();
}

void ProgramRun::interpretAhead() {
    while (m_interpreterStatus == interp::RunStatus::BudgetUsed && !m_syncPending &&
           m_queue.size() < m_options.readAhead) {
        m_interpreterStatus = m_interpreter->run(*m_collector, 256);
        if (m_interpreterStatus == interp::RunStatus::NeedsSync) {
            m_syncPending = true;
            m_interpreterStatus = interp::RunStatus::BudgetUsed;
        }
    }
}

void ProgramRun::service() {
    m_motion.pump();
    const bool active = m_state == RunState::Running || m_state == RunState::Held ||
                        m_state == RunState::Stopped || m_state == RunState::WaitingForSync;
    if (!m_interpreter || !active) return;
    const MotionPort::Progress progress = m_motion.progress();
    if (progress.state == MotionPort::State::Faulted) {
        m_queue.clear();
        fail("motion", KERF_TR_NOOP("motion stopped: {1}"), {progress.fault});
        return;
    }
    if (m_interpreter->checkFailed()) {
        m_motion.quickStop();
        m_queue.clear();
        m_diagnostics = m_interpreter->diagnostics();
        m_state = RunState::Failed;
        return;
    }
    // The operator's stops are motion's state; the sequencer mirrors them.
    if (progress.state == MotionPort::State::Held) {
        m_state = RunState::Held;
    } else if (progress.state == MotionPort::State::Stopped) {
        m_state = RunState::Stopped;
    } else {
        m_state = RunState::Running;
    }
    if (m_syncPending) {
        if (!submitQueued()) return;
        m_motion.flush();
        if (!m_motion.drained()) {
            if (m_state == RunState::Running) m_state = RunState::WaitingForSync;
            return;
        }
        interp::WorldSnapshot world = m_motion.world();
        if (m_scan && !m_scan->reached()) world.position = m_scan->position();
        m_interpreter->resume(world);
        m_syncPending = false;
    }
    if (!submitQueued()) return;
    interpretAhead();
    if (!submitQueued()) return;
    if (m_interpreterStatus == interp::RunStatus::Finished ||
        m_interpreterStatus == interp::RunStatus::Failed) {
        // Everything interpreted: finish when motion has executed it.
        m_motion.flush();
        if (!m_motion.drained()) return;
        if (m_interpreterStatus == interp::RunStatus::Failed) {
            m_diagnostics = m_interpreter->diagnostics();
            m_state = RunState::Failed;
        } else {
            m_state = RunState::Finished;
        }
    }
}

void ProgramRun::cycleStart() {
    if (m_state == RunState::Held || m_state == RunState::Stopped) {
        m_motion.cycleStart();
        m_state = RunState::Running;
    }
}

void ProgramRun::feedHold() {
    if (moving()) {
        m_motion.feedHold();
        m_state = RunState::Held;
    }
}

void ProgramRun::abort() {
    if (m_state == RunState::Idle || m_state == RunState::Finished) return;
    m_motion.quickStop();
    m_queue.clear();
    m_interpreter.reset();
    m_state = RunState::Aborted;
}

}  // namespace kerf::task
