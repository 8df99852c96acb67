#include "core/interp/klartext/cycle_parameter_spans.h"

#include "core/interp/klartext/cursor.h"

namespace kerf::klartext {

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

// "Q200=" or "QS500 =" at `at`.
bool parameterAt(std::string_view text, size_t at, size_t to) {
    if (upper(text[at]) != 'Q') return false;
    size_t i = at + 1;
    if (i < to && upper(text[i]) == 'S') ++i;
    const size_t digits = i;
    while (i < to && isDigit(text[i]))
        ++i;
    if (i == digits) return false;
    while (i < to && isBlank(text[i]))
        ++i;
    return i < to && text[i] == '=';
}

}  // namespace

CycleParameterSpans cycleParameterSpans(std::string_view text, size_t from, size_t to) {
    CycleParameterSpans spans;
    spans.commentAt = to;
    bool inString = false;
    for (size_t i = from; i < to; ++i) {
        const char c = text[i];
        if (c == '"') inString = !inString;
        if (inString) continue;
        if (c == ';') {
            spans.commentAt = i;
            break;
        }
        if ((i == from || isBlank(text[i - 1])) && parameterAt(text, i, to))
            spans.starts.push_back(i);
    }
    return spans;
}

}  // namespace kerf::klartext
