// Cycles in DIN/ISO: parameter cycles (G200 ... Q200=2 ...) and the old cycles that ISO writes as
// one G block (G54 X+10 is CYCL DEF 7.0 and 7.1 X+10).
#include <algorithm>
#include <array>
#include <vector>

#include "core/base/translate.h"
#include "core/interp/klartext/cursor.h"
#include "core/interp/klartext/cycle_parameter_spans.h"
#include "core/interp/tnciso/detail/translation_context.h"

namespace kerf::tnciso {

using klartext::isDigit;
using klartext::upper;

namespace {

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '*'))
        text.remove_suffix(1);
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    return text;
}

}  // namespace

bool IsoTranslator::translateCycle(Context& c, const IsoWord& g) {
    const std::string_view text = c.text;
    const int number = g.number >= 120 && g.number <= 139 ? g.number - 100 : g.number;
    const bool probing = g.number >= 400;
    ConversationalBlock& b = c.newBlock();
    b.add(probing ? "TCH PROBE" : "CYCL DEF", g.offset, 1);
    b.add(std::to_string(number), g.offset + 1, g.valueOffset - g.offset - 1);
    // Each segment (physical line) holds a name or parameters "Qnnn=value" side by side, and may
    // end in a comment; every parameter becomes a parameter line of the conversational block.
    bool parameterSeen = false;
    for (size_t s = 0; s < c.line.segments.size(); ++s) {
        const size_t segStart = s == 0 ? g.valueOffset : c.line.segments[s].joinedOffset;
        const size_t segEnd =
            s + 1 < c.line.segments.size() ? c.line.segments[s + 1].joinedOffset : text.size();
        const klartext::CycleParameterSpans spans =
            klartext::cycleParameterSpans(text, segStart, segEnd);
        const std::vector<size_t>& starts = spans.starts;
        const size_t comment = spans.commentAt;
        const size_t firstParameter = starts.empty() ? comment : starts.front();
        const std::string_view before = trimmed(text.substr(segStart, firstParameter - segStart));
        if (!before.empty()) {
            if (parameterSeen) {
                const size_t at = text.find(before, segStart);
                return fail(at, KERF_TR_NOOP("cycle parameter Qnnn= expected"));
            }
            b.add(before, text.find(before, segStart), before.size());  // the cycle's name
        }
        for (size_t k = 0; k < starts.size(); ++k) {
            const size_t end = k + 1 < starts.size() ? starts[k + 1] : comment;
            const std::string_view parameter = trimmed(text.substr(starts[k], end - starts[k]));
            b.newLine();
            b.add(parameter, starts[k], parameter.size());
            parameterSeen = true;
        }
        if (!starts.empty() && comment < segEnd) {
            const std::string_view note = trimmed(text.substr(comment, segEnd - comment));
            b.add(note, comment, note.size());
        }
    }
    return true;
}

bool IsoTranslator::translateOldCycle(Context& c, const IsoWord& g, bool& handled) {
    struct OldCycle {
        int g;
        int cycle;
        const char* name;
    };
    static constexpr std::array<OldCycle, 11> kOld = {{{4, 9, "DWELL TIME"},
                                                       {28, 8, "MIRROR IMAGE"},
                                                       {36, 13, "ORIENTATION"},
                                                       {37, 14, "CONTOUR"},
                                                       {39, 12, "PGM CALL"},
                                                       {53, 7, "DATUM SHIFT"},
                                                       {54, 7, "DATUM SHIFT"},
                                                       {62, 32, "TOLERANCE"},
                                                       {72, 11, "SCALING"},
                                                       {73, 10, "ROTATION"},
                                                       {80, 19, "WORKING PLANE"}}};
    if (g.number == 55) {
        handled = true;
        return translateReferencePlane(c, g);
    }
    const OldCycle* old = nullptr;
    for (const OldCycle& o : kOld) {
        if (o.g == g.number) old = &o;
    }
    if (old == nullptr) return true;
    handled = true;
    const std::string prefix = "CYCL DEF " + std::to_string(old->cycle);
    c.newBlock().add(prefix + ".0 " + old->name, g.offset, 3);
    ConversationalBlock& b = c.newBlock();
    b.add(prefix + ".1", g.offset, 3);
    auto value = [&](const char* key, const char* word, bool incremental) -> bool {
        const IsoWord* w = c.take(key);
        if (w == nullptr || w->value.empty()) {
            return fail(w ? w->valueOffset : c.end(g), KERF_TR_NOOP("{1} expected after G{2}"),
                        {key, gNumber(g.number)});
        }
        c.addWord(b, *w, word, incremental);
        return true;
    };
    auto axes = [&](bool withValues) -> bool {
        for (size_t w = 0; w < c.words.words.size(); ++w) {
            const IsoWord& word = c.words.words[w];
            if (c.used[w] || word.key.size() != 1 ||
                std::string_view("XYZABCUVW").find(upper(word.key[0])) == std::string_view::npos) {
                continue;
            }
            c.used[w] = true;
            if (!withValues) {
                b.add(std::string(1, upper(word.key[0])), word.offset, 1);
            } else if (word.value.empty()) {
                return fail(word.valueOffset, KERF_TR_NOOP("value expected after '{1}'"),
                            {std::string(word.key)});
            } else {
                c.addWord(b, word, std::string(1, upper(word.key[0])), m_incremental);
            }
        }
        return true;
    };
    switch (g.number) {
        case 4:
            return value("F", "DWELL ", false);
        case 36:
            return value("S", "ANGLE ", false);
        case 62:
            return value("T", "T", false);
        case 72:
            return value("F", "SCL ", false);
        case 73:
            return value("H", "ROT", m_incremental);
        case 54:
        case 80:
            return axes(true);
        case 28:
            return axes(false);
        case 53:
            return value("P", "#", false);
        case 39:
        case 37: {
            std::string list;
            size_t at = c.end(g);
            while (const IsoWord* p = c.take("P")) {
                at = p->offset;
                if (const IsoWord* name = c.take("\"")) {
                    list += std::string(name->value);
                } else {
                    list += std::string(p->value);
                }
                list += "/";
            }
            if (const IsoWord* name = c.take("\"")) list += std::string(name->value) + "/";
            if (list.empty()) {
                return fail(at, g.number == 39
                                    ? KERF_TR_NOOP("program name expected (P01 \"NAME\")")
                                    : KERF_TR_NOOP("contour labels expected (P01 1)"));
            }
            list.pop_back();
            b.add(g.number == 39 ? "PGM " + list : "CONTOUR LABEL " + list, at, 0);
            return true;
        }
        default:
            return true;
    }
}

