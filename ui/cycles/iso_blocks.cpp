#include "ui/cycles/iso_blocks.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include "ui/cycles/iso_old_cycles.h"

namespace kerf::ui {

namespace {

IsoResult failure(const QString& message) {
    return {QString(), message};
}

// The words of a Klartext block as writePathFunction writes them, sorted into ISO words.
struct Words {
    QStringList absolute;     // "X+10"
    QStringList incremental;  // "X+5" from "IX+5"
    QString compensation;     // G40 / G41 / G42
    QString feed;             // "F200"
    bool rapid = false;       // FMAX
    bool feedAuto = false;    // FAUTO
    QStringList misc;         // "M3"
    QString direction;        // "DR+" / "DR-"
    QString radius;           // "R+20" (CR, RND)
    QStringList rest;         // anything else, in order (TOOL CALL's words)
};

Words sortWords(const QStringList& words) {
    static const QRegularExpression coordinate(QStringLiteral(R"(^(I?)([XYZ])(.+)$)"));
    Words w;
    for (const QString& word : words) {
        const auto c = coordinate.match(word);
        if (c.hasMatch()) {
            (c.captured(1).isEmpty() ? w.absolute : w.incremental) << c.captured(2) + c.captured(3);
        } else if (word == QLatin1String("R0")) {
            w.compensation = QStringLiteral("G40");
        } else if (word == QLatin1String("RL")) {
            w.compensation = QStringLiteral("G41");
        } else if (word == QLatin1String("RR")) {
            w.compensation = QStringLiteral("G42");
        } else if (word.startsWith(QLatin1String("FMAX"))) {
            w.rapid = true;
        } else if (word == QLatin1String("FAUTO")) {
            w.feedAuto = true;
        } else if (word.startsWith(QLatin1Char('F'))) {
            w.feed = word;
        } else if (word.startsWith(QLatin1Char('M'))) {
            w.misc << word;
        } else if (word.startsWith(QLatin1String("DR+")) || word.startsWith(QLatin1String("DR-"))) {
            if (word.size() == 3) {
                w.direction = word;
            } else {
                w.rest << word;  // TOOL CALL's radius oversize DR+0.1
            }
        } else if (word.startsWith(QLatin1Char('R'))) {
            w.radius = word;
        } else {
            w.rest << word;
        }
    }
    return w;
}

// "G90 X+10 Y+5" or "G91 X+5": an ISO block is absolute or incremental as a whole.
IsoResult coordinates(const Words& w, const QString& absoluteLetters = QStringLiteral("XYZ"),
                      const QString& isoLetters = QStringLiteral("XYZ")) {
    if (!w.absolute.isEmpty() && !w.incremental.isEmpty())
        return failure(QCoreApplication::translate(
            "kerf",
            "An ISO block is either absolute (G90) or incremental (G91): enter "
            "all coordinates with I or none"));
    const QStringList& values = w.incremental.isEmpty() ? w.absolute : w.incremental;
    if (values.isEmpty()) return {};
    QStringList words{w.incremental.isEmpty() ? QStringLiteral("G90") : QStringLiteral("G91")};
    for (const QString& value : values) {
        const int axis = absoluteLetters.indexOf(value.front());
        words << isoLetters.at(axis) + value.mid(1);
    }
    return {words.join(QLatin1Char(' ')), QString()};
}

IsoResult motionBlock(const QString& g, const Words& w) {
    if (w.feedAuto)
        return failure(
            QCoreApplication::translate("kerf", "ISO programs have no FAUTO: enter the feed"));
    const IsoResult xyz = coordinates(w);
    if (!xyz.error.isEmpty()) return xyz;
    QStringList words{g};
    if (!w.compensation.isEmpty()) words << w.compensation;
    if (!xyz.block.isEmpty()) words << xyz.block;
    if (!w.radius.isEmpty()) words << w.radius;
    if (!w.feed.isEmpty() && !w.rapid) words << w.feed;
    words << w.misc;
    return {words.join(QLatin1Char(' ')), QString()};
}

}  // namespace

IsoResult isoCycleBlock(const QStringList& klartextBlocks) {
    static const QRegularExpression header(QStringLiteral(R"(^CYCL DEF (\d+) (.*?)(\s*~)?$)"));
    static const QRegularExpression oldHeader(QStringLiteral(R"(^CYCL DEF (\d+)\.0\b)"));
    static const QRegularExpression subBlock(QStringLiteral(R"(^CYCL DEF \d+\.\d+\s*)"));
    if (klartextBlocks.isEmpty())
        return failure(QCoreApplication::translate("kerf", "This cycle has no ISO form"));
    if (const auto old = oldHeader.match(klartextBlocks.first()); old.hasMatch()) {
        QStringList words;
        for (int i = 1; i < klartextBlocks.size(); ++i)
            words << QString(klartextBlocks[i]).remove(subBlock);
        return isoOldCycleBlock(old.captured(1).toInt(), words.join(QLatin1Char(' ')));
    }
    QStringList lines = klartextBlocks.first().split(QLatin1Char('\n'));
    const auto m = header.match(lines.first());
    if (klartextBlocks.size() != 1 || !m.hasMatch())
        return failure(QCoreApplication::translate("kerf", "This cycle has no ISO form"));
    // The SL and cylinder-surface cycles 20-39 are G120-G139 (the cycle manual's index).
    const int number = m.captured(1).toInt();
    lines[0] =
        QStringLiteral("G%1 %2").arg(number < 100 ? number + 100 : number).arg(m.captured(2));
    lines[0] = lines[0].trimmed();
    static const QRegularExpression continuation(QStringLiteral(R"(\s*~\s*$)"));
    for (QString& line : lines)
        line.remove(continuation);
    return {lines.join(QLatin1Char('\n')), QString()};
}

QStringList klartextCycleBlocks(const QString& isoBlock) {
    static const QRegularExpression header(QStringLiteral(R"(^\s*G(\d{3,4})\b(.*)$)"),
                                           QRegularExpression::CaseInsensitiveOption);
    QStringList lines = isoBlock.split(QLatin1Char('\n'));
    const auto m = header.match(lines.first());
    if (!m.hasMatch()) return klartextOldCycleBlocks(isoBlock);
    const int g = m.captured(1).toInt();
    lines[0] =
        QStringLiteral("CYCL DEF %1%2").arg(g >= 120 && g <= 139 ? g - 100 : g).arg(m.captured(2));
    static const QRegularExpression end(QStringLiteral(R"(\s*\*\s*$)"));
    lines.last().remove(end);
    return {lines.join(QLatin1Char('\n'))};
}

IsoResult isoPathBlock(PathFunction function, const QStringList& values) {
    QStringList words = writePathFunction(function, values).split(QLatin1Char(' '));
    const QString keyword = pathFunctionKeyword(function);
    words = words.mid(keyword.count(QLatin1Char(' ')) + 1);
    const Words w = sortWords(words);
    switch (function) {
        case PathFunction::Line:
            return motionBlock(w.rapid ? QStringLiteral("G00") : QStringLiteral("G01"), w);
        case PathFunction::CircleCentre: {
            // The centre's X and Y are I and J.
            return coordinates(w, QStringLiteral("XY"), QStringLiteral("IJ"));
        }
        case PathFunction::Circle:
        case PathFunction::CircleRadius:
            return motionBlock(
                w.direction == QLatin1String("DR+") ? QStringLiteral("G03") : QStringLiteral("G02"),
                w);
        case PathFunction::CircleTangential:
            return motionBlock(QStringLiteral("G06"), w);
        case PathFunction::Rounding:
            return motionBlock(QStringLiteral("G25"), w);
        case PathFunction::Chamfer: {
            Words chamfer = w;
            chamfer.radius = QLatin1Char('R') + w.rest.value(0);
            return motionBlock(QStringLiteral("G24"), chamfer);
        }
        case PathFunction::ToolCall: {
            // "TOOL CALL 5 Z S2000 F100 DL+0.1 DR-0.05" -> "T5 G17 S2000 F100 DL+0.1 DR-0.05".
            static const QStringList planes{QStringLiteral("Z"), QStringLiteral("Y"),
                                            QStringLiteral("X")};
            const QString tool = words.value(0);
            QStringList iso{tool.startsWith(QLatin1Char('"')) ? QStringLiteral("T ") + tool
                                                              : QLatin1Char('T') + tool};
            const int plane = planes.indexOf(words.value(1));
            iso << QStringLiteral("G%1").arg(17 + std::max(plane, 0));
            iso << words.mid(2);
            return {iso.join(QLatin1Char(' ')), QString()};
        }
    }
    return failure(QCoreApplication::translate("kerf", "This block has no ISO form"));
}

}  // namespace kerf::ui
