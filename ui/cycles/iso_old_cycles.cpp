#include "ui/cycles/iso_old_cycles.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace kerf::ui {

namespace {

IsoResult written(const QStringList& words) {
    return {words.join(QLatin1Char(' ')), QString()};
}

IsoResult failure(const QString& message) {
    return {QString(), message};
}

QString noIsoForm() {
    return QCoreApplication::translate("kerf", "This cycle has no ISO form");
}

// The cycle's words that ISO has no place for: the operator must leave them empty.
IsoResult onlyWords(int cycle, const QString& words) {
    return failure(
        QCoreApplication::translate(
            "kerf", "In ISO programs cycle %1 takes only %2: leave the other fields empty")
            .arg(cycle)
            .arg(words));
}

// What follows `keyword` in the words ("DWELL 1.5" -> "1.5"), or empty.
QString valueAfter(const QString& words, const QString& keyword) {
    const QRegularExpression re(
        QStringLiteral(R"((?:^|\s)%1\s*=?\s*(\S+))").arg(QRegularExpression::escape(keyword)));
    return re.match(words).captured(1);
}

// Axis words of cycle 7 or 19 ("X+10", "IY-5") as "G90 X+10" / "G91 Y-5": an ISO block is
// absolute or incremental as a whole.
IsoResult axisWords(const QString& g, const QStringList& tokens, const QString& letters,
                    bool withMode) {
    QStringList absolute;
    QStringList incremental;
    for (const QString& token : tokens) {
        const bool inc =
            token.startsWith(QLatin1Char('I')) && token.size() > 1 && letters.contains(token.at(1));
        const QString word = inc ? token.mid(1) : token;
        if (word.isEmpty() || !letters.contains(word.front())) return failure(noIsoForm());
        (inc ? incremental : absolute) << word;
    }
    if (!absolute.isEmpty() && !incremental.isEmpty())
        return failure(QCoreApplication::translate(
            "kerf",
            "An ISO block is either absolute (G90) or incremental (G91): enter "
            "all coordinates with I or none"));
    QStringList words{g};
    if (withMode && !(absolute.isEmpty() && incremental.isEmpty()))
        words << (incremental.isEmpty() ? QStringLiteral("G90") : QStringLiteral("G91"));
    words << absolute << incremental;
    return written(words);
}

// The blank-separated words of an ISO block, a quoted name being one word.
QStringList isoTokens(const QString& text) {
    static const QRegularExpression token(QStringLiteral(R"("[^"]*"|\S+)"));
    QStringList tokens;
    for (auto it = token.globalMatch(text); it.hasNext();)
        tokens << it.next().captured(0);
    return tokens;
}

// The value of "P01 value" (P01 = number `n`) among the tokens.
QString pValue(const QStringList& tokens, int n) {
    for (int i = 0; i + 1 < tokens.size(); ++i) {
        const QString& t = tokens[i];
        if (t.size() > 1 && t.front().toUpper() == QLatin1Char('P') && t.mid(1).toInt() == n)
            return tokens[i + 1];
    }
    return {};
}

QString withoutQuotes(QString text) {
    if (text.startsWith(QLatin1Char('"')) && text.endsWith(QLatin1Char('"')) && text.size() >= 2)
        text = text.mid(1, text.size() - 2);
    return text;
}

// The value of the first token that starts with `letter` (and is more than the letter).
QString letterValue(const QStringList& tokens, QChar letter) {
    for (const QString& t : tokens) {
        if (t.size() > 1 && t.front().toUpper() == letter) return t.mid(1);
    }
    return {};
}

}  // namespace

IsoResult isoOldCycleBlock(int cycle, const QString& klartextWords) {
    const QString words = klartextWords.simplified();
    const QStringList tokens = words.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    switch (cycle) {
        case 7: {
            const QString datum = words.startsWith(QLatin1Char('#')) ? words.mid(1) : QString();
            if (!datum.isEmpty()) return written({QStringLiteral("G53 P01"), datum});
            return axisWords(QStringLiteral("G54"), tokens, QStringLiteral("XYZ"), true);
        }
        case 8:
            return written(QStringList{QStringLiteral("G28")} + tokens);
        case 9:
            return written({QStringLiteral("G04 F") + valueAfter(words, QStringLiteral("DWELL"))});
        case 10: {
            const bool inc = words.startsWith(QLatin1String("IROT"));
            return written({QStringLiteral("G73"),
                            inc ? QStringLiteral("G91") : QStringLiteral("G90"),
                            QLatin1Char('H') + words.mid(inc ? 4 : 3)});
        }
        case 11:
            return written({QStringLiteral("G72 F") + valueAfter(words, QStringLiteral("SCL"))});
        case 12:
            return written({QStringLiteral("G39 P01"),
                            QLatin1Char('"') + words.mid(4).trimmed() + QLatin1Char('"')});
        case 13:
            return written({QStringLiteral("G36 S") + valueAfter(words, QStringLiteral("ANGLE"))});
        case 14: {
            QStringList iso{QStringLiteral("G37")};
            const QStringList labels = words.mid(QStringLiteral("CONTOUR LABEL").size())
                                           .split(QLatin1Char('/'), Qt::SkipEmptyParts);
            for (int i = 0; i < labels.size(); ++i) {
                const QString label = labels[i].trimmed();
                bool number = false;
                label.toInt(&number);
                iso << QStringLiteral("P%1").arg(i + 1, 2, 10, QLatin1Char('0'))
                    << (number ? label : QLatin1Char('"') + label + QLatin1Char('"'));
            }
            return written(iso);
        }
        case 18:
            return written({QStringLiteral("G18 P01"), valueAfter(words, QStringLiteral("DEPTH")),
                            QStringLiteral("P02"), valueAfter(words, QStringLiteral("PITCH"))});
        case 19:
            for (const QString& t : tokens) {
                if (t.startsWith(QLatin1Char('F')) || t.startsWith(QLatin1String("DIST")))
                    return onlyWords(19, QStringLiteral("A B C"));
            }
            return axisWords(QStringLiteral("G80"), tokens, QStringLiteral("ABC"), false);
        case 32:
            if (words.contains(QLatin1String("HSC-MODE")) || words.contains(QLatin1String(" TA")))
                return onlyWords(32, QStringLiteral("T"));
            return written({QStringLiteral("G62"), words});
        default:
            return failure(noIsoForm());
    }
}

QStringList klartextOldCycleBlocks(const QString& isoBlock) {
    static const QRegularExpression header(QStringLiteral(R"(^\s*G(\d{2})\b(.*)$)"),
                                           QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression end(QStringLiteral(R"(\s*\*\s*(;.*)?$)"));
    const auto m = header.match(isoBlock);
    if (!m.hasMatch()) return {};
    QString rest = m.captured(2);
    rest.remove(end);
    const QStringList tokens = isoTokens(rest);
    const bool incremental = tokens.contains(QStringLiteral("G91"), Qt::CaseInsensitive);
    // The axis words among the tokens; `marked`: "I" before each under G91 (cycle 7).
    const auto axes = [&](const QString& letters, bool withValues, bool marked) {
        QStringList words;
        for (const QString& t : tokens) {
            if (t.isEmpty() || !letters.contains(t.front().toUpper())) continue;
            if (!withValues) {
                words << t.left(1).toUpper();
            } else if (t.size() > 1) {
                words << (marked && incremental ? QStringLiteral("I") : QString()) + t.toUpper();
            }
        }
        return words.join(QLatin1Char(' '));
    };
    int cycle = 0;
    QString words;
    switch (m.captured(1).toInt()) {
        case 4:
            cycle = 9;
            words = QStringLiteral("DWELL ") + letterValue(tokens, QLatin1Char('F'));
            break;
        case 18:
            if (pValue(tokens, 1).isEmpty()) return {};  // the plane, not the cycle
            cycle = 18;
            words =
                QStringLiteral("DEPTH = %1 PITCH = %2").arg(pValue(tokens, 1), pValue(tokens, 2));
            break;
        case 28:
            cycle = 8;
            words = axes(QStringLiteral("XYZ"), false, false);
            break;
        case 36:
            cycle = 13;
            words = QStringLiteral("ANGLE ") + letterValue(tokens, QLatin1Char('S'));
            break;
        case 37: {
            cycle = 14;
            QStringList labels;
            for (int n = 1; !pValue(tokens, n).isEmpty(); ++n)
                labels << withoutQuotes(pValue(tokens, n));
            words = QStringLiteral("CONTOUR LABEL ") + labels.join(QLatin1Char('/'));
            break;
        }
        case 39:
            cycle = 12;
            words = QStringLiteral("PGM ") + withoutQuotes(pValue(tokens, 1));
            break;
        case 53:
            cycle = 7;
            words = QLatin1Char('#') + pValue(tokens, 1);
            break;
        case 54:
            cycle = 7;
            words = axes(QStringLiteral("XYZ"), true, true);
            break;
        case 62:
            cycle = 32;
            words = QLatin1Char('T') + letterValue(tokens, QLatin1Char('T'));
            break;
        case 72:
            cycle = 11;
            words = QStringLiteral("SCL ") + letterValue(tokens, QLatin1Char('F'));
            break;
        case 73:
            cycle = 10;
            words = (incremental ? QStringLiteral("IROT") : QStringLiteral("ROT")) +
                    letterValue(tokens, QLatin1Char('H'));
            break;
        case 80:
            cycle = 19;
            words = axes(QStringLiteral("ABC"), true, false);
            break;
        default:
            return {};
    }
    return {QStringLiteral("CYCL DEF %1.0").arg(cycle),
            QStringLiteral("CYCL DEF %1.1 %2").arg(cycle).arg(words)};
}

}  // namespace kerf::ui
