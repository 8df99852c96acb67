#include "ui/cycles/path_function.h"

#include <QCoreApplication>

#include "ui/cycles/cycle_block.h"
#include "ui/cycles/word_pattern.h"

namespace kerf::ui {

namespace {

std::optional<double> number(QString text) {
    text.replace(QLatin1Char(','), QLatin1Char('.'));
    bool ok = false;
    const double value = text.toDouble(&ok);
    return ok ? std::optional<double>(value) : std::nullopt;
}

// A number with its sign ("+10"), a reference with a sign ("+Q3").
QString signedText(const QString& text) {
    const QString upper = text.trimmed().toUpper();
    if (matchesWhole(kParameterPattern, upper))
        return upper.startsWith(QLatin1Char('-')) || upper.startsWith(QLatin1Char('+'))
                   ? upper
                   : QLatin1Char('+') + upper;
    return formatNumber(number(upper).value_or(0.0), true);
}

QString plainText(const QString& text) {
    const QString upper = text.trimmed().toUpper();
    if (matchesWhole(kParameterPattern, upper)) return upper;
    return formatNumber(number(upper).value_or(0.0), false);
}

PathField field(const char* word, PathFieldKind kind, bool required = false,
                QStringList choices = {}) {
    PathField f{QString::fromLatin1(word), kind, required, std::move(choices)};
    return f;
}

}  // namespace

QString pathFunctionKeyword(PathFunction function) {
    switch (function) {
        case PathFunction::Line:
            return QStringLiteral("L");
        case PathFunction::CircleCentre:
            return QStringLiteral("CC");
        case PathFunction::Circle:
            return QStringLiteral("C");
        case PathFunction::CircleRadius:
            return QStringLiteral("CR");
        case PathFunction::CircleTangential:
            return QStringLiteral("CT");
        case PathFunction::Rounding:
            return QStringLiteral("RND");
        case PathFunction::Chamfer:
            return QStringLiteral("CHF");
        case PathFunction::ToolCall:
            return QStringLiteral("TOOL CALL");
    }
    return {};
}

std::vector<PathField> pathFields(PathFunction function) {
    const PathField x = field("X", PathFieldKind::Coordinate);
    const PathField y = field("Y", PathFieldKind::Coordinate);
    const PathField z = field("Z", PathFieldKind::Coordinate);
    const PathField compensation =
        field("R", PathFieldKind::Compensation, false, {"", "R0", "RL", "RR"});
    const PathField feed = field("F", PathFieldKind::Feed);
    const PathField misc = field("M", PathFieldKind::Misc);
    const PathField direction = field("DR", PathFieldKind::Direction, true, {"DR-", "DR+"});
    switch (function) {
        case PathFunction::Line:
            return {x, y, z, compensation, feed, misc};
        case PathFunction::CircleCentre:
            return {x, y};
        case PathFunction::Circle:
            return {x, y, direction, compensation, feed, misc};
        case PathFunction::CircleRadius:
            return {x,    y,   field("R", PathFieldKind::Radius, true), direction, compensation,
                    feed, misc};
        case PathFunction::CircleTangential:
            return {x, y, compensation, feed, misc};
        case PathFunction::Rounding:
            return {field("R", PathFieldKind::Length, true), feed};
        case PathFunction::Chamfer:
            return {field("", PathFieldKind::Length, true), feed};
        case PathFunction::ToolCall:
            return {field("", PathFieldKind::Tool, true),
                    field("", PathFieldKind::ToolAxis, true, {"Z", "X", "Y"}),
                    field("S", PathFieldKind::Speed),
                    feed,
                    field("DL", PathFieldKind::Oversize),
                    field("DR", PathFieldKind::Oversize)};
    }
    return {};
}

QString pathFieldDescription(const PathField& field) {
    switch (field.kind) {
        case PathFieldKind::Coordinate:
            return QCoreApplication::translate(
                       "kerf", "%1 coordinate of the end point (I before the value: incremental)")
                .arg(field.word);
        case PathFieldKind::Radius:
            return QCoreApplication::translate("kerf",
                                               "Circle radius (negative: arc greater than 180°)");
        case PathFieldKind::Length:
            return field.word.isEmpty() ? QCoreApplication::translate("kerf", "Chamfer length")
                                        : QCoreApplication::translate("kerf", "Rounding radius");
        case PathFieldKind::Direction:
            return QCoreApplication::translate(
                "kerf", "Direction of rotation (DR-: clockwise, DR+: counterclockwise)");
        case PathFieldKind::Compensation:
            return QCoreApplication::translate(
                "kerf", "Radius compensation (RL left, RR right of the contour, R0 none)");
        case PathFieldKind::Feed:
            return QCoreApplication::translate(
                "kerf", "Feed rate (FMAX: rapid traverse, FAUTO: from TOOL CALL)");
        case PathFieldKind::Misc:
            return QCoreApplication::translate("kerf", "Miscellaneous functions, e.g. 3 8");
        case PathFieldKind::Tool:
            return QCoreApplication::translate("kerf", "Tool number or name");
        case PathFieldKind::ToolAxis:
            return QCoreApplication::translate("kerf", "Spindle axis");
        case PathFieldKind::Speed:
            return QCoreApplication::translate("kerf", "Spindle speed S [1/min]");
        case PathFieldKind::Oversize:
            return field.word == QLatin1String("DL")
                       ? QCoreApplication::translate("kerf", "Delta length DL")
                       : QCoreApplication::translate("kerf", "Delta radius DR");
    }
    return {};
}

std::optional<QString> checkPathField(const PathField& field, const QString& text) {
    const QString value = text.trimmed().toUpper();
    const QString name = field.word.isEmpty() ? pathFieldDescription(field) : field.word;
    if (value.isEmpty()) {
        if (!field.required) return std::nullopt;
        return QCoreApplication::translate("kerf", "%1: enter a value").arg(name);
    }
    switch (field.kind) {
        case PathFieldKind::Coordinate: {
            const QString rest = value.startsWith(QLatin1Char('I')) ? value.mid(1) : value;
            if (matchesWhole(kNumberPattern, rest) || matchesWhole(kParameterPattern, rest))
                return std::nullopt;
            return QCoreApplication::translate("kerf", "%1: \"%2\" is not a coordinate")
                .arg(name, text.trimmed());
        }
        case PathFieldKind::Radius:
            if (matchesWhole(kParameterPattern, value)) return std::nullopt;
            if (!matchesWhole(kNumberPattern, value) || *number(value) == 0.0)
                return QCoreApplication::translate("kerf", "%1: enter a radius other than 0")
                    .arg(name);
            return std::nullopt;
        case PathFieldKind::Length:
        case PathFieldKind::Speed:
            if (matchesWhole(kParameterPattern, value)) return std::nullopt;
            if (!matchesWhole(kNumberPattern, value) || *number(value) < 0.0 ||
                (field.kind == PathFieldKind::Length && *number(value) == 0.0))
                return QCoreApplication::translate("kerf", "%1: enter a positive number").arg(name);
            return std::nullopt;
        case PathFieldKind::Feed:
            if (value == QLatin1String("FMAX") || value == QLatin1String("FAUTO") ||
                matchesWhole(kParameterPattern, value))
                return std::nullopt;
            if (!matchesWhole(kNumberPattern, value) || *number(value) < 0.0)
                return QCoreApplication::translate("kerf", "%1: enter a feed rate, FMAX or FAUTO")
                    .arg(name);
            return std::nullopt;
        case PathFieldKind::Misc:
            if (matchesWhole(QStringLiteral(R"(M?\d{1,3}(\s+M?\d{1,3})*)"), value))
                return std::nullopt;
            return QCoreApplication::translate("kerf", "%1: enter M function numbers, e.g. 3 8")
                .arg(name);
        case PathFieldKind::Tool:
            if (matchesWhole(QStringLiteral(R"(\d{1,5}(\.\d)?)"), value) ||
                matchesWhole(QStringLiteral(R"([A-Z_][A-Z0-9_.\-]{0,31})"), value) ||
                matchesWhole(kParameterPattern, value))
                return std::nullopt;
            return QCoreApplication::translate("kerf", "%1: enter a tool number or a name")
                .arg(name);
        case PathFieldKind::Oversize:
            if (matchesWhole(kNumberPattern, value) || matchesWhole(kParameterPattern, value))
                return std::nullopt;
            return QCoreApplication::translate("kerf", "%1: \"%2\" is not a number")
                .arg(name, text.trimmed());
        case PathFieldKind::Direction:
        case PathFieldKind::Compensation:
        case PathFieldKind::ToolAxis:
            if (field.choices.contains(value)) return std::nullopt;
            return QCoreApplication::translate("kerf", "%1: choose one of %2")
                .arg(name, field.choices.join(QLatin1Char(' ')));
    }
    return std::nullopt;
}

std::optional<QString> checkPathFunction(PathFunction function, const QStringList& values) {
    const std::vector<PathField> fields = pathFields(function);
    bool coordinate = false;
    for (size_t i = 0; i < fields.size(); ++i) {
        const QString text = values.value(static_cast<int>(i));
        if (auto error = checkPathField(fields[i], text)) return error;
        if (fields[i].kind == PathFieldKind::Coordinate && !text.trimmed().isEmpty())
            coordinate = true;
    }
    const bool needsCoordinate = function == PathFunction::Line ||
                                 function == PathFunction::CircleCentre ||
                                 function == PathFunction::CircleTangential;
    if (needsCoordinate && !coordinate)
        return QCoreApplication::translate("kerf", "%1: enter at least one coordinate")
            .arg(pathFunctionKeyword(function));
    return std::nullopt;
}

QString writePathFunction(PathFunction function, const QStringList& values) {
    const std::vector<PathField> fields = pathFields(function);
    QStringList words{pathFunctionKeyword(function)};
    for (size_t i = 0; i < fields.size(); ++i) {
        const QString value = values.value(static_cast<int>(i)).trimmed().toUpper();
        if (value.isEmpty()) continue;
        const PathField& f = fields[i];
        switch (f.kind) {
            case PathFieldKind::Coordinate:
                if (value.startsWith(QLatin1Char('I')))
                    words << QLatin1Char('I') + f.word + signedText(value.mid(1));
                else
                    words << f.word + signedText(value);
                break;
            case PathFieldKind::Radius:
            case PathFieldKind::Oversize:
                words << f.word + signedText(value);
                break;
            case PathFieldKind::Length:
                words << (f.word.isEmpty() ? plainText(value) : f.word + plainText(value));
                break;
            case PathFieldKind::Speed:
                words << f.word + plainText(value);
                break;
            case PathFieldKind::Feed:
                words << (value.startsWith(QLatin1String("FMAX")) || value == QLatin1String("FAUTO")
                              ? value
                              : f.word + plainText(value));
                break;
            case PathFieldKind::Misc:
                for (QString m : value.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
                    if (m.startsWith(QLatin1Char('M'))) m.remove(0, 1);
                    words << QLatin1Char('M') + QString::number(m.toInt());
                }
                break;
            case PathFieldKind::Tool:
                words << (value.front().isDigit() || value.startsWith(QLatin1Char('Q'))
                              ? value
                              : QLatin1Char('"') + values.value(static_cast<int>(i)).trimmed() +
                                    QLatin1Char('"'));
                break;
            case PathFieldKind::Direction:
            case PathFieldKind::Compensation:
            case PathFieldKind::ToolAxis:
                words << value;
                break;
        }
    }
    return words.join(QLatin1Char(' '));
}

}  // namespace kerf::ui
