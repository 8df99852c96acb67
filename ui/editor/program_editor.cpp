#include "ui/editor/program_editor.h"

#include <QFontDatabase>
#include <QKeyEvent>
#include <QTextBlock>
#include <QTextCursor>

#include "ui/common/diagnostic_text.h"
#include "ui/editor/block_numbers.h"
#include "ui/editor/visible_highlighter.h"

namespace kerf::ui {

namespace {

constexpr int kMaxUnderlinedLines = 2000;

// The numbers renumber() gives: Klartext the line index; ISO the first number, then steps of 10.
QString renumberedText(const QTextDocument& document, program::Dialect dialect, bool* changed) {
    QString text;
    text.reserve(document.characterCount());
    long long isoNumber = -1;
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        const QString line = block.text();
        long long wanted = block.blockNumber();
        if (dialect != program::Dialect::Klartext) {
            if (const auto current = readBlockNumber(line, dialect)) {
                isoNumber = isoNumber < 0 ? current->number : isoNumber + 10;
            }
            wanted = isoNumber;
        }
        const auto current = readBlockNumber(line, dialect);
        if (current && current->number != wanted) {
            *changed = true;
            text += withBlockNumber(line, wanted, dialect);
        } else {
            text += line;
        }
        if (block.next().isValid()) text += QLatin1Char('\n');
    }
    return text;
}

}  // namespace

ProgramEditor::ProgramEditor(QWidget* parent) : QPlainTextEdit(parent) {
    setObjectName("programEditor");
    setLineWrapMode(QPlainTextEdit::NoWrap);
    QFont font = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    font.setPointSize(13);
    setFont(font);
    m_highlighter = new VisibleHighlighter(this);
}

void ProgramEditor::adoptDocument(QTextDocument* document) {
    // The previous document is a child of the editor, so setDocument() deletes it.
    setDocument(document);
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
        long long isoNumber =
            readBlockNumber(cursor.block().text(), dialect()).value_or(BlockNumber{}).number;
        for (QTextBlock next = cursor.block().next(); next.isValid(); next = next.next()) {
            const auto current = readBlockNumber(next.text(), dialect());
            if (!current) continue;
            long long wanted = next.blockNumber();
            if (dialect() != program::Dialect::Klartext) {
                if (current->number > isoNumber) break;  // ISO numbers only need to keep ascending
                isoNumber += 10;
                wanted = isoNumber;
            }
            if (current->number == wanted) continue;
            edit.setPosition(next.position());
            edit.setPosition(next.position() + current->length, QTextCursor::KeepAnchor);
            edit.insertText(withBlockNumber(next.text().left(current->length), wanted, dialect()));
        }
        edit.endEditBlock();
    } else {
        m_numbersStale = true;
    }
}

bool ProgramEditor::renumber() {
    bool changed = false;
    const QString text = renumberedText(*document(), dialect(), &changed);
    m_numbersStale = false;
    if (!changed) return false;
    const int line = currentLine();
    QTextCursor cursor(document());
    cursor.select(QTextCursor::Document);
    cursor.insertText(text);
    goToLine(line);
    return true;
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
