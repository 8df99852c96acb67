#pragma once

#include <QObject>
#include <filesystem>
#include <memory>
#include <thread>

#include "core/base/diagnostic.h"
#include "ui/editor/program_file.h"

class QFont;
class QTextDocument;

namespace kerf::ui {

// Reads a program and builds its QTextDocument in a worker thread: for a million-block program
// that takes seconds, during which the panel stays responsive. The finished document is moved
// to the UI thread and handed over by loaded(); the receiver takes ownership.
class ProgramLoader : public QObject {
    Q_OBJECT

public:
    explicit ProgramLoader(QObject* parent = nullptr);
    ~ProgramLoader() override;

    // One load at a time; a new one waits for the previous to finish. The document is laid out
    // in `font`, the editor's (a document's own default is the application's smaller font).
    void load(const std::filesystem::path& path, const QFont& font);
    bool busy() const { return m_busy; }

signals:
    // The ProgramText still holds the text as read (for the first check); the receiver drops it
    // once done, as the document holds the text.
    void loaded(QTextDocument* document, const kerf::ui::ProgramText& format,
                const std::filesystem::path& path);
    void failed(const kerf::Diagnostic& error);

private:
    std::thread m_worker;
    bool m_busy = false;
};

}  // namespace kerf::ui
