#include "core/interp/tnciso/iso_words.h"

#include "core/base/translate.h"
#include "core/interp/klartext/cursor.h"

namespace kerf::tnciso {

using klartext::isDigit;
using klartext::isLetter;
using klartext::upper;

namespace {

size_t skipBlanks(std::string_view text, size_t at) {
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t'))
        ++at;
    return at;
}

size_t digitsEnd(std::string_view text, size_t at) {
    while (at < text.size() && isDigit(text[at]))
        ++at;
    return at;
}

bool fail(klartext::ParseProblem& problem, size_t offset, const char* messageTemplate,
          std::vector<std::string> args = {}) {
    problem = klartext::ParseProblem{offset, "syntax", messageTemplate, std::move(args)};
    return false;
}

// "Q200=" or "QS500 =" at `at`: a cycle parameter starts.
bool parameterStarts(std::string_view text, size_t at) {
    if (at >= text.size() || upper(text[at]) != 'Q') return false;
    size_t i = at + 1;
    if (i < text.size() && upper(text[i]) == 'S') ++i;
    const size_t digits = digitsEnd(text, i);
    if (digits == i) return false;
    i = skipBlanks(text, digits);
    return i < text.size() && text[i] == '=';
}

}  // namespace

std::string gNumber(int number) {
    return (number < 10 ? "0" : "") + std::to_string(number);
}

const IsoWord* IsoWords::find(std::string_view key) const {
    if (key[0] >= 'A' && key[0] <= 'Z' && !hasLetter(key[0])) return nullptr;
    for (const IsoWord& w : words) {
        if (w.key == key) return &w;
    }
    return nullptr;
}

const IsoWord* IsoWords::findG(int number) const {
    for (const IsoWord& w : words) {
        if (w.key == "G" && w.number == number) return &w;
    }
    return nullptr;
}

size_t valueEnd(std::string_view text, size_t at) {
    size_t i = skipBlanks(text, at);
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) i = skipBlanks(text, i + 1);
    if (i >= text.size()) return std::string_view::npos;
    if (text[i] == '(') {
        int depth = 0;
        for (; i < text.size(); ++i) {
            if (text[i] == '(') ++depth;
            if (text[i] == ')' && --depth == 0) return i + 1;
        }
        return text.size();  // unbalanced: the formula parser reports it
    }
    if (upper(text[i]) == 'Q') {
        size_t j = i + 1;
        if (j < text.size() && (upper(text[j]) == 'L' || upper(text[j]) == 'R')) ++j;
        const size_t end = digitsEnd(text, j);
        return end == j ? std::string_view::npos : end;
    }
    const size_t whole = digitsEnd(text, i);
    size_t end = whole;
    if (end < text.size() && (text[end] == '.' || text[end] == ',') && end + 1 < text.size() &&
        isDigit(text[end + 1])) {
        end = digitsEnd(text, end + 1);
    } else if (end < text.size() && text[end] == '.') {
        end = digitsEnd(text, end + 1);
    }
    return end == i ? std::string_view::npos : end;
}

