#include "ui/editor/background_writer.h"

#include <QMetaObject>
#include <utility>

namespace kerf::ui {

BackgroundWriter::BackgroundWriter(QObject* parent) : QObject(parent) {}

BackgroundWriter::~BackgroundWriter() {
    if (m_worker.joinable()) m_worker.join();
}

void BackgroundWriter::run(Job job, Done done) {
    // One worker at a time keeps the writes in order (an autosave copy never lands after the
    // save that removed it).
    if (m_worker.joinable()) m_worker.join();
    ++m_pending;
    m_worker = std::thread([this, job = std::move(job), done = std::move(done)] {
        const MaybeError result = job();
        QMetaObject::invokeMethod(
            this,
            [this, done, result] {
                --m_pending;
                done(result);
            },
            Qt::QueuedConnection);
    });
}

}  // namespace kerf::ui
