#include "ui/cycles/special_function.h"

#include <QCoreApplication>

#include "ui/cycles/cycle_block.h"
#include "ui/cycles/word_pattern.h"

namespace kerf::ui {

namespace {

// Letters, digits and the path characters of the NC root (TNC:\DIR\PART.H); no blank, no quote.
const QString kProgramName = QStringLiteral(R"([A-Z0-9_.\-:\\/]{1,200})");

double number(QString text) {
    text.replace(QLatin1Char(','), QLatin1Char('.'));
    return text.toDouble();
}

bool positive(const QString& value) {
    return matchesWhole(kParameterPattern, value) ||
           (matchesWhole(kNumberPattern, value) && number(value) > 0.0);
}

// "+10" for a number, "+Q3" for a parameter.
QString signedText(const QString& value) {
    if (matchesWhole(kParameterPattern, value))
        return value.front() == QLatin1Char('+') || value.front() == QLatin1Char('-')
                   ? value
                   : QLatin1Char('+') + value;
    return formatNumber(number(value), true);
}

QString plainText(const QString& value) {
    return matchesWhole(kParameterPattern, value) ? value : formatNumber(number(value), false);
}

SpecialField numberField(const char* word, const char* description, bool required = true) {
    return {QString::fromLatin1(word), SpecialFieldKind::Number, required, {}, description};
}

bool isPlane(SpecialFunction function) {
    return function <= SpecialFunction::PlaneReset;
}

// MOVE/TURN/STAY with MB, DIST and F; the other PLANE functions also take SEQ and TABLE/COORD
// ROT.
void addPositioning(std::vector<SpecialField>& fields, bool reset) {
    fields.push_back({{},
                      SpecialFieldKind::Choice,
                      true,
                      {"TURN", "MOVE", "STAY"},
                      QT_TRANSLATE_NOOP("kerf", "Positioning: TURN, MOVE (DIST) or STAY")});
    fields.push_back({"MB",
                      SpecialFieldKind::Retract,
                      false,
                      {},
                      QT_TRANSLATE_NOOP("kerf", "Retract along the tool axis first: MAX or mm")});
    fields.push_back({"DIST",
                      SpecialFieldKind::Length,
                      false,
                      {},
                      QT_TRANSLATE_NOOP("kerf",
                                        "MOVE: distance of the tool tip from the centre of "
                                        "rotation")});
    fields.push_back({"F",
                      SpecialFieldKind::Feed,
                      false,
                      {},
                      QT_TRANSLATE_NOOP("kerf", "Feed rate of the positioning, or FMAX")});
    if (reset) return;
    fields.push_back({{},
                      SpecialFieldKind::Choice,
                      false,
                      {"", "SEQ+", "SEQ-"},
                      QT_TRANSLATE_NOOP("kerf", "Solution: SEQ+ or SEQ- (empty: the machine's)")});
    fields.push_back({{},
                      SpecialFieldKind::Choice,
                      false,
                      {"", "COORD ROT", "TABLE ROT"},
                      QT_TRANSLATE_NOOP("kerf", "Transformation: COORD ROT or TABLE ROT")});
}

QString name(const SpecialField& field) {
    return field.word.isEmpty() ? specialFieldDescription(field) : field.word;
}

QString fieldWords(const SpecialField& field, const QString& raw) {
    const QString value = raw.trimmed().toUpper();
    switch (field.kind) {
        case SpecialFieldKind::Number:
            return field.word + signedText(value);
        case SpecialFieldKind::Choice:
            return value;
        case SpecialFieldKind::Length:
            return field.word + plainText(value);
        case SpecialFieldKind::Retract:
            return value == QLatin1String("MAX") ? QStringLiteral("MB MAX")
                                                 : field.word + plainText(value);
        case SpecialFieldKind::Feed:
            return value == QLatin1String("FMAX") ? value : field.word + plainText(value);
        case SpecialFieldKind::ProgramName:
            return raw.trimmed();
    }
    return {};
}

}  // namespace

QString specialFunctionTitle(SpecialFunction function) {
    switch (function) {
        case SpecialFunction::PlaneSpatial:
            return QStringLiteral("PLANE SPATIAL");
        case SpecialFunction::PlaneProjected:
            return QStringLiteral("PLANE PROJECTED");
        case SpecialFunction::PlaneEuler:
            return QStringLiteral("PLANE EULER");
        case SpecialFunction::PlaneVector:
            return QStringLiteral("PLANE VECTOR");
        case SpecialFunction::PlanePoints:
            return QStringLiteral("PLANE POINTS");
        case SpecialFunction::PlaneRelative:
            return QStringLiteral("PLANE RELATIV");
        case SpecialFunction::PlaneAxial:
            return QStringLiteral("PLANE AXIAL");
        case SpecialFunction::PlaneReset:
            return QStringLiteral("PLANE RESET");
        case SpecialFunction::Tcpm:
            return QStringLiteral("FUNCTION TCPM");
        case SpecialFunction::ResetTcpm:
            return QStringLiteral("FUNCTION RESET TCPM");
        case SpecialFunction::M128:
            return QStringLiteral("M128");
        case SpecialFunction::M129:
            return QStringLiteral("M129");
        case SpecialFunction::SelectProgram:
            return QStringLiteral("SEL PGM");
        case SpecialFunction::CallSelectedProgram:
            return QStringLiteral("CALL SELECTED PGM");
        case SpecialFunction::CallProgram:
            return QStringLiteral("CALL PGM");
    }
    return {};
}

std::vector<SpecialField> specialFields(SpecialFunction function) {
    std::vector<SpecialField> fields;
    switch (function) {
        case SpecialFunction::PlaneSpatial:
            fields = {numberField("SPA", QT_TRANSLATE_NOOP("kerf", "Spatial angle A [°]")),
                      numberField("SPB", QT_TRANSLATE_NOOP("kerf", "Spatial angle B [°]")),
                      numberField("SPC", QT_TRANSLATE_NOOP("kerf", "Spatial angle C [°]"))};
            break;
        case SpecialFunction::PlaneProjected:
            fields = {
                numberField("PROPR", QT_TRANSLATE_NOOP(
                                         "kerf", "Projected angle in the principal plane [°]")),
                numberField("PROMIN",
                            QT_TRANSLATE_NOOP("kerf", "Projected angle in the minor plane [°]")),
                numberField("ROT", QT_TRANSLATE_NOOP("kerf", "Rotation in the tilted plane [°]"))};
            break;
        case SpecialFunction::PlaneEuler:
            fields = {numberField("EULPR", QT_TRANSLATE_NOOP("kerf", "Precession angle [°]")),
                      numberField("EULNU", QT_TRANSLATE_NOOP("kerf", "Nutation angle [°]")),
                      numberField("EULROT", QT_TRANSLATE_NOOP("kerf", "Rotation angle [°]"))};
            break;
        case SpecialFunction::PlaneVector:
            for (const char* word : {"BX", "BY", "BZ"})
                fields.push_back(
                    numberField(word, QT_TRANSLATE_NOOP("kerf", "Base vector (X direction)")));
            for (const char* word : {"NX", "NY", "NZ"})
                fields.push_back(numberField(word, QT_TRANSLATE_NOOP("kerf", "Normal vector")));
            break;
        case SpecialFunction::PlanePoints:
            for (const char* word : {"P1X", "P1Y", "P1Z"})
                fields.push_back(
                    numberField(word, QT_TRANSLATE_NOOP("kerf", "First point (origin of X)")));
            for (const char* word : {"P2X", "P2Y", "P2Z"})
                fields.push_back(
                    numberField(word, QT_TRANSLATE_NOOP("kerf", "Second point (on the X axis)")));
            for (const char* word : {"P3X", "P3Y", "P3Z"})
                fields.push_back(
                    numberField(word, QT_TRANSLATE_NOOP("kerf", "Third point (in the plane)")));
            break;
        case SpecialFunction::PlaneRelative:
            fields = {{{},
                       SpecialFieldKind::Choice,
                       true,
                       {"SPA", "SPB", "SPC"},
                       QT_TRANSLATE_NOOP("kerf", "Axis of the incremental spatial angle")},
                      numberField("", QT_TRANSLATE_NOOP("kerf", "Incremental angle [°]"))};
            break;
        case SpecialFunction::PlaneAxial:
            for (const char* word : {"A", "B", "C"})
                fields.push_back(numberField(
                    word, QT_TRANSLATE_NOOP("kerf", "Axis angle [°] (empty: not moved)"), false));
            break;
        case SpecialFunction::Tcpm:
            fields = {{{},
                       SpecialFieldKind::Choice,
                       false,
                       {"F TCP", ""},
                       QT_TRANSLATE_NOOP("kerf", "Feed rate at the tool tip")},
                      {{},
                       SpecialFieldKind::Choice,
                       false,
                       {"AXIS POS", ""},
                       QT_TRANSLATE_NOOP("kerf", "Rotary axes: machine positions")},
                      {{},
                       SpecialFieldKind::Choice,
                       false,
                       {"PATHCTRL AXIS", ""},
                       QT_TRANSLATE_NOOP("kerf", "Path: the axes interpolate linearly")},
                      {{},
                       SpecialFieldKind::Choice,
                       false,
                       {"REFPNT TIP-TIP", ""},
                       QT_TRANSLATE_NOOP("kerf", "Reference point: the tool tip")}};
            break;
        case SpecialFunction::M128:
            fields = {{"F",
                       SpecialFieldKind::Length,
                       false,
                       {},
                       QT_TRANSLATE_NOOP("kerf", "Feed rate of the compensating moves")}};
            break;
        case SpecialFunction::SelectProgram:
        case SpecialFunction::CallProgram:
            fields = {{{},
                       SpecialFieldKind::ProgramName,
                       true,
                       {},
                       QT_TRANSLATE_NOOP("kerf", "Program name, e.g. PART or TNC:\\DIR\\PART.H")}};
            break;
        case SpecialFunction::PlaneReset:
        case SpecialFunction::ResetTcpm:
        case SpecialFunction::M129:
        case SpecialFunction::CallSelectedProgram:
            break;
    }
    if (isPlane(function)) addPositioning(fields, function == SpecialFunction::PlaneReset);
    return fields;
}

std::optional<QString> checkSpecialField(const SpecialField& field, const QString& text) {
    const QString value = text.trimmed().toUpper();
    if (value.isEmpty()) {
        if (!field.required) return std::nullopt;
        return QCoreApplication::translate("kerf", "%1: enter a value").arg(name(field));
    }
    bool ok = true;
    switch (field.kind) {
        case SpecialFieldKind::Number:
            ok = matchesWhole(kNumberPattern, value) || matchesWhole(kParameterPattern, value);
            break;
        case SpecialFieldKind::Choice:
            ok = field.choices.contains(value);
            break;
        case SpecialFieldKind::Length:
            ok = positive(value);
            break;
        case SpecialFieldKind::Retract:
            ok = value == QLatin1String("MAX") || positive(value);
            break;
        case SpecialFieldKind::Feed:
            ok = value == QLatin1String("FMAX") || positive(value);
            break;
        case SpecialFieldKind::ProgramName:
            ok = matchesWhole(kProgramName, value);
            break;
    }
    if (ok) return std::nullopt;
    return QCoreApplication::translate("kerf", "%1: \"%2\" is not allowed here")
        .arg(name(field), text.trimmed());
}

QString specialFieldDescription(const SpecialField& field) {
    return QCoreApplication::translate("kerf", field.description);
}

std::optional<QString> checkSpecialFunction(SpecialFunction function, const QStringList& values) {
    const std::vector<SpecialField> fields = specialFields(function);
    for (size_t i = 0; i < fields.size(); ++i) {
        if (auto error = checkSpecialField(fields[i], values.value(static_cast<int>(i))))
            return error;
    }
    auto value = [&](const QString& word) {
        for (size_t i = 0; i < fields.size(); ++i)
            if (fields[i].word == word) return values.value(static_cast<int>(i)).trimmed();
        return QString();
    };
    if (function == SpecialFunction::PlaneAxial && value("A").isEmpty() && value("B").isEmpty() &&
        value("C").isEmpty())
        return QCoreApplication::translate("kerf", "PLANE AXIAL: enter the angle of A, B or C");
    if (!isPlane(function)) return std::nullopt;
    // The positioning choice is the first field after the form's own.
    QString positioning;
    for (size_t i = 0; i < fields.size(); ++i)
        if (fields[i].choices.contains(QStringLiteral("STAY")))
            positioning = values.value(static_cast<int>(i)).trimmed().toUpper();
    if (positioning == QLatin1String("STAY") &&
        !(value("MB").isEmpty() && value("DIST").isEmpty() && value("F").isEmpty()))
        return QCoreApplication::translate("kerf",
                                           "STAY moves nothing: leave MB, DIST and F empty");
    if (positioning == QLatin1String("TURN") && !value("DIST").isEmpty())
        return QCoreApplication::translate("kerf", "DIST belongs to MOVE");
    return std::nullopt;
}

QString writeSpecialFunction(SpecialFunction function, const QStringList& values,
                             program::Dialect dialect) {
    const std::vector<SpecialField> fields = specialFields(function);
    if (function == SpecialFunction::CallProgram && dialect == program::Dialect::TncIso)
        return QLatin1Char('%') + values.value(0).trimmed();
    QStringList words{specialFunctionTitle(function)};
    for (size_t i = 0; i < fields.size(); ++i) {
        const QString value = values.value(static_cast<int>(i));
        if (value.trimmed().isEmpty()) continue;
        if (function == SpecialFunction::SelectProgram) {
            words << QLatin1Char('"') + value.trimmed() + QLatin1Char('"');
        } else if (function == SpecialFunction::PlaneRelative && i == 1) {
            words.last() += signedText(value.trimmed().toUpper());  // "SPB" + "+10"
        } else {
            words << fieldWords(fields[i], value);
        }
    }
    return words.join(QLatin1Char(' '));
}

}  // namespace kerf::ui
