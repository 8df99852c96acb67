#include "ui/cycles/program_blocks.h"

#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QTextBlock>
#include <QTextDocument>

#include "ui/cycles/cycle_block.h"
#include "ui/cycles/iso_blocks.h"
#include "ui/editor/block_numbers.h"

namespace kerf::ui {

namespace {

// Renumbering every following block of a huge program on each insertion would make the dialog
// slow; beyond this the numbers are left for the editor's Renumber blocks.
constexpr int kLiveRenumberLimit = 20000;

// ISO programs end with "N99999999 %NAME G71 *": that number is never changed.
constexpr long long kIsoEndNumber = 99999999;

std::optional<BlockNumber> numberOf(const QTextBlock& block, program::Dialect dialect) {
    return readBlockNumber(block.text(), dialect);
}

QString withoutNumber(const QTextBlock& block, program::Dialect dialect) {
    const auto number = numberOf(block, dialect);
    return number ? block.text().mid(number->length).trimmed() : block.text();
}

// The block number of the last numbered line at or before `line` (-1 if none).
long long numberBefore(const QTextDocument& document, int line, program::Dialect dialect) {
    for (QTextBlock b = document.findBlockByNumber(line); b.isValid(); b = b.previous()) {
        if (const auto number = numberOf(b, dialect)) return number->number;
    }
    return -1;
}

// An ISO program's numbering step: the spacing of the two numbered blocks before `line`, else 1.
long long isoStep(const QTextDocument& document, int line) {
    std::optional<long long> later;
    for (QTextBlock b = document.findBlockByNumber(line); b.isValid(); b = b.previous()) {
        const auto number = numberOf(b, program::Dialect::TncIso);
        if (!number || number->number == kIsoEndNumber) continue;
        if (!later) {
            later = number->number;
            continue;
        }
        return *later > number->number ? *later - number->number : 1;
    }
    return 1;
}

// Numbers every block from `line` on consecutively after the one before it, inside the cursor's
// current edit block (TNC numbering: one number per block, continuation lines carry none).
void renumberFrom(QTextCursor& edit, int line, program::Dialect dialect) {
    QTextDocument& document = *edit.document();
    if (document.blockCount() > kLiveRenumberLimit) return;
    if (dialect == program::Dialect::TncIso) {
        // Only what the insertion made collide moves up, by the program's step; numbers that
        // already increase, and the end block's, stay.
        long long previous = numberBefore(document, line - 1, dialect);
        const long long step = isoStep(document, line - 1);
        for (QTextBlock b = document.findBlockByNumber(line); b.isValid(); b = b.next()) {
            const auto number = numberOf(b, dialect);
            if (!number) continue;
            if (number->number == kIsoEndNumber || number->number > previous) break;
            previous += step;
            edit.setPosition(b.position() + 1);
            edit.setPosition(b.position() + number->length, QTextCursor::KeepAnchor);
            edit.insertText(QString::number(previous));
        }
        return;
    }
    BlockCounter counter(dialect, numberBefore(document, line - 1, dialect));
    for (QTextBlock b = document.findBlockByNumber(line); b.isValid(); b = b.next()) {
        const auto number = counter.next(b.text());
        if (!number || number->current.number == number->wanted) continue;
        edit.setPosition(b.position());
        edit.setPosition(b.position() + number->current.length, QTextCursor::KeepAnchor);
        edit.insertText(QString::number(number->wanted));
    }
}

QString numbered(const QStringList& blocks, long long first, long long step,
                 program::Dialect dialect) {
    QStringList lines;
    for (int i = 0; i < blocks.size(); ++i) {
        const QString number = QString::number(first + i * step);
        lines << (dialect == program::Dialect::TncIso
                      ? QLatin1Char('N') + number + QLatin1Char(' ') + blocks[i] +
                            QStringLiteral(" *")
                      : number + QLatin1Char(' ') + blocks[i]);
    }
    return lines.join(QLatin1Char('\n'));
}

long long stepOf(const QTextDocument& document, int line, program::Dialect dialect) {
    return dialect == program::Dialect::TncIso ? isoStep(document, line) : 1;
}

bool isEndBlock(const QString& text, program::Dialect dialect) {
    if (dialect == program::Dialect::TncIso) return text.startsWith(QLatin1Char('%'));
    return text.startsWith(QLatin1String("END PGM"));
}

}  // namespace

LineRange blockAt(const QTextDocument& document, int line, program::Dialect dialect) {
    QTextBlock block = document.findBlockByNumber(std::max(0, line));
    if (!block.isValid()) block = document.lastBlock();
    while (block.previous().isValid() && !numberOf(block, dialect))
        block = block.previous();
    LineRange range{block.blockNumber(), block.blockNumber()};
    for (QTextBlock next = block.next(); next.isValid() && !numberOf(next, dialect);
         next = next.next())
        range.last = next.blockNumber();
    return range;
}

std::optional<LineRange> cycleDefinitionAt(const QTextDocument& document, int line,
                                           program::Dialect dialect) {
    LineRange range = blockAt(document, line, dialect);
    const auto headerOf = [&](int first) {
        const QString text = withoutNumber(document.findBlockByNumber(first), dialect);
        return dialect == program::Dialect::TncIso ? klartextCycleBlocks(text).value(0) : text;
    };
    int subBlock = -1;
    const auto number = cycleDefNumber(headerOf(range.first), &subBlock);
    if (!number) return std::nullopt;
    if (subBlock < 0) return range;
    // Old style: back to the ".0" block, then on over the sub-blocks of the same cycle.
    while (subBlock > 0 && range.first > 0) {
        const LineRange previous = blockAt(document, range.first - 1, dialect);
        int previousSub = -1;
        if (cycleDefNumber(headerOf(previous.first), &previousSub) != number ||
            previousSub != subBlock - 1) {
            return std::nullopt;
        }
        range.first = previous.first;
        subBlock = previousSub;
    }
    if (subBlock != 0) return std::nullopt;
    for (;;) {
        if (range.last + 1 >= document.blockCount()) break;
        const LineRange next = blockAt(document, range.last + 1, dialect);
        int nextSub = -1;
        if (cycleDefNumber(headerOf(next.first), &nextSub) != number || nextSub <= 0) break;
        range.last = next.last;
    }
    return range;
}

QStringList blockTexts(const QTextDocument& document, LineRange range, program::Dialect dialect) {
    QStringList blocks;
    for (int line = range.first; line <= range.last; ++line) {
        const QTextBlock block = document.findBlockByNumber(line);
        if (numberOf(block, dialect) || blocks.isEmpty())
            blocks << withoutNumber(block, dialect);
        else
            blocks.last() += QLatin1Char('\n') + block.text();
    }
    if (dialect != program::Dialect::TncIso) return blocks;
    QStringList klartext;
    for (const QString& block : blocks) {
        const QStringList cycle = klartextCycleBlocks(block);
        klartext << (cycle.isEmpty() ? QStringList{QString()} : cycle);
    }
    return klartext;
}

bool programIsInch(const QTextDocument& document) {
    static const QRegularExpression begin(QStringLiteral(R"(BEGIN\s+PGM\s+\S+\s+INCH\b)"),
                                          QRegularExpression::CaseInsensitiveOption);
    // TNC ISO: "%NAME G70 *" opens an inch program.
    static const QRegularExpression isoHeader(QStringLiteral(R"(^\s*%\S+\s+G7([01])\b)"),
                                              QRegularExpression::CaseInsensitiveOption);
    for (QTextBlock b = document.begin(); b.isValid() && b.blockNumber() < 50; b = b.next()) {
        if (const auto iso = isoHeader.match(b.text()); iso.hasMatch())
            return iso.captured(1) == QLatin1String("0");
        if (b.text().contains(QLatin1String("BEGIN"), Qt::CaseInsensitive))
            return begin.match(b.text()).hasMatch();
    }
    return false;
}

void insertBlocks(QPlainTextEdit& editor, const QStringList& blocks, program::Dialect dialect) {
    QTextDocument& document = *editor.document();
    const int cursorLine = editor.textCursor().blockNumber();
    const LineRange at = blockAt(document, cursorLine, dialect);
    const QTextBlock atBlock = document.findBlockByNumber(at.first);
    const bool beforeEnd = numberOf(atBlock, dialect).has_value() &&
                           isEndBlock(withoutNumber(atBlock, dialect), dialect);
    const bool empty = document.characterCount() <= 1;
    const bool iso = dialect == program::Dialect::TncIso;
    QTextCursor edit(&document);
    edit.beginEditBlock();
    int firstLine = 0;
    if (empty) {
        edit.insertText(numbered(blocks, iso ? 1 : 0, 1, dialect));
    } else if (beforeEnd) {
        firstLine = at.first;
        const long long step = stepOf(document, at.first - 1, dialect);
        const long long before = numberBefore(document, at.first - 1, dialect);
        edit.setPosition(atBlock.position());
        edit.insertText(numbered(blocks, std::max(before, iso ? 0LL : -1LL) + step, step, dialect) +
                        QLatin1Char('\n'));
    } else {
        firstLine = at.last + 1;
        const long long step = stepOf(document, at.last, dialect);
        const long long before = numberBefore(document, at.last, dialect);
        const QTextBlock last = document.findBlockByNumber(at.last);
        edit.setPosition(last.position() + last.length() - 1);
        edit.insertText(QLatin1Char('\n') +
                        numbered(blocks, std::max(before, iso ? 0LL : -1LL) + step, step, dialect));
    }
    // Klartext renumbers from the inserted blocks on; ISO only moves what follows them.
    const int insertedLines = static_cast<int>(blocks.join(QLatin1Char('\n')).count('\n')) + 1;
    renumberFrom(edit, iso ? firstLine + insertedLines : firstLine, dialect);
    edit.endEditBlock();
    QTextCursor cursor(document.findBlockByNumber(firstLine));
    editor.setTextCursor(cursor);
}

void replaceBlocks(QPlainTextEdit& editor, LineRange range, const QStringList& blocks,
                   program::Dialect dialect) {
    QTextDocument& document = *editor.document();
    const auto first = numberOf(document.findBlockByNumber(range.first), dialect);
    const long long step = stepOf(document, range.first - 1, dialect);
    const long long number =
        first ? first->number : numberBefore(document, range.first, dialect) + step;
    const QTextBlock last = document.findBlockByNumber(range.last);
    QTextCursor edit(&document);
    edit.beginEditBlock();
    edit.setPosition(document.findBlockByNumber(range.first).position());
    edit.setPosition(last.position() + last.length() - 1, QTextCursor::KeepAnchor);
    edit.insertText(numbered(blocks, number, step, dialect));
    renumberFrom(edit, range.first, dialect);
    edit.endEditBlock();
    editor.setTextCursor(QTextCursor(document.findBlockByNumber(range.first)));
}

}  // namespace kerf::ui
