#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>

#include "core/base/diagnostic.h"
#include "core/interp/interpreter.h"
#include "core/task/block_scan.h"
#include "core/task/motion_port.h"

namespace kerf::task {

enum class RunState : uint8_t {
    Idle,
    Running,
    Held,            // feed hold
    Stopped,         // M0/M1, single block or after a quick stop of a still-open program
    WaitingForSync,  // motion drains before the interpreter reads machine data
    Finished,
    Failed,   // diagnostics() says why
    Aborted,  // the operator stopped the program
};

const char* runStateName(RunState state);

struct StartOptions {
    // Start in mid-program: the first block of the main program at or after this line.
    std::optional<uint32_t> startLine;
    Axis toolAxis = Axis::Z;
    size_t readAhead = 4096;  // canonical commands interpreted ahead of motion at most
};

// The program-run sequencer: interprets ahead of motion (bounded), hands commands to motion as it
// has room, drains motion at sync points and answers the interpreter with fresh machine data,
// follows the operator's cycle start / feed hold / stop, and restores the state for a start in
// mid-program. Task thread only; service() is its heartbeat.
class ProgramRun {
public:
    explicit ProgramRun(MotionPort& motion);
    ~ProgramRun();

    // The interpreter has loaded and checked its program.
    void start(std::unique_ptr<interp::Interpreter> interpreter, StartOptions options = {});
    void service();

    void cycleStart();
    void feedHold();
    void abort();

    RunState state() const { return m_state; }
    bool moving() const {
        return m_state == RunState::Running || m_state == RunState::WaitingForSync;
    }
    SourceLocation executingBlock() const { return m_motion.progress().block; }
    const DiagnosticList& diagnostics() const { return m_diagnostics; }
    uint64_t blocksExecuted() const { return m_interpreter ? m_interpreter->blocksExecuted() : 0; }
    // The running program's interpreter (status tabs); nullptr before start and after abort.
    const interp::Interpreter* interpreter() const { return m_interpreter.get(); }

private:
    class Collector;
    void interpretAhead();
    bool submitQueued();
    void fail(std::string code, std::string messageTemplate, std::vector<std::string> args = {},
              std::optional<SourceLocation> at = std::nullopt);

    MotionPort& m_motion;
    std::unique_ptr<interp::Interpreter> m_interpreter;
    std::unique_ptr<Collector> m_collector;
    std::deque<canon::Command> m_queue;
    std::optional<BlockScan> m_scan;
    StartOptions m_options;
    RunState m_state = RunState::Idle;
    interp::RunStatus m_interpreterStatus = interp::RunStatus::BudgetUsed;
    bool m_syncPending = false;
    DiagnosticList m_diagnostics;
};

}  // namespace kerf::task