// G55 P01 5 X- X+5 Y+0 Z-5: touch-probe cycle 0 REF. PLANE (spec 4: ISO G55), the result in
// Q5, probing along X-, from the pre-position X+5 Y+0 Z-5. The spec names G55 but not its
// words: these mirror the conversational sub-blocks 0.0 and 0.1.
bool IsoTranslator::translateReferencePlane(Context& c, const IsoWord& g) {
    const IsoWord* p = c.take("P");
    const bool digits =
        p != nullptr && !p->value.empty() &&
        std::all_of(p->value.begin(), p->value.end(), [](char ch) { return isDigit(ch); });
    if (p == nullptr || p->number != 1 || !digits) {
        return fail(p != nullptr ? p->offset : c.end(g), KERF_TR_NOOP("P0{1} expected"), {"1"});
    }
    const IsoWord* direction = nullptr;
    for (size_t w = 0; w < c.words.words.size(); ++w) {
        const IsoWord& word = c.words.words[w];
        if (c.used[w] || (word.value != "+" && word.value != "-")) continue;
        if (direction != nullptr ||
            std::string_view("XYZ").find(upper(word.key[0])) == std::string_view::npos) {
            return fail(word.offset, KERF_TR_NOOP("'{1}' is not allowed in this block"),
                        {std::string(word.key) + std::string(word.value)});
        }
        c.used[w] = true;
        direction = &word;
    }
    if (direction == nullptr) {
        return fail(c.end(*p),
                    KERF_TR_NOOP("G55: the probing axis with its direction (X-, Y+ ...) expected"));
    }
    ConversationalBlock& head = c.newBlock();
    head.add("TCH PROBE 0.0 REF. PLANE Q", g.offset, 3, true);
    head.add(p->value, p->valueOffset, p->value.size());
    head.add(std::string(1, upper(direction->key[0])) + std::string(direction->value),
             direction->offset, 2);
    ConversationalBlock& b = c.newBlock();
    b.add("TCH PROBE 0.1", g.offset, 3);
    for (size_t w = 0; w < c.words.words.size(); ++w) {
        const IsoWord& word = c.words.words[w];
        if (c.used[w] || word.key.size() != 1 ||
            std::string_view("XYZ").find(upper(word.key[0])) == std::string_view::npos) {
            continue;
        }
        c.used[w] = true;
        c.addWord(b, word, std::string(1, upper(word.key[0])), false);
    }
    return true;
}

// G18 P01 depth P02 pitch: cycle 18 THREAD CUTTING (its ISO code is the plane's, G18).
bool IsoTranslator::translateThreadCutting(Context& c) {
    const IsoWord& g = *c.words.findG(18);
    c.newBlock().add("CYCL DEF 18.0 THREAD CUTTING", g.offset, 3);
    size_t at = c.end(g);
    for (const auto& [number, word] : {std::pair{1, "DEPTH "}, std::pair{2, "PITCH "}}) {
        const IsoWord* p = c.take("P");
        if (p == nullptr || p->number != number || p->value.empty()) {
            return fail(p != nullptr ? p->offset : at, KERF_TR_NOOP("P{1} expected after G18"),
                        {"0" + std::to_string(number)});
        }
        at = c.end(*p);
        ConversationalBlock& b = c.newBlock();
        b.add("CYCL DEF 18." + std::to_string(number), g.offset, 3);
        c.addWord(b, *p, word, false);
    }
    return true;
}

}  // namespace kerf::tnciso
