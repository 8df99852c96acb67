#include "ui/editor/program_editor.h"

#include <QFontDatabase>
#include <QKeyEvent>
#include <QTextBlock>
#include <QTextCursor>
#include <limits>

#include "ui/common/diagnostic_text.h"
#include "ui/editor/block_insertion.h"
#include "ui/editor/block_numbers.h"
#include "ui/editor/label_references.h"
#include "ui/editor/renumber_job.h"
#include "ui/editor/visible_highlighter.h"

namespace kerf::ui {

namespace {

constexpr int kMaxUnderlinedLines = 2000;

}  // namespace

ProgramEditor::ProgramEditor(QWidget* parent) : QPlainTextEdit(parent) {
    setObjectName("programEditor");
    setLineWrapMode(QPlainTextEdit::NoWrap);
    // A scroll bar that comes and goes changes the text width, and QPlainTextEdit then visits all
    // blocks again (~0.1 s on a million blocks, just after a large program is shown).
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOn);
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPointSize(13);
    setFont(font);
    m_highlighter = new VisibleHighlighter(this);
}

void ProgramEditor::adoptDocument(QTextDocument* document) {
    if (m_renumberJob) {
        // The numbers belong to the document being replaced: stop, without a renumbered().
        m_renumberJob->disconnect(this);
        m_renumberJob->cancel();
        m_renumberJob->deleteLater();
        m_renumberJob = nullptr;
        setReadOnly(m_readOnlyBeforeRenumber);
    }
    // setDocument() deletes only the editor's first document (a child of its text control); an
    // adopted one is deleted here, later, in an event of its own (a million blocks take ~0.1 s).
    // Not in another thread: cursors and selections of the editor still point into it.
    QTextDocument* previous = this->document();
    const bool adoptedBefore = previous->parent() == this;
    // Underlines and marks are cursors into the document being replaced: QPlainTextEdit keeps
    // them across setDocument() and would later measure them against the new one.
    setExtraSelections({});
    // The editor's font, as for a program typed or opened here (ProgramLoader lays the document
    // out in it already; setting it again would lay out every block once more).
    if (document->defaultFont() != font()) document->setDefaultFont(font());
    setDocument(document);
    if (adoptedBefore) previous->deleteLater();
    document->setParent(this);
    m_highlighter->watch(document);
    m_numbersStale = false;
}

void ProgramEditor::setDialect(program::Dialect dialect) {
    m_highlighter->setDialect(dialect);
}

program::Dialect ProgramEditor::dialect() const {
    return m_highlighter->dialect();
}

void ProgramEditor::keyPressEvent(QKeyEvent* event) {
    const bool enter = event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter;
    if (enter && !isReadOnly()) {
        // Shift+Enter: a line without a number. (QPlainTextEdit's own Shift+Enter would insert
        // U+2028, which no control reads.)
        if (event->modifiers() & Qt::ShiftModifier) {
            insertPlainText(QStringLiteral("\n"));
        } else {
            insertBlock();
        }
        return;
    }
    QPlainTextEdit::keyPressEvent(event);
}

void ProgramEditor::insertBlock() {
    if (renumbering()) return;
    QTextCursor cursor = textCursor();
    const bool live = document()->blockCount() <= kLiveRenumberLimit;
    const BlockInsertion plan = planBlockInsertion(*document(), cursor, dialect(), live);
    cursor.beginEditBlock();
    if (plan.before) {
        cursor.movePosition(QTextCursor::StartOfBlock);
        cursor.insertText(plan.prefix + QStringLiteral("\n"));
        cursor.movePosition(QTextCursor::PreviousBlock);
        cursor.movePosition(QTextCursor::EndOfBlock);
    } else {
        cursor.insertText(QStringLiteral("\n") + plan.prefix);
    }
    cursor.endEditBlock();
    setTextCursor(cursor);
    if (plan.problem) emit labelsKept(*plan.problem);
    if (plan.prefix.isEmpty()) return;
    if (!live) {
        m_numbersStale = true;
        return;
    }
    // The following blocks move down by one: renumber them in the same undo step.
    QTextCursor edit(document());
    edit.joinPreviousEditBlock();
    for (const BlockInsertion::Move& move : plan.moves)
        writeBlockNumber(edit, document()->findBlockByNumber(move.line + 1), move.current,
                         move.wanted, dialect());
    // FAGOR block numbers are labels: what jumps to them or names them follows them.
    renameLabelReferences(*document(), edit, plan.renamed);
    edit.endEditBlock();
}

std::optional<RenumberProblem> ProgramEditor::renumber(BlockNumbering numbering) {
    if (renumbering()) return std::nullopt;
    if (dialect() == program::Dialect::Fagor) {
        if (auto problem = fagorRenumberProblem(*document(), numbering)) {
            emit renumbered(false);
            return problem;
        }
    }
    if (document()->blockCount() <= kLiveRenumberLimit) {
        emit renumbered(renumberNow(numbering));
        return std::nullopt;
    }
    m_numbersStale = false;
    m_readOnlyBeforeRenumber = isReadOnly();
    setReadOnly(true);  // the slices form one undo step only if nothing else edits in between
    m_renumberJob = new RenumberJob(document(), dialect(), numbering, this);
    connect(m_renumberJob, &RenumberJob::finished, this, [this](bool changed) {
        m_renumberJob->deleteLater();
        m_renumberJob = nullptr;
        setReadOnly(m_readOnlyBeforeRenumber);
        emit renumbered(changed);
    });
    m_renumberJob->start();
    return std::nullopt;
}

bool ProgramEditor::renumberNow(BlockNumbering numbering) {
    m_numbersStale = false;
    bool changed = false;
    RenumberJob job(document(), dialect(), numbering);
    job.setSliceMs(std::numeric_limits<int>::max());
    connect(&job, &RenumberJob::finished, this, [&changed](bool result) { changed = result; });
    job.start();
    return changed;
}

bool ProgramEditor::renumbering() const {
    return m_renumberJob != nullptr;
}

void ProgramEditor::goToLine(int line) {
    const QTextBlock block = document()->findBlockByNumber(std::max(0, line - 1));
    if (!block.isValid()) return;
    QTextCursor cursor(block);
    setTextCursor(cursor);
    centerCursor();
    setFocus();
}

int ProgramEditor::currentLine() const {
    return textCursor().blockNumber() + 1;
}

void ProgramEditor::setDiagnostics(const DiagnosticList& diagnostics) {
    QList<QTextEdit::ExtraSelection> selections;
    for (const Diagnostic& d : diagnostics) {
        if (selections.size() >= kMaxUnderlinedLines) break;
        const QTextBlock block = document()->findBlockByNumber(static_cast<int>(d.line) - 1);
        if (d.line == 0 || !block.isValid()) continue;
        QTextEdit::ExtraSelection selection;
        selection.cursor = QTextCursor(block);
        selection.cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
        selection.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
        selection.format.setUnderlineColor(
            d.severity == Severity::Error ? Qt::red : QColor(0xd0, 0x80, 0x00));
        selection.format.setToolTip(translatedMessage(d));
        selections.append(selection);
    }
    setExtraSelections(selections);
}

}  // namespace kerf::ui
