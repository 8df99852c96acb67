#include "ui/editor/block_numbers.h"

#include <QTextBlock>
#include <QTextDocument>

namespace kerf::ui {

std::optional<BlockNumber> readBlockNumber(QStringView line, program::Dialect dialect) {
    qsizetype pos = 0;
    while (pos < line.size() && line[pos] == QLatin1Char(' '))
        ++pos;
    if (dialect != program::Dialect::Klartext) {
        if (pos >= line.size() || (line[pos] != QLatin1Char('N') && line[pos] != QLatin1Char('n')))
            return std::nullopt;
        ++pos;
    }
    const qsizetype digits = pos;
    long long number = 0;
    while (pos < line.size() && line[pos].isDigit() && pos - digits < 12) {
        number = number * 10 + line[pos].digitValue();
        ++pos;
    }
    if (pos == digits) return std::nullopt;
    return BlockNumber{number, static_cast<int>(pos)};
}

bool continuesOnNextLine(QStringView line) {
    qsizetype end = line.size();
    while (end > 0 && (line[end - 1] == QLatin1Char(' ') || line[end - 1] == QLatin1Char('\t')))
        --end;
    return end > 0 && line[end - 1] == QLatin1Char('~');
}

std::optional<BlockCounter::Numbered> BlockCounter::next(QStringView line) {
    const bool klartext = m_dialect == program::Dialect::Klartext;
    const bool continuation = klartext && m_continued;
    m_continued = klartext && continuesOnNextLine(line);
    if (continuation) return std::nullopt;
    const auto current = readBlockNumber(line, m_dialect);
    if (!current) return std::nullopt;
    if (klartext) {
        m_last += 1;
    } else {
        m_last =
            m_last < 0 ? m_numbering.first.value_or(current->number) : m_last + m_numbering.step;
    }
    return Numbered{*current, m_last};
}

QString nextBlockPrefix(QStringView line, QStringView previousLine, program::Dialect dialect) {
    const auto current = readBlockNumber(line, dialect);
    if (!current) return {};
    if (dialect == program::Dialect::Klartext) {
        if (continuesOnNextLine(previousLine)) return {};  // digits that continue a block
        return QString::number(current->number + 1) + QLatin1Char(' ');
    }
    long long step = 10;
    if (const auto previous = readBlockNumber(previousLine, dialect)) {
        if (current->number > previous->number) step = current->number - previous->number;
    }
    return QStringLiteral("N%1 ").arg(current->number + step);
}

QString withBlockNumber(QStringView line, long long number, program::Dialect dialect) {
    const auto current = readBlockNumber(line, dialect);
    if (!current) return line.toString();
    const QString prefix = dialect == program::Dialect::Klartext
                               ? QString::number(number)
                               : QStringLiteral("N%1").arg(number);
    return prefix + line.mid(current->length).toString();
}

long long blockNumberOfLine(const QTextDocument& document, int line, program::Dialect dialect) {
    const QTextBlock block = document.findBlockByNumber(line - 1);
    if (!block.isValid()) return -1;
    // A '~' on the line before: this line continues that block.
    const QTextBlock previous = block.previous();
    if (dialect == program::Dialect::Klartext && previous.isValid() &&
        continuesOnNextLine(previous.text()))
        return -1;
    const auto number = readBlockNumber(block.text(), dialect);
    return number ? number->number : -1;
}

std::optional<int> lineOfBlock(const QTextDocument& document, long long number,
                               program::Dialect dialect) {
    bool continued = false;
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        const QString text = block.text();
        if (!continued) {
            const auto found = readBlockNumber(text, dialect);
            if (found && found->number == number) return block.blockNumber() + 1;
        }
        continued = dialect == program::Dialect::Klartext && continuesOnNextLine(text);
    }
    return std::nullopt;
}

bool numbersBlocks(const QTextDocument& document, program::Dialect dialect) {
    // FAGOR programs often start with a %name header and comments before the first N.
    constexpr int kLinesLooked = 20;
    int looked = 0;
    for (QTextBlock block = document.begin(); block.isValid() && looked < kLinesLooked;
         block = block.next(), ++looked) {
        if (readBlockNumber(block.text(), dialect)) return true;
    }
    return false;
}

}  // namespace kerf::ui
