#include "ui/editor/program_loader.h"

#include <QFont>
#include <QMetaObject>
#include <QPlainTextDocumentLayout>
#include <QTextBlock>
#include <QTextDocument>
#include <QThread>
#include <utility>

namespace kerf::ui {

namespace {

// Frees the document if it is never handed over (the loader was destroyed before delivery).
struct PendingDocument {
    QTextDocument* document = nullptr;
    ~PendingDocument() { delete document; }
};

}  // namespace

ProgramLoader::ProgramLoader(QObject* parent) : QObject(parent) {}

ProgramLoader::~ProgramLoader() {
    if (m_worker.joinable()) m_worker.join();
}

void ProgramLoader::load(const std::filesystem::path& path, const QFont& font) {
    if (m_worker.joinable()) m_worker.join();
    m_busy = true;
    QThread* uiThread = thread();
    m_worker = std::thread([this, path, uiThread, font] {
        auto file = readProgramFile(path);
        if (!file) {
            QMetaObject::invokeMethod(
                this,
                [this, error = file.error()] {
                    m_busy = false;
                    emit failed(error);
                },
                Qt::QueuedConnection);
            return;
        }
        auto pending = std::make_shared<PendingDocument>();
        pending->document = new QTextDocument;
        // The editor's layout, set before the text so that its per-block bookkeeping is done
        // here too; QPlainTextEdit refuses documents with another layout.
        pending->document->setDocumentLayout(new QPlainTextDocumentLayout(pending->document));
        pending->document->setDefaultFont(font);
        pending->document->setUndoRedoEnabled(false);  // loading is not an edit to undo
        pending->document->setPlainText(file->text);
        pending->document->setUndoRedoEnabled(true);
        // QPlainTextEdit::setDocument() visits every block's layout, creating it if missing:
        // for a million blocks that took the UI thread ~0.4 s. Created here, they are only reset.
        for (QTextBlock block = pending->document->begin(); block.isValid(); block = block.next())
            block.layout();
        pending->document->setModified(false);
        pending->document->moveToThread(uiThread);
        QMetaObject::invokeMethod(
            this,
            [this, pending, format = std::move(*file), path] {
                m_busy = false;
                emit loaded(std::exchange(pending->document, nullptr), format, path);
            },
            Qt::QueuedConnection);
    });
}

}  // namespace kerf::ui
