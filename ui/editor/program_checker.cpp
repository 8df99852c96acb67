#include "ui/editor/program_checker.h"

#include <QMetaObject>

#include "ui/editor/program_text_check.h"

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

uint64_t ProgramChecker::check(const QString& text, const std::filesystem::path& path,
                               program::Dialect dialect) {
    uint64_t request = 0;
    {
        std::lock_guard lock(m_mutex);
        request = ++m_generation;
        // A shallow copy: the UTF-8 conversion of a large program is done by the worker.
        m_pending = Request{text, path, dialect, request};
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
        }
        DiagnosticList diagnostics = checkText(request.text.toStdString(), request);
        std::lock_guard lock(m_mutex);
        if (request.generation != m_generation || m_quit) continue;  // the text changed meanwhile
        // Queued to the UI thread; dropped by Qt if this object is gone by then.
        QMetaObject::invokeMethod(
            this,
            [this, request = request.generation, diagnostics = std::move(diagnostics)] {
                emit checked(request, diagnostics);
            },
            Qt::QueuedConnection);
    }
}

DiagnosticList ProgramChecker::checkText(const std::string& text, const Request& request) const {
    return checkProgramText(text, request.path.string(), request.dialect, m_machine, m_ncRoot);
}

}  // namespace kerf::ui
