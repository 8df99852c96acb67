#include "ui/editor/renumber_job.h"

#include <QElapsedTimer>
#include <QTextBlock>
#include <QTextDocument>
#include <QTimer>

namespace kerf::ui {

namespace {

// Blocks handled between two looks at the clock.
constexpr int kBlocksPerCheck = 1000;

}  // namespace

void writeBlockNumber(QTextCursor& edit, const QTextBlock& block, const BlockNumber& current,
                      long long number, program::Dialect dialect) {
    edit.setPosition(block.position());
    edit.setPosition(block.position() + current.length, QTextCursor::KeepAnchor);
    edit.insertText(dialect == program::Dialect::Klartext ? QString::number(number)
                                                          : QStringLiteral("N%1").arg(number));
}

RenumberJob::RenumberJob(QTextDocument* document, program::Dialect dialect,
                         BlockNumbering numbering, QObject* parent)
    : QObject(parent), m_document(document), m_edit(document), m_counter(dialect, -1, numbering) {}

void RenumberJob::start() {
    m_running = true;
    runSlice();
}

void RenumberJob::cancel() {
    m_running = false;
}

void RenumberJob::runSlice() {
    if (!m_running) return;
    if (!m_document) {
        m_running = false;
        emit finished(m_changed);
        return;
    }
    QElapsedTimer clock;
    clock.start();
    const program::Dialect dialect = m_counter.dialect();
    bool editing = false;
    QTextBlock block = m_document->findBlockByNumber(m_nextBlock);
    while (block.isValid()) {
        for (int i = 0; i < kBlocksPerCheck && block.isValid(); ++i, block = block.next()) {
            const auto numbered = m_counter.next(block.text());
            if (!numbered || numbered->current.number == numbered->wanted) continue;
            if (!editing) {
                // The first change opens the edit block; later slices rejoin it.
                if (m_changed) {
                    m_edit.joinPreviousEditBlock();
                } else {
                    m_edit.beginEditBlock();
                }
                editing = true;
                m_changed = true;
            }
            writeBlockNumber(m_edit, block, numbered->current, numbered->wanted, dialect);
            if (dialect == program::Dialect::Fagor)
                m_renamed.emplace(numbered->current.number, numbered->wanted);
        }
        if (clock.elapsed() >= m_sliceMs) break;
    }
    if (block.isValid()) {
        if (editing) m_edit.endEditBlock();
        m_nextBlock = block.blockNumber();
        QTimer::singleShot(0, this, &RenumberJob::runSlice);
        return;
    }
    if (!m_renamed.empty()) {
        if (!editing) m_edit.joinPreviousEditBlock();
        renameLabelReferences(*m_document, m_edit, m_renamed);
        editing = true;
    }
    if (editing) m_edit.endEditBlock();
    m_running = false;
    emit finished(m_changed);
}

}  // namespace kerf::ui
