#pragma once

#include <QObject>
#include <QPointer>
#include <QTextCursor>

#include "core/program/dialect.h"
#include "ui/editor/block_numbers.h"
#include "ui/editor/label_references.h"

class QTextBlock;
class QTextDocument;

namespace kerf::ui {

// Replaces the number at the start of `block` (its first `current.length` characters).
void writeBlockNumber(QTextCursor& edit, const QTextBlock& block, const BlockNumber& current,
                      long long number, program::Dialect dialect);

// Renumbers a long program in slices of a few milliseconds between events, so that the UI stays
// responsive (a million blocks take seconds). Only the numbers that change are replaced, and all
// slices form one edit block: undo restores the old numbers in one step. The document must not be
// edited otherwise until finished() (the editor is read-only meanwhile). In FAGOR programs the
// references to the renumbered labels follow them at the end, in the same edit block.
class RenumberJob : public QObject {
    Q_OBJECT

public:
    RenumberJob(QTextDocument* document, program::Dialect dialect, BlockNumbering numbering = {},
                QObject* parent = nullptr);

    // Runs the first slice at once and the others from the event loop.
    void start();
    // Stops between slices; the numbers changed so far stay changed (one undo step).
    void cancel();
    bool running() const { return m_running; }
    // How long one slice may run; 0 means one check interval (used by tests to force many slices).
    void setSliceMs(int ms) { m_sliceMs = ms; }

signals:
    // `changed`: some number was rewritten.
    void finished(bool changed);

private:
    void runSlice();

    QPointer<QTextDocument> m_document;
    QTextCursor m_edit;
    BlockCounter m_counter;
    int m_nextBlock = 0;  // block number to continue from
    int m_sliceMs = 40;
    bool m_changed = false;
    bool m_running = false;
    RenamedLabels m_renamed;  // FAGOR: old label -> new label
};

}  // namespace kerf::ui
