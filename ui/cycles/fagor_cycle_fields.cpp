#include "ui/cycles/fagor_cycle_fields.h"

#include <QCoreApplication>
#include <algorithm>
#include <cstring>
#include <string>

#include "core/base/diagnostic.h"
#include "core/base/translate.h"
#include "core/interp/fagor/block_parser.h"
#include "core/interp/fagor/g_functions.h"

namespace kerf::ui {

namespace {

// The cycles that share parameter meanings (spec part 2 §2).
enum class Family { Profile, Stock, Straight, Curved, Drill, Thread, Groove };

Family familyOf(int g) {
    switch (g) {
        case 66:
            return Family::Profile;
        case 68:
        case 69:
            return Family::Stock;
        case 81:
        case 82:
            return Family::Straight;
        case 84:
        case 85:
            return Family::Curved;
        case 83:
            return Family::Drill;
        case 86:
        case 87:
            return Family::Thread;
        default:
            return Family::Groove;
    }
}

struct Meaning {
    const char* text;
    FagorUnit unit;
};

// The meaning of `letter` in the cycles of `family`, after the manual's parameter tables.
Meaning meaningOf(Family family, char letter) {
    const bool roughing = family == Family::Profile || family == Family::Stock ||
                          family == Family::Straight || family == Family::Curved;
    const bool profileByLabels = family == Family::Profile || family == Family::Stock;
    using enum FagorUnit;
    switch (letter) {
        case 'X':
            return {KERF_TR_NOOP("X of the start point"), Length};
        case 'Z':
            return {KERF_TR_NOOP("Z of the start point"), Length};
        case 'Q':
            if (profileByLabels) return {KERF_TR_NOOP("Program that holds the profile"), None};
            return {KERF_TR_NOOP("X of the end point"), Length};
        case 'R':
            if (family == Family::Drill)
                return {KERF_TR_NOOP("Peck reduction factor (tapping: tapping type)"), None};
            return {KERF_TR_NOOP("Z of the end point"), Length};
        case 'S':
            return {KERF_TR_NOOP("Label of the first profile block"), None};
        case 'E':
            if (family == Family::Thread) return {KERF_TR_NOOP("Minimum infeed increment"), Length};
            return {KERF_TR_NOOP("Label of the last profile block"), None};
        case 'C':
            if (profileByLabels) return {KERF_TR_NOOP("Pass step"), Length};
            if (roughing) return {KERF_TR_NOOP("Maximum pass step"), Length};
            if (family == Family::Drill)
                return {KERF_TR_NOOP("Rapid approach to the previous peck"), Length};
            if (family == Family::Thread) return {KERF_TR_NOOP("Thread pitch"), Length};
            return {KERF_TR_NOOP("Maximum step between plunges"), Length};
        case 'I':
            if (family == Family::Profile) return {KERF_TR_NOOP("Stock to remove"), Length};
            if (family == Family::Curved)
                return {KERF_TR_NOOP("X distance from the start point to the arc centre"), Length};
            if (family == Family::Drill)
                return {KERF_TR_NOOP("Depth from the start point"), Length};
            return {KERF_TR_NOOP("Total thread depth"), Length};
        case 'K':
            if (family == Family::Stock)
                return {KERF_TR_NOOP("Feed for plunging into valleys"), Feed};
            if (family == Family::Curved)
                return {KERF_TR_NOOP("Z distance from the start point to the arc centre"), Length};
            if (family == Family::Thread)
                return {KERF_TR_NOOP("Measured point of a thread to repass"), Length};
            return {KERF_TR_NOOP("Dwell at the bottom"), Hundredths};
        case 'A':
            if (family == Family::Thread) return {KERF_TR_NOOP("Infeed angle"), Degrees};
            return {KERF_TR_NOOP("Main machining axis (0: Z, 1: X)"), None};
        case 'L':
            if (roughing) return {KERF_TR_NOOP("Finishing allowance in X"), Length};
            if (family == Family::Drill) return {KERF_TR_NOOP("Minimum peck depth"), Length};
            return {KERF_TR_NOOP("Finishing pass allowance"), Length};
        case 'M':
            if (roughing) return {KERF_TR_NOOP("Finishing allowance in Z"), Length};
            return {KERF_TR_NOOP("Pitch change per revolution"), Length};
        case 'H':
            if (family == Family::Drill)
                return {KERF_TR_NOOP("Rapid retract after each peck"), Length};
            return {KERF_TR_NOOP("Feed of the finishing pass"), Feed};
        case 'F':
            return {KERF_TR_NOOP("Feed of the final roughing pass"), Feed};
        case 'D':
            if (family == Family::Thread)
                return {KERF_TR_NOOP("Safety distance from the thread start"), Length};
            return {KERF_TR_NOOP("Safety distance for the retract"), Length};
        case 'B':
            if (family == Family::Drill) return {KERF_TR_NOOP("Peck depth (0: tapping)"), Length};
            return {KERF_TR_NOOP("Depth of the first pass (negative: constant step)"), Length};
        case 'J':
            return {KERF_TR_NOOP("Thread run-out"), Length};
        case 'W':
            return {KERF_TR_NOOP("Spindle angle at the start or measured point"), Degrees};
        case 'V':
            return {KERF_TR_NOOP("Number of thread starts"), None};
        default:
            return {"", None};
    }
}

// The lengths of cycle G<g> that the manual gives in radius (spec part 2 §2), though X is
// programmed as a diameter: G68's pass step C2 takes 4 mm off the diameter.
bool inRadius(int g, char letter) {
    const char* letters = "";
    switch (g) {
        case 66:
            letters = "ICL";
            break;
        case 68:
        case 81:
            letters = "CL";
            break;
        case 69:
        case 82:
        case 85:
            letters = "L";
            break;
        case 84:
            letters = "CLI";
            break;
        case 86:
            letters = "IBDL";
            break;
        case 88:
            letters = "D";
            break;
        case 89:
            letters = "C";
            break;
        default:
            break;
    }
    return std::strchr(letters, letter) != nullptr;
}

QString translated(const fagor::Problem& problem) {
    const QString text = QCoreApplication::translate("kerf", problem.messageTemplate.c_str());
    return QString::fromStdString(substituteArgs(text.toStdString(), problem.args));
}

QString missingMessage(int g, char letter) {
    // The interpreter's own message for a missing required parameter.
    const QString text = QCoreApplication::translate("kerf", "{1} needs its parameter {2}");
    return QString::fromStdString(
        substituteArgs(text.toStdString(), {"G" + std::to_string(g), std::string(1, letter)}));
}

// Reads `block` as the interpreter does (no parameter values: P words read as 0).
bool parseBlock(const QString& block, fagor::ParsedBlock& out, fagor::Problem& problem) {
    fagor::BlockParser parser(nullptr);
    const std::string text = block.toStdString();
    const bool ok = parser.parse(text, false, out);
    problem = parser.problem();
    return ok;
}

QString gWord(int g) {
    return QStringLiteral("G%1").arg(g);
}

}  // namespace

const std::vector<int>& fagorCycleNumbers() {
    static const std::vector<int> numbers = {66, 68, 69, 81, 82, 83, 84, 85, 86, 87, 88, 89};
    return numbers;
}

QString fagorCycleName(int g) {
    const fagor::GFunction* function = fagor::gFunction(g);
    return function ? QCoreApplication::translate("kerf", function->meaning) : QString();
}

std::vector<FagorField> fagorCycleFields(int g) {
    std::vector<FagorField> fields;
    const fagor::CycleSyntax* syntax = fagor::cycleSyntax(g);
    if (!syntax) return fields;
    for (const fagor::CycleParameter& p : syntax->parameters) {
        const Meaning meaning = meaningOf(familyOf(g), p.letter);
        const bool radius = meaning.unit == FagorUnit::Length && inRadius(g, p.letter);
        fields.push_back({&p, meaning.text, radius ? FagorUnit::RadiusLength : meaning.unit});
    }
    return fields;
}

QString fagorUnitText(FagorUnit unit) {
    switch (unit) {
        case FagorUnit::Length:
            return QStringLiteral("mm");
        case FagorUnit::RadiusLength:
            return QCoreApplication::translate("kerf", "mm (radius)");
        case FagorUnit::Feed:
            return QStringLiteral("mm/rev (G95)");
        case FagorUnit::Degrees:
            return QStringLiteral("°");
        case FagorUnit::Hundredths:
            return QStringLiteral("1/100 s");
        case FagorUnit::None:
            return {};
    }
    return {};
}

QString fagorFormatText(const fagor::CycleParameter& p) {
    // The manual's format codes: ±5.5, 5.5, 4 (whole number of four digits), 0 … 1.
    if (p.decDigits == 0) {
        if (p.maxValue != 0) return QStringLiteral("0 … %1").arg(p.maxValue);
        return QString::number(p.intDigits);
    }
    return QStringLiteral("%1%2.%3")
        .arg(p.sign ? QStringLiteral("±") : QString())
        .arg(p.intDigits)
        .arg(p.decDigits);
}

std::optional<QString> checkFagorField(int g, const FagorField& field, const QString& text) {
    const QString value = text.trimmed();
    const char letter = field.parameter->letter;
    if (value.isEmpty()) {
        if (field.required()) return missingMessage(g, letter);
        return std::nullopt;
    }
    const QString prefix = gWord(g) + QLatin1Char(' ');
    fagor::ParsedBlock out;
    fagor::Problem problem;
    // The interpreter reads the word alone; a missing other parameter is not this field's fault.
    if (!parseBlock(prefix + QLatin1Char(letter) + value, out, problem) &&
        problem.offset >= static_cast<size_t>(prefix.size()))
        return translated(problem);
    // Another word, or a comment or repetition that would swallow the parameters after it.
    const bool oneWord = std::all_of(value.begin(), value.end(), [](QChar c) {
        return c.isLetterOrNumber() || c == QLatin1Char('.') || c == QLatin1Char('+') ||
               c == QLatin1Char('-');
    });
    bool otherWord = false;
    for (const fagor::CycleParameter& other : fagor::cycleSyntax(g)->parameters)
        otherWord = otherWord || (other.letter != letter && out.iso.cycle.has(other.letter));
    if (!oneWord || otherWord) return QCoreApplication::translate("kerf", "One value per field");
    return std::nullopt;
}

QString writeFagorCycleBlock(int g, const std::vector<FagorField>& fields,
                             const QStringList& values) {
    QString block = gWord(g);
    for (size_t i = 0; i < fields.size(); ++i) {
        const QString value = values.value(static_cast<int>(i)).trimmed();
        if (!value.isEmpty()) block += QLatin1Char(' ') + fields[i].label() + value;
    }
    return block;
}

std::optional<FagorBlockRefusal> checkFagorCycleBlock(int g, const std::vector<FagorField>& fields,
                                                      const QStringList& values) {
    for (size_t i = 0; i < fields.size(); ++i) {
        if (const auto message = checkFagorField(g, fields[i], values.value(static_cast<int>(i))))
            return FagorBlockRefusal{static_cast<int>(i), *message};
    }
    fagor::ParsedBlock out;
    fagor::Problem problem;
    if (parseBlock(writeFagorCycleBlock(g, fields, values), out, problem)) return std::nullopt;
    // The rules between parameters (M with K in G86): the field of the word the error is at.
    FagorBlockRefusal refusal{-1, translated(problem)};
    size_t at = 0;
    for (size_t i = 0; i < fields.size(); ++i) {
        const fagor::WordValue& word = out.iso.cycle[fields[i].parameter->letter];
        if (word.present && word.offset <= problem.offset && word.offset >= at) {
            at = word.offset;
            refusal.field = static_cast<int>(i);
        }
    }
    return refusal;
}

std::optional<FagorCycleInLine> readFagorCycleLine(const QString& line) {
    fagor::ParsedBlock out;
    fagor::Problem problem;
    parseBlock(line, out, problem);  // an incomplete cycle is still opened to be completed
    const fagor::CycleWords& cycle = out.iso.cycle;
    if (cycle.g < 0) return std::nullopt;
    const std::vector<FagorField> fields = fagorCycleFields(cycle.g);
    std::vector<int> starts;
    for (const FagorField& field : fields) {
        if (cycle.has(field.parameter->letter))
            starts.push_back(cycle[field.parameter->letter].offset);
    }
    std::sort(starts.begin(), starts.end());
    int end = static_cast<int>(line.indexOf(QLatin1Char(';')));
    if (end < 0) end = static_cast<int>(line.size());
    FagorCycleInLine found;
    found.g = cycle.g;
    found.first = cycle.offset;
    int last = cycle.offset + static_cast<int>(gWord(cycle.g).size());
    for (const FagorField& field : fields) {
        if (!cycle.has(field.parameter->letter)) {
            found.values << QString();
            continue;
        }
        const int start = cycle[field.parameter->letter].offset;
        const auto next = std::upper_bound(starts.begin(), starts.end(), start);
        const int stop = next != starts.end() ? std::min(*next, end) : end;
        const QString value = line.mid(start + 1, stop - start - 1).trimmed();
        found.values << value;
        last = std::max(last, static_cast<int>(line.indexOf(value, start + 1)) +
                                  static_cast<int>(value.size()));
    }
    found.length = last - found.first;
    return found;
}

}  // namespace kerf::ui
