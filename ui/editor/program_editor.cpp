#include "ui/editor/program_editor.h"

#include <QFontDatabase>
#include <QKeyEvent>
#include <QTextBlock>
#include <QTextCursor>
#include <limits>

#include "ui/common/diagnostic_text.h"
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
    const QTextBlock block = cursor.block();
    const QString prefix = nextBlockPrefix(block.text(), block.previous().text(), dialect());
    cursor.beginEditBlock();
    cursor.insertText(QStringLiteral("\n") + prefix);
    cursor.endEditBlock();
    setTextCursor(cursor);
    if (prefix.isEmpty()) return;
    if (document()->blockCount() <= kLiveRenumberLimit) {
        // The following blocks move down by one: renumber them in the same undo step.
        QTextCursor edit(document());
        edit.joinPreviousEditBlock();
        const long long inserted =
            readBlockNumber(cursor.block().text(), dialect()).value_or(BlockNumber{}).number;
        BlockCounter counter(dialect(), inserted);
        RenamedLabels renamed;
        for (QTextBlock next = cursor.block().next(); next.isValid(); next = next.next()) {
            const long long previous = counter.last();
            const auto numbered = counter.next(next.text());
            if (!numbered) continue;
            // ISO numbers only need to keep ascending.
            if (dialect() != program::Dialect::Klartext && numbered->current.number > previous)
                break;
            if (numbered->current.number == numbered->wanted) continue;
            writeBlockNumber(edit, next, numbered->current, numbered->wanted, dialect());
            renamed.emplace(numbered->current.number, numbered->wanted);
        }
        // FAGOR block numbers are labels: what jumps to them or names them follows them.
        if (dialect() == program::Dialect::Fagor) renameLabelReferences(*document(), edit, renamed);
        edit.endEditBlock();
    } else {
        m_numbersStale = true;
    }
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
