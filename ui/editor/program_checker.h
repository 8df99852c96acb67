#pragma once

#include <QObject>
#include <QString>
#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "core/base/diagnostic.h"
#include "core/machine/machine_config.h"
#include "core/program/dialect.h"
#include "core/task/move_check.h"
#include "core/task/program_sketch.h"

namespace kerf::ui {

// Checks the program being edited in a worker thread and reports its diagnostics back on the
// UI thread. A new request replaces one not started yet; results of an outdated text are
// dropped. Each result names its request: a receiver that swapped its document meanwhile knows
// the result is not about what it shows. Two depths: the static check (task::loadProgram, what
// the editor runs after each pause in typing), and the check that also runs the program dry as
// `kerf check` does (task::checkByRunning: a missing called program, a tool the table lacks, a
// division by zero once the Q parameters have their values ...). A Klartext program with FK
// blocks is also run for the FK solver (task::sketchProgram): its errors join the diagnostics
// and sketched() brings its contour for the programming graphics. A new request cancels a run
// under way.
class ProgramChecker : public QObject {
    Q_OBJECT

public:
    ProgramChecker(machine::MachineConfig machine, std::filesystem::path ncRoot,
                   QObject* parent = nullptr);
    ~ProgramChecker() override;

    enum class Depth { Static, Run };

    // With a work-area check, the check that runs the program also judges every command as
    // Program run would before it moves (soft limits, axes, the planner's rules), with the
    // workpiece origin `origin()` gives when the check is asked for (`kerf check` does the
    // same). Call before the first check.
    void setWorkAreaCheck(task::MoveCheckFactory checkMoves, std::function<Pose()> origin);

    // Returns the request's number (1, 2, ...), which checked() echoes.
    uint64_t check(const QString& text, const std::filesystem::path& path, program::Dialect dialect,
                   Depth depth = Depth::Static);

signals:
    void checked(quint64 request, const kerf::DiagnosticList& diagnostics);
    // Before checked() of the same request.
    void sketched(quint64 request, std::shared_ptr<const kerf::task::ProgramSketch> sketch);

private:
    struct Request {
        QString text;
        std::filesystem::path path;
        program::Dialect dialect = program::Dialect::Klartext;
        Depth depth = Depth::Static;
        uint64_t generation = 0;
        std::optional<Pose> origin;  // Run with a work-area check: the workpiece origin
    };
    void work();
    task::ProgramSketch checkText(std::string text, const Request& request) const;

    machine::MachineConfig m_machine;
    std::filesystem::path m_ncRoot;
    task::MoveCheckFactory m_checkMoves;  // set before the worker reads it
    std::function<Pose()> m_origin;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::optional<Request> m_pending;
    bool m_quit = false;
    std::atomic<bool> m_cancel{false};  // the text changed: the dry run under way is outdated
    uint64_t m_generation = 0;
    std::thread m_worker;
};

}  // namespace kerf::ui
