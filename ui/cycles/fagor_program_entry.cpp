#include "ui/cycles/fagor_program_entry.h"

#include <QPlainTextEdit>
#include <QTextBlock>

#include "ui/cycles/fagor_cycle_dialog.h"
#include "ui/editor/block_numbers.h"

namespace kerf::ui {

namespace {

// "N40 " after the cursor's "N30" line when the next numbered line (if any) is above N40, so
// that labels stay unique and increasing; nothing otherwise.
QString freeNumberAfter(const QTextBlock& block) {
    constexpr auto fagor = program::Dialect::Fagor;
    const QString prefix = nextBlockPrefix(block.text(), block.previous().text(), fagor);
    const auto wanted = readBlockNumber(prefix, fagor);
    if (!wanted) return {};
    for (QTextBlock next = block.next(); next.isValid(); next = next.next()) {
        if (const auto number = readBlockNumber(next.text(), fagor))
            return number->number > wanted->number ? prefix : QString();
    }
    return prefix;
}

}  // namespace

bool defineFagorCycle(QPlainTextEdit& editor, QWidget* dialogParent, int g) {
    if (editor.isReadOnly()) return false;
    FagorCycleDialog dialog(g, dialogParent);
    if (dialog.exec() != QDialog::Accepted) return false;
    QTextCursor cursor = editor.textCursor();
    const QTextBlock block = cursor.block();
    const auto label = readBlockNumber(block.text(), program::Dialect::Fagor);
    const int labelLength = label ? label->length : 0;
    cursor.beginEditBlock();
    if (block.text().mid(labelLength).trimmed().isEmpty()) {
        // An empty line, or one that holds only its label ("N60 ", as the editor numbers a new
        // line): the cycle goes into it, after the label.
        cursor.setPosition(block.position() + labelLength);
        cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
        cursor.insertText((labelLength > 0 ? QStringLiteral(" ") : QString()) + dialog.block());
    } else {
        cursor.movePosition(QTextCursor::EndOfBlock);
        cursor.insertText(QStringLiteral("\n") + freeNumberAfter(block) + dialog.block());
    }
    cursor.endEditBlock();
    cursor.movePosition(QTextCursor::StartOfBlock);
    editor.setTextCursor(cursor);
    return true;
}

bool editFagorCycleAtCursor(QPlainTextEdit& editor, QWidget* dialogParent) {
    if (editor.isReadOnly()) return false;
    const QTextBlock block = editor.textCursor().block();
    const auto found = readFagorCycleLine(block.text());
    if (!found) return false;
    FagorCycleDialog dialog(found->g, dialogParent);
    dialog.setValues(found->values);
    if (dialog.exec() != QDialog::Accepted) return false;
    QTextCursor cursor(block);
    cursor.setPosition(block.position() + found->first);
    cursor.setPosition(block.position() + found->first + found->length, QTextCursor::KeepAnchor);
    cursor.insertText(dialog.block());
    cursor.movePosition(QTextCursor::StartOfBlock);
    editor.setTextCursor(cursor);
    return true;
}

}  // namespace kerf::ui
