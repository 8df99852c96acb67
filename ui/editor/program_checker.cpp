#include "ui/editor/program_checker.h"

#include <QMetaObject>

#include "core/task/dry_run.h"

namespace kerf::ui {

ProgramChecker::ProgramChecker(machine::MachineConfig machine, std::filesystem::path ncRoot,
                               QObject* parent)
    : QObject(parent), m_machine(std::move(machine)), m_ncRoot(std::move(ncRoot)) {
    m_worker = std::thread([this] { work(); });
}

ProgramChecker::~ProgramChecker() {
    {
        std::lock_guard lock(m_mutex);
        m_quit = true;
        m_pending.reset();
    }
    m_wake.notify_one();
    m_worker.join();
}

void ProgramChecker::setWorkAreaCheck(task::MoveCheckFactory checkMoves,
                                      std::function<Pose()> origin) {
    std::lock_guard lock(m_mutex);
    m_checkMoves = std::move(checkMoves);
    m_origin = std::move(origin);
}

uint64_t ProgramChecker::check(const QString& text, const std::filesystem::path& path,
                               program::Dialect dialect, Depth depth) {
    uint64_t request = 0;
    std::optional<Pose> origin;
    if (depth == Depth::Run && m_checkMoves && m_origin) origin = m_origin();
    {
        std::lock_guard lock(m_mutex);
        request = ++m_generation;
        // A shallow copy: the UTF-8 conversion of a large program is done by the worker.
        m_pending = Request{text, path, dialect, depth, request, origin};
        m_cancel.store(true);
    }
    m_wake.notify_one();
    return request;
}

void ProgramChecker::work() {
    for (;;) {
        Request request;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [this] { return m_quit || m_pending.has_value(); });
            if (m_quit) return;
            request = std::move(*m_pending);
            m_pending.reset();
            m_cancel.store(false);
        }
        auto sketch =
            std::make_shared<task::ProgramSketch>(checkText(request.text.toStdString(), request));
        std::lock_guard lock(m_mutex);
        if (request.generation != m_generation || m_quit) continue;  // the text changed meanwhile
        // Queued to the UI thread; dropped by Qt if this object is gone by then.
        QMetaObject::invokeMethod(
            this,
            [this, request = request.generation,
             sketch = std::shared_ptr<const task::ProgramSketch>(std::move(sketch))] {
                emit sketched(request, sketch);
                emit checked(request, sketch->diagnostics);
            },
            Qt::QueuedConnection);
    }
}

task::ProgramSketch ProgramChecker::checkText(std::string text, const Request& request) const {
    task::ProgramRequest load;
    load.text = std::move(text);
    load.path = request.path;
    load.dialect = request.dialect;
    load.ncRoot = m_ncRoot;
    task::ProgramSketch sketch = task::sketchProgram(m_machine, load, &m_cancel);
    if (request.depth == Depth::Static || sketch.cancelled || hasErrors(sketch.diagnostics))
        return sketch;
    task::DryRunOptions dry;
    dry.cancel = &m_cancel;
    std::unique_ptr<task::MoveCheck> moves;
    if (request.origin) {
        moves = m_checkMoves(*request.origin);
        dry.moves = moves.get();
    }
    task::RunCheck run = task::checkByRunning(m_machine, std::move(load), dry);
    sketch.cancelled = run.cancelled;
    sketch.diagnostics = std::move(run.diagnostics);
    return sketch;
}

}  // namespace kerf::ui
