// Special functions in DIN/ISO: the TNC writes SEL TABLE, SEL PGM, CALL SELECTED PGM, GLOBAL
// DEF, PATTERN DEF, FUNCTION ..., PLANE, CONTOUR DEF and the contour formula (SEL CONTOUR,
// DECLARE CONTOUR, QC) with their conversational words inside an ISO block
// ("N50 SEL TABLE "DATUMS" *"); they have no G code.
#include <array>
#include <string_view>

#include "core/interp/klartext/cursor.h"
#include "core/interp/tnciso/detail/translation_context.h"

namespace kerf::tnciso {

using klartext::isDigit;
using klartext::isLetter;
using klartext::upper;

namespace {

bool startsWithWord(std::string_view text, size_t at, std::string_view word) {
    if (text.size() - at < word.size()) return false;
    for (size_t i = 0; i < word.size(); ++i) {
        if (upper(text[at + i]) != word[i]) return false;
    }
    const size_t end = at + word.size();
    return end == text.size() || !isLetter(text[end]);
}

// The end of a segment's text before the block end '*' (outside quotes) and trailing blanks.
size_t segmentEnd(std::string_view text, size_t from, size_t to) {
    bool quoted = false;
    for (size_t i = from; i < to; ++i) {
        if (text[i] == '"') quoted = !quoted;
        if (!quoted && (text[i] == ';' || text[i] == '*')) {
            // '*' ends the block, unless a formula goes on after it ("Q1 = 2 * 3" is no QC).
            size_t after = i + 1;
            while (after < to && (text[after] == ' ' || text[after] == '\t'))
                ++after;
            if (text[i] == ';' || after == to || text[after] == ';') {
                to = i;
                break;
            }
        }
    }
    while (to > from && (text[to - 1] == ' ' || text[to - 1] == '\t'))
        --to;
    return to;
}

}  // namespace

bool isSpecialFunction(std::string_view text, size_t at) {
    static constexpr std::array<std::string_view, 7> kHeads = {
        "SEL", "GLOBAL", "PATTERN", "FUNCTION", "PLANE", "DECLARE", "CONTOUR"};
    for (std::string_view head : kHeads) {
        if (startsWithWord(text, at, head)) return true;
    }
    // "CALL SELECTED PGM" calls what SEL PGM selected ("CALL" alone is no ISO word).
    if (startsWithWord(text, at, "CALL")) {
        size_t next = at + 4;
        while (next < text.size() && (text[next] == ' ' || text[next] == '\t'))
            ++next;
        if (startsWithWord(text, next, "SELECTED")) return true;
    }
    // "QC10 = QC1 | QC2": a contour formula.
    return at + 2 < text.size() && upper(text[at]) == 'Q' && upper(text[at + 1]) == 'C' &&
           isDigit(text[at + 2]);
}

void IsoTranslator::translateSpecialFunction(Context& c, size_t at) {
    ConversationalBlock& b = c.newBlock();
    const std::string_view text = c.text;
    for (size_t s = 0; s < c.line.segments.size(); ++s) {
        size_t start = s == 0 ? at : c.line.segments[s].joinedOffset;
        const size_t limit =
            s + 1 < c.line.segments.size() ? c.line.segments[s + 1].joinedOffset : text.size();
        while (start < limit && (text[start] == ' ' || text[start] == '\t'))
            ++start;
        if (start >= limit) continue;
        const size_t end = segmentEnd(text, start, limit);
        if (s > 0) b.newLine();
        b.add(text.substr(start, end - start), start, end - start);
    }
}

}  // namespace kerf::tnciso
