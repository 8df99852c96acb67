#include "ui/cycles/program_blocks.h"

#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QTextBlock>
#include <QTextDocument>

#include "ui/cycles/cycle_block.h"
#include "ui/editor/block_numbers.h"

namespace kerf::ui {

namespace {

// Renumbering every following block of a huge program on each insertion would make the dialog
// slow; beyond this the numbers are left for the editor's Renumber blocks.
constexpr int kLiveRenumberLimit = 20000;

std::optional<BlockNumber> numberOf(const QTextBlock& block) {
    return readBlockNumber(block.text(), program::Dialect::Klartext);
}

QString withoutNumber(const QTextBlock& block) {
    const auto number = numberOf(block);
    return number ? block.text().mid(number->length).trimmed() : block.text();
}

// The block number of the last numbered line at or before `line` (-1 if none).
long long numberBefore(const QTextDocument& document, int line) {
    for (QTextBlock b = document.findBlockByNumber(line); b.isValid(); b = b.previous()) {
        if (const auto number = numberOf(b)) return number->number;
    }
    return -1;
}

// Numbers every block from `line` on consecutively after the one before it, inside the cursor's
// current edit block (TNC numbering: one number per block, continuation lines carry none).
void renumberFrom(QTextCursor& edit, int line) {
    QTextDocument& document = *edit.document();
    if (document.blockCount() > kLiveRenumberLimit) return;
    BlockCounter counter(program::Dialect::Klartext, numberBefore(document, line - 1));
    for (QTextBlock b = document.findBlockByNumber(line); b.isValid(); b = b.next()) {
        const auto number = counter.next(b.text());
        if (!number || number->current.number == number->wanted) continue;
        edit.setPosition(b.position());
        edit.setPosition(b.position() + number->current.length, QTextCursor::KeepAnchor);
        edit.insertText(QString::number(number->wanted));
    }
}

QString numbered(const QStringList& blocks, long long first) {
    QStringList lines;
    for (int i = 0; i < blocks.size(); ++i)
        lines << QString::number(first + i) + QLatin1Char(' ') + blocks[i];
    return lines.join(QLatin1Char('\n'));
}

}  // namespace

LineRange blockAt(const QTextDocument& document, int line) {
    QTextBlock block = document.findBlockByNumber(std::max(0, line));
    if (!block.isValid()) block = document.lastBlock();
    while (block.previous().isValid() && !numberOf(block))
        block = block.previous();
    LineRange range{block.blockNumber(), block.blockNumber()};
    for (QTextBlock next = block.next(); next.isValid() && !numberOf(next); next = next.next())
        range.last = next.blockNumber();
    return range;
}

std::optional<LineRange> cycleDefinitionAt(const QTextDocument& document, int line) {
    LineRange range = blockAt(document, line);
    int subBlock = -1;
    const auto number =
        cycleDefNumber(withoutNumber(document.findBlockByNumber(range.first)), &subBlock);
    if (!number) return std::nullopt;
    if (subBlock < 0) return range;
    // Old style: back to the ".0" block, then on over the sub-blocks of the same cycle.
    while (subBlock > 0 && range.first > 0) {
        const LineRange previous = blockAt(document, range.first - 1);
        int previousSub = -1;
        if (cycleDefNumber(withoutNumber(document.findBlockByNumber(previous.first)),
                           &previousSub) != number ||
            previousSub != subBlock - 1) {
            return std::nullopt;
        }
        range.first = previous.first;
        subBlock = previousSub;
    }
    if (subBlock != 0) return std::nullopt;
    for (;;) {
        if (range.last + 1 >= document.blockCount()) break;
        const LineRange next = blockAt(document, range.last + 1);
        int nextSub = -1;
        if (cycleDefNumber(withoutNumber(document.findBlockByNumber(next.first)), &nextSub) !=
                number ||
            nextSub <= 0) {
            break;
        }
        range.last = next.last;
    }
    return range;
}

QStringList blockTexts(const QTextDocument& document, LineRange range) {
    QStringList blocks;
    for (int line = range.first; line <= range.last; ++line) {
        const QTextBlock block = document.findBlockByNumber(line);
        if (numberOf(block) || blocks.isEmpty())
            blocks << withoutNumber(block);
        else
            blocks.last() += QLatin1Char('\n') + block.text();
    }
    return blocks;
}

bool programIsInch(const QTextDocument& document) {
    static const QRegularExpression begin(QStringLiteral(R"(BEGIN\s+PGM\s+\S+\s+INCH\b)"),
                                          QRegularExpression::CaseInsensitiveOption);
    for (QTextBlock b = document.begin(); b.isValid() && b.blockNumber() < 50; b = b.next()) {
        if (b.text().contains(QLatin1String("BEGIN"), Qt::CaseInsensitive))
            return begin.match(b.text()).hasMatch();
    }
    return false;
}

void insertBlocks(QPlainTextEdit& editor, const QStringList& blocks) {
    QTextDocument& document = *editor.document();
    const int cursorLine = editor.textCursor().blockNumber();
    const LineRange at = blockAt(document, cursorLine);
    const bool beforeEnd =
        withoutNumber(document.findBlockByNumber(at.first)).startsWith(QLatin1String("END PGM"));
    const bool empty = document.characterCount() <= 1;
    QTextCursor edit(&document);
    edit.beginEditBlock();
    int firstLine = 0;
    if (empty) {
        edit.insertText(numbered(blocks, 0));
    } else if (beforeEnd) {
        firstLine = at.first;
        edit.setPosition(document.findBlockByNumber(at.first).position());
        edit.insertText(numbered(blocks, numberBefore(document, at.first - 1) + 1) +
                        QLatin1Char('\n'));
    } else {
        firstLine = at.last + 1;
        const QTextBlock last = document.findBlockByNumber(at.last);
        edit.setPosition(last.position() + last.length() - 1);
        edit.insertText(QLatin1Char('\n') + numbered(blocks, numberBefore(document, at.last) + 1));
    }
    renumberFrom(edit, firstLine);
    edit.endEditBlock();
    QTextCursor cursor(document.findBlockByNumber(firstLine));
    editor.setTextCursor(cursor);
}

void replaceBlocks(QPlainTextEdit& editor, LineRange range, const QStringList& blocks) {
    QTextDocument& document = *editor.document();
    const auto first = numberOf(document.findBlockByNumber(range.first));
    const long long number = first ? first->number : numberBefore(document, range.first) + 1;
    const QTextBlock last = document.findBlockByNumber(range.last);
    QTextCursor edit(&document);
    edit.beginEditBlock();
    edit.setPosition(document.findBlockByNumber(range.first).position());
    edit.setPosition(last.position() + last.length() - 1, QTextCursor::KeepAnchor);
    edit.insertText(numbered(blocks, number));
    renumberFrom(edit, range.first);
    edit.endEditBlock();
    editor.setTextCursor(QTextCursor(document.findBlockByNumber(range.first)));
}

}  // namespace kerf::ui
