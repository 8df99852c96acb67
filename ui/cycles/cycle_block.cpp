#include "ui/cycles/cycle_block.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <cmath>

#include "core/cycles/cycle_registry.h"
#include "ui/cycles/cycle_catalogue.h"
#include "ui/cycles/parameter_comments.h"

namespace kerf::ui {

namespace {

using cycles::ParameterDescriptor;
using cycles::Unit;

constexpr double kMmPerInch = 25.4;
// A number or a Q parameter reference, as the parser reads a word value.
const QString kValuePattern = QStringLiteral(R"([+-]?(?:\d+(?:[.,]\d*)?|[.,]\d+|Q[LR]?\d+))");

bool isQReference(const QString& text) {
    static const QRegularExpression reference(QStringLiteral(R"(^[+-]?Q[LR]?\d+$)"));
    return reference.match(text).hasMatch();
}

std::optional<double> parseNumber(QString text) {
    text.replace(QLatin1Char(','), QLatin1Char('.'));
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (!ok || !std::isfinite(value)) return std::nullopt;
    return value;
}

// The keywords a parameter allows instead of a number, as the dialog lists them.
QStringList allowedKeywords(const ParameterDescriptor& p) {
    QStringList words;
    if (p.predef) words << QStringLiteral("PREDEF");
    if (p.keywords & cycles::kFeedAuto) words << QStringLiteral("FAUTO");
    if (p.keywords & cycles::kFeedMax) words << QStringLiteral("FMAX");
    if (p.keywords & cycles::kFeedPerRev) words << QStringLiteral("FU");
    if (p.keywords & cycles::kFeedPerTooth) words << QStringLiteral("FZ");
    return words;
}

std::optional<QString> checkKeyword(const CycleField& field, const QString& upper) {
    const ParameterDescriptor& p = *field.parameter;
    QString keyword = upper;
    if (upper.startsWith(QLatin1String("FU")) || upper.startsWith(QLatin1String("FZ"))) {
        keyword = upper.left(2);
        const auto perRevOrTooth = parseNumber(upper.mid(2));
        if (!perRevOrTooth || *perRevOrTooth <= 0.0)
            return QCoreApplication::translate("kerf",
                                               "%1: %2 needs a positive feed after it, e.g. %2 0.1")
                .arg(field.label, keyword);
    }
    if (allowedKeywords(p).contains(keyword)) return std::nullopt;
    const QStringList allowed = allowedKeywords(p);
    if (allowed.isEmpty())
        return QCoreApplication::translate("kerf", "%1: %2 is not allowed here; enter a number")
            .arg(field.label, keyword);
    return QCoreApplication::translate("kerf", "%1: %2 is not allowed here; allowed: a number, %3")
        .arg(field.label, keyword, allowed.join(QStringLiteral(", ")));
}

bool isKeyword(const QString& upper) {
    static const QRegularExpression keyword(QStringLiteral(R"(^(PREDEF|FAUTO|FMAX|FU.*|FZ.*)$)"));
    return keyword.match(upper).hasMatch();
}

QString signedValue(const QString& value) {
    if (value.startsWith(QLatin1Char('+')) || value.startsWith(QLatin1Char('-'))) return value;
    return QLatin1Char('+') + value;
}

// A value as the block writes it: numbers normalised with a sign, keywords in upper case.
QString writtenValue(const QString& text, bool sign) {
    const QString upper = text.trimmed().toUpper();
    if (isKeyword(upper)) return upper;
    if (isQReference(upper)) return sign ? signedValue(upper) : upper;
    if (const auto number = parseNumber(upper)) return formatNumber(*number, sign);
    return text.trimmed();
}

QString oldStyleWord(const CycleField& field, const QString& text) {
    const QString value = text.trimmed();
    switch (field.style) {
        case WordStyle::Signed: {
            if (value.startsWith(QLatin1Char('#'))) return value;
            if (value.startsWith(QLatin1Char('I'), Qt::CaseInsensitive))
                return QLatin1Char('I') + field.word + writtenValue(value.mid(1), true);
            return field.word + writtenValue(value, true);
        }
        case WordStyle::Spaced:
            if (field.parameter->unit == Unit::Text) return field.word + QLatin1Char(' ') + value;
            return field.word + QLatin1Char(' ') + writtenValue(value, false);
        case WordStyle::Joined:
            return field.word + writtenValue(value, false);
        case WordStyle::Equals:
            return field.word + QStringLiteral(" = ") + writtenValue(value, true);
        case WordStyle::Colon:
            return field.word + QLatin1Char(':') + writtenValue(value, false);
        case WordStyle::Bare:
            return value.toUpper().simplified();
    }
    return value;
}

QString stripContinuation(QString line) {
    line = line.trimmed();
    if (line.endsWith(QLatin1Char('~'))) line.chop(1);
    return line.trimmed();
}

// The text of a field in an old-style sub-block, or empty.
QString readOldStyleWord(const CycleField& field, const QString& text) {
    const QString word = QRegularExpression::escape(field.word);
    QString pattern;
    switch (field.style) {
        case WordStyle::Signed:
            if (field.word == QLatin1String("X")) {
                static const QRegularExpression table(QStringLiteral(R"((?:^|\s)(#\d+))"));
                const auto m = table.match(text);
                if (m.hasMatch()) return m.captured(1);
            }
            pattern = QStringLiteral(R"((?:^|\s)(I?)%1\s*(%2))");
            break;
        case WordStyle::Spaced:
            if (field.parameter->unit == Unit::Text) {
                pattern = QStringLiteral(R"((?:^|\s)()%1\s+(.+)$)");
                break;
            }
            pattern = QStringLiteral(R"((?:^|\s)()%1\s*(%2))");
            break;
        case WordStyle::Joined:
            pattern = QStringLiteral(R"((?:^|\s)()%1(%2)(?=\s|$))");
            break;
        case WordStyle::Equals:
            pattern = QStringLiteral(R"((?:^|\s)()%1\s*=\s*(%2))");
            break;
        case WordStyle::Colon:
            pattern = QStringLiteral(R"((?:^|\s)()%1:\s*(%2))");
            break;
        case WordStyle::Bare:
            return text.simplified();
    }
    const QRegularExpression re(pattern.arg(word, kValuePattern),
                                QRegularExpression::CaseInsensitiveOption);
    const auto m = re.match(text);
    if (!m.hasMatch()) return {};
    QString value = m.captured(2).trimmed();
    if (!m.captured(1).isEmpty()) value = QLatin1Char('I') + value;
    return value;
}

}  // namespace

double inProgramUnit(const ParameterDescriptor& parameter, double mmValue, bool inch) {
    const bool scales = parameter.unit == Unit::Millimetre || parameter.unit == Unit::FeedPerMinute;
    return inch && scales ? mmValue / kMmPerInch : mmValue;
}

QString formatNumber(double value, bool sign) {
    QString text = QString::number(value, 'f', 4);
    while (text.contains(QLatin1Char('.')) && text.endsWith(QLatin1Char('0')))
        text.chop(1);
    if (text.endsWith(QLatin1Char('.'))) text.chop(1);
    if (text == QLatin1String("-0")) text = QStringLiteral("0");
    if (sign && !text.startsWith(QLatin1Char('-'))) text.prepend(QLatin1Char('+'));
    return text;
}

QString defaultText(const CycleField& field, bool inch) {
    const ParameterDescriptor& p = *field.parameter;
    if (p.unit == Unit::Text) return {};
    if (!field.word.isEmpty() && field.optional) return {};
    return formatNumber(inProgramUnit(p, p.defaultValue, inch), false);
}

std::optional<QString> checkFieldText(const cycles::CycleDescriptor& cycle, const CycleField& field,
                                      const QString& text, bool inch) {
    const ParameterDescriptor& p = *field.parameter;
    const QString value = text.trimmed();
    if (value.isEmpty()) {
        if (field.optional) return std::nullopt;
        return QCoreApplication::translate("kerf", "%1: enter a value").arg(field.label);
    }
    if (p.unit == Unit::Text) {
        if (value.contains(QLatin1Char('"')))
            return QCoreApplication::translate("kerf", "%1: the text must not contain \"")
                .arg(field.label);
        return std::nullopt;
    }
    QString upper = value.toUpper();
    if (field.style == WordStyle::Bare) {
        static const QRegularExpression axes(QStringLiteral(R"(^([XYZABCUVW](\s+|$))+$)"));
        if (axes.match(upper).hasMatch()) return std::nullopt;
        return QCoreApplication::translate("kerf",
                                           "%1: enter axis letters separated by blanks, e.g. X Y")
            .arg(field.label);
    }
    if (cycle.number == 7 && upper.startsWith(QLatin1Char('#'))) {
        const auto datum = parseNumber(upper.mid(1));
        if (datum && *datum >= 0 && std::floor(*datum) == *datum) return std::nullopt;
        return QCoreApplication::translate("kerf", "%1: #n needs a datum number, e.g. #5")
            .arg(field.label);
    }
    if (field.style == WordStyle::Signed && (cycle.number == 7 || cycle.number == 10) &&
        upper.startsWith(QLatin1Char('I'))) {
        upper = upper.mid(1);  // incremental: IX+10, IROT+45
    }
    if (isKeyword(upper)) return checkKeyword(field, upper);
    if (isQReference(upper)) return std::nullopt;
    const auto number = parseNumber(upper);
    if (!number)
        return QCoreApplication::translate("kerf", "%1: \"%2\" is not a number")
            .arg(field.label, value);
    const double low = inProgramUnit(p, p.min, inch);
    const double high = inProgramUnit(p, p.max, inch);
    if (p.integer && std::fabs(*number - std::round(*number)) > 1e-9)
        return QCoreApplication::translate("kerf", "%1: enter a whole number from %2 to %3")
            .arg(field.label, formatNumber(low, false), formatNumber(high, false));
    if (*number < low - 1e-9 || *number > high + 1e-9)
        return QCoreApplication::translate("kerf", "%1: %2 is outside the range %3 to %4")
            .arg(field.label, formatNumber(*number, false), formatNumber(low, false),
                 formatNumber(high, false));
    return std::nullopt;
}

QStringList writeCycleBlocks(const cycles::CycleDescriptor& cycle,
                             const std::vector<CycleField>& fields, const QStringList& values) {
    const QString name = cycleName(cycle);
    if (!cycle.oldStyle) {
        QStringList lines{QStringLiteral("CYCL DEF %1 %2").arg(cycle.number).arg(name)};
        for (size_t i = 0; i < fields.size(); ++i) {
            const QString text = values.value(static_cast<int>(i)).trimmed();
            const ParameterDescriptor& p = *fields[i].parameter;
            if (text.isEmpty()) continue;
            const QString assignment =
                p.unit == Unit::Text
                    ? QStringLiteral("QS%1=\"%2\"").arg(p.q).arg(text)
                    : QStringLiteral("Q%1=%2").arg(p.q).arg(writtenValue(text, true));
            lines << QStringLiteral("  ") + assignment.leftJustified(12) + QStringLiteral(" ;") +
                         parameterComment(cycle.number, p);
        }
        // Every line but the last continues the block (the newer TNC format, spec 1.4 rule 4).
        for (int i = 0; i + 1 < lines.size(); ++i)
            lines[i] += QStringLiteral(" ~");
        return {lines.join(QLatin1Char('\n'))};
    }
    QStringList blocks{QStringLiteral("CYCL DEF %1.0 %2").arg(cycle.number).arg(name)};
    // Sub-blocks in field order: words of one sub-block share a line, numbered consecutively.
    QStringList subBlocks;
    int lastShared = -1;
    for (size_t i = 0; i < fields.size(); ++i) {
        const QString text = values.value(static_cast<int>(i)).trimmed();
        if (text.isEmpty()) continue;
        const QString word = oldStyleWord(fields[i], text);
        if (fields[i].subBlock != 0 && fields[i].subBlock == lastShared) {
            subBlocks.last() += QLatin1Char(' ') + word;
            continue;
        }
        subBlocks << word;
        lastShared = fields[i].subBlock;
    }
    for (int i = 0; i < subBlocks.size(); ++i)
        blocks
            << QStringLiteral("CYCL DEF %1.%2 %3").arg(cycle.number).arg(i + 1).arg(subBlocks[i]);
    return blocks;
}

std::optional<int> cycleDefNumber(const QString& blockText, int* subBlock) {
    static const QRegularExpression header(QStringLiteral(R"(^\s*CYCL\s+DEF\s+(\d+)(?:\.(\d+))?)"),
                                           QRegularExpression::CaseInsensitiveOption);
    const auto m = header.match(blockText);
    if (!m.hasMatch()) return std::nullopt;
    if (subBlock) *subBlock = m.captured(2).isEmpty() ? -1 : m.captured(2).toInt();
    return m.captured(1).toInt();
}

std::optional<ReadCycle> readCycleBlocks(const QStringList& blocks) {
    if (blocks.isEmpty()) return std::nullopt;
    const auto number = cycleDefNumber(blocks.first());
    if (!number) return std::nullopt;
    ReadCycle read;
    read.cycle = cycles::findCycle(*number);
    if (!read.cycle) return std::nullopt;
    const std::vector<CycleField> fields = cycleFields(*read.cycle);
    for (size_t i = 0; i < fields.size(); ++i)
        read.values << QString();
    if (!read.cycle->oldStyle) {
        static const QRegularExpression parameter(
            QStringLiteral(R"(^(QS)?(\d+)\s*=\s*("[^"]*"|[^;]*))"),
            QRegularExpression::CaseInsensitiveOption);
        const QStringList lines = blocks.first().split(QLatin1Char('\n'));
        for (int l = 1; l < lines.size(); ++l) {
            QString line = stripContinuation(lines[l]);
            if (!line.startsWith(QLatin1Char('Q'), Qt::CaseInsensitive)) continue;
            const auto m = parameter.match(line.mid(1));
            if (!m.hasMatch()) continue;
            const int q = m.captured(2).toInt();
            QString value = m.captured(3).trimmed();
            if (value.startsWith(QLatin1Char('"'))) value = value.mid(1, value.size() - 2);
            for (size_t i = 0; i < fields.size(); ++i) {
                if (fields[i].parameter->q == q) read.values[static_cast<int>(i)] = value;
            }
        }
        return read;
    }
    // Old style: the words of all sub-blocks, each field looked up in its own sub-block text.
    for (int b = 1; b < blocks.size(); ++b) {
        static const QRegularExpression subHeader(QStringLiteral(R"(^\s*CYCL\s+DEF\s+\d+\.\d+\s*)"),
                                                  QRegularExpression::CaseInsensitiveOption);
        QString text = stripContinuation(blocks[b]);
        text.remove(subHeader);
        const int comment = text.indexOf(QLatin1Char(';'));
        if (comment >= 0) text = text.left(comment).trimmed();
        for (size_t i = 0; i < fields.size(); ++i) {
            auto& slot = read.values[static_cast<int>(i)];
            if (slot.isEmpty()) slot = readOldStyleWord(fields[i], text);
        }
    }
    return read;
}

}  // namespace kerf::ui
