#pragma once

#include <QObject>
#include <functional>
#include <thread>

#include "core/base/expected.h"

namespace kerf::ui {

// Runs file writes in a worker thread, one at a time and in the order asked, and reports each
// result on the UI thread: encoding and writing a 35 MB program would block the UI for ~0.1 s.
class BackgroundWriter : public QObject {
    Q_OBJECT

public:
    using Job = std::function<MaybeError()>;
    using Done = std::function<void(const MaybeError&)>;

    explicit BackgroundWriter(QObject* parent = nullptr);
    // Waits for the write under way, so that no work is lost when the panel closes.
    ~BackgroundWriter() override;

    // `done` runs on the UI thread afterwards, unless this object is destroyed first.
    void run(Job job, Done done);
    bool busy() const { return m_pending > 0; }

private:
    std::thread m_worker;
    int m_pending = 0;
};

}  // namespace kerf::ui
