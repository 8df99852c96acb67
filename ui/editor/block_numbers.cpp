#include "ui/editor/block_numbers.h"

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

QString nextBlockPrefix(QStringView line, QStringView previousLine, program::Dialect dialect) {
    const auto current = readBlockNumber(line, dialect);
    if (!current) return {};
    if (dialect == program::Dialect::Klartext)
        return QString::number(current->number + 1) + QLatin1Char(' ');
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

}  // namespace kerf::ui