bool scanWords(std::string_view text, size_t from, IsoWords& out, klartext::ParseProblem& problem) {
    out.words.clear();
    out.parametersAt = std::string_view::npos;
    out.letters = 0;
    size_t i = from;
    while (true) {
        i = skipBlanks(text, i);
        if (i >= text.size() || text[i] == ';') return true;
        if (text[i] == '*') {
            const size_t after = skipBlanks(text, i + 1);
            if (after >= text.size() || text[after] == ';') return true;
            return fail(problem, after, KERF_TR_NOOP("text after the block end '*'"));
        }
        IsoWord word;
        word.offset = i;
        if (text[i] == '"') {
            const size_t close = text.find('"', i + 1);
            if (close == std::string_view::npos) {
                return fail(problem, i, KERF_TR_NOOP("closing '\"' missing"));
            }
            word.key = text.substr(i, 1);
            word.value = text.substr(i + 1, close - i - 1);
            word.valueOffset = i + 1;
            out.words.push_back(word);
            i = close + 1;
            continue;
        }
        if (!isLetter(text[i])) {
            return fail(problem, i, KERF_TR_NOOP("unexpected '{1}'"), {std::string(1, text[i])});
        }
        if (parameterStarts(text, i)) {
            out.parametersAt = i;
            return true;
        }
        const char letter = upper(text[i]);
        const char next = i + 1 < text.size() ? upper(text[i + 1]) : '\0';
        out.letters |= 1u << (letter - 'A');
        size_t keyEnd = i + 1;
        if ((letter == 'F' && (next == 'M' || next == 'A')) || (letter == 'P' && next == 'A')) {
            while (keyEnd < text.size() && isLetter(text[keyEnd]))
                ++keyEnd;  // FMAX, FAUTO, PAT: no value
            word.key = text.substr(i, keyEnd - i);
            out.words.push_back(word);
            i = keyEnd;
            continue;
        }
        // FU, FZ, DL, DR, DR2 and the vectors of a 3D-compensated straight NX NY NZ TX TY TZ.
        const bool surfaceVector =
            (letter == 'N' || letter == 'T') && (next == 'X' || next == 'Y' || next == 'Z');
        if ((letter == 'F' && (next == 'U' || next == 'Z')) ||
            (letter == 'D' && (next == 'L' || next == 'R')) || surfaceVector) {
            keyEnd = i + 2;
            if (letter == 'D' && next == 'R' && keyEnd < text.size() && text[keyEnd] == '2') {
                ++keyEnd;
            }
        }
        word.key = text.substr(i, keyEnd - i);
        if (letter == 'G' || letter == 'M' || letter == 'P' || letter == 'D') {
            if (keyEnd == i + 1) {
                const size_t end = digitsEnd(text, keyEnd);
                if (end == keyEnd || end - keyEnd > 4) {
                    return fail(problem, i, KERF_TR_NOOP("number expected after '{1}'"),
                                {std::string(1, letter)});
                }
                word.number = 0;
                for (size_t d = keyEnd; d < end; ++d)
                    word.number = word.number * 10 + (text[d] - '0');
                keyEnd = end;
                if (letter == 'G' || letter == 'M' || letter == 'D') {
                    out.words.push_back(word);
                    i = keyEnd;
                    continue;
                }
            }
        }
        const size_t valueAt = skipBlanks(text, keyEnd);
        if (letter == 'P' && valueAt < text.size() && text[valueAt] == '"') {
            out.words.push_back(word);  // P01 "name": the name is a word of its own
            i = valueAt;
            continue;
        }
        if (letter == 'T' && valueAt < text.size() && text[valueAt] == '"') {
            out.words.push_back(word);  // T "name"
            i = valueAt;
            continue;
        }
        // "L1,2" is label 1 twice, not a decimal comma.
        const bool labelNumber = letter == 'L' && valueAt < text.size() && isDigit(text[valueAt]);
        const size_t end = labelNumber ? digitsEnd(text, valueAt) : valueEnd(text, keyEnd);
        if (end == std::string_view::npos && valueAt < text.size() &&
            (text[valueAt] == '+' || text[valueAt] == '-')) {
            // G55 (probing cycle 0) names its probing axis and direction as "X-".
            const size_t after = valueAt + 1;
            const bool signAlone = after >= text.size() || text[after] == ' ' ||
                                   text[after] == '\t' || text[after] == '*';
            if (!signAlone || out.findG(55) == nullptr || word.key.size() != 1) {
                return fail(problem, valueAt, KERF_TR_NOOP("value expected after '{1}'"),
                            {std::string(word.key)});
            }
            word.valueOffset = valueAt;
            word.value = text.substr(valueAt, 1);
            out.words.push_back(word);
            i = after;
            continue;
        }
        if (end == std::string_view::npos) {
            // Words that stand without a value: mirror axes (G28 X Y), G79 PAT.
            word.valueOffset = keyEnd;
            out.words.push_back(word);
            i = keyEnd;
            continue;
        }
        word.valueOffset = valueAt;
        word.value = text.substr(valueAt, end - valueAt);
        i = end;
        if (letter == 'L' && i < text.size() && text[i] == ',') {
            const size_t repeatEnd = digitsEnd(text, i + 1);
            if (repeatEnd == i + 1 || repeatEnd - i - 1 > 5) {
                return fail(problem, i + 1, KERF_TR_NOOP("repeat count expected after ','"));
            }
            int repeat = 0;
            for (size_t d = i + 1; d < repeatEnd; ++d)
                repeat = repeat * 10 + (text[d] - '0');
            word.repeat = repeat;
            i = repeatEnd;
        }
        out.words.push_back(word);
    }
}

}  // namespace kerf::tnciso
