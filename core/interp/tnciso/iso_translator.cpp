#include "core/interp/tnciso/iso_translator.h"

#include <algorithm>
#include <utility>

#include "core/base/translate.h"
#include "core/interp/klartext/cursor.h"
#include "core/interp/tnciso/detail/translation_context.h"
#include "core/program/line_reader.h"

namespace kerf::tnciso {

using klartext::isDigit;
using klartext::isLetter;
using klartext::upper;

// ---- ConversationalBlock ---------------------------------------------------------------------

void ConversationalBlock::add(std::string_view text, size_t isoOffset, size_t isoLength,
                              bool joined) {
    m_pieces.push_back({m_text.size(), text.size(), isoOffset, isoLength});
    m_text.append(text);
    if (!joined) m_text.push_back(' ');
}

void ConversationalBlock::clear() {
    m_text.clear();
    m_pieces.clear();
    m_lineStarts.assign(1, 0);
}

ConversationalBlock& Translation::newBlock() {
    if (m_count == m_blocks.size()) m_blocks.emplace_back();
    ConversationalBlock& block = m_blocks[m_count++];
    block.clear();
    return block;
}

void Translation::clear() {
    m_count = 0;
    direct.reset();
    blockNumber = -1;
    hidden = false;
}

size_t ConversationalBlock::isoOffset(size_t offset) const {
    if (m_pieces.empty()) return 0;
    auto it = std::upper_bound(m_pieces.begin(), m_pieces.end(), offset,
                               [](size_t o, const Piece& p) { return o < p.start; });
    const Piece& piece = it == m_pieces.begin() ? *it : *std::prev(it);
    const size_t inside = offset >= piece.start ? offset - piece.start : 0;
    // The blank after a piece belongs to what follows ("+5 DIV +Q2": the operator's word).
    if (inside >= piece.length && it != m_pieces.end() && it != m_pieces.begin()) {
        return it->isoOffset;
    }
    // A verbatim piece maps character by character; a written keyword maps to its ISO word.
    if (piece.isoLength == piece.length) return piece.isoOffset + std::min(inside, piece.length);
    return piece.isoOffset + std::min(inside, piece.isoLength);
}

// ---- helpers ---------------------------------------------------------------------------------

namespace {

size_t skipBlanks(std::string_view text, size_t at) {
    while (at < text.size() && (text[at] == ' ' || text[at] == '\t'))
        ++at;
    return at;
}

bool isMotion(int g) {
    return g == 0 || g == 1 || g == 2 || g == 3 || g == 5 || g == 6 ||
           (g >= 10 && g <= 16 && g != 14);
}

// Parameter cycles: 2xx, SL 12x/139 (cycles 20-29, 39), probing 4xx and 14xx.
bool isParameterCycle(int g) {
    return (g >= 120 && g <= 129) || g == 139 || (g >= 200 && g <= 299) || (g >= 400 && g <= 499) ||
           (g >= 1400 && g <= 1499);
}

// The end of a block's text before its ';' comment (quotes respected) and the block end '*'.
size_t contentEnd(std::string_view text, size_t from) {
    bool quoted = false;
    size_t end = text.size();
    for (size_t i = from; i < text.size(); ++i) {
        if (text[i] == '"') quoted = !quoted;
        if (text[i] == ';' && !quoted) {
            end = i;
            break;
        }
    }
    while (end > from && (text[end - 1] == ' ' || text[end - 1] == '\t'))
        --end;
    if (end > from && text[end - 1] == '*') --end;
    while (end > from && (text[end - 1] == ' ' || text[end - 1] == '\t'))
        --end;
    return end;
}

}  // namespace

bool IsoTranslator::fail(size_t offset, const char* messageTemplate,
                         std::vector<std::string> args) {
    m_problem = klartext::ParseProblem{offset, "syntax", messageTemplate, std::move(args)};
    return false;
}

bool IsoTranslator::translate(const program::LogicalLine& line, Translation& out) {
    out.clear();
    const std::string_view text = line.text;
    if (text.size() > program::kMaxBlockCharacters) {
        return fail(program::kMaxBlockCharacters,
                    KERF_TR_NOOP("the block is longer than 60000 characters"));
    }
    size_t i = skipBlanks(text, 0);
    if (i < text.size() && text[i] == '/') {
        out.hidden = true;
        i = skipBlanks(text, i + 1);
        while (i < text.size() && isDigit(text[i]))
            ++i;
        i = skipBlanks(text, i);
    }
    if (i + 1 < text.size() && upper(text[i]) == 'N' && isDigit(text[i + 1])) {
        int64_t number = 0;
        for (++i; i < text.size() && isDigit(text[i]); ++i) {
            number = std::min<int64_t>(number * 10 + (text[i] - '0'), 999999999);
        }
        out.blockNumber = number;
        i = skipBlanks(text, i);
    }
    if (i >= text.size() || text[i] == ';' || text[i] == '*') return true;
    const bool programStart = std::exchange(m_atProgramStart, false);
    Context c{line, text, out, m_words, m_used};
    if (text[i] == '%') return translateProgramWord(c, i, programStart);
    if (upper(text[i]) == 'D' && i + 1 < text.size() && isDigit(text[i + 1])) {
        return translateDFunction(c, i);
    }
    if (isSpecialFunction(text, i)) {
        translateSpecialFunction(c, i);
        return true;
    }
    // "Q1 = ...", "QS2 = ...": a formula, as in conversational programs.
    if (upper(text[i]) == 'Q') {
        size_t j = i + 1;
        if (j < text.size() && std::string_view("LRSlrs").find(text[j]) != std::string_view::npos) {
            ++j;
        }
        while (j < text.size() && isDigit(text[j]))
            ++j;
        if (j > i + 1 && skipBlanks(text, j) < text.size() && text[skipBlanks(text, j)] == '=') {
            const size_t end = contentEnd(text, i);
            c.newBlock().add(text.substr(i, end - i), i, end - i);
            return true;
        }
    }
    // Cycles with a parameter list: G200 DRILLING Q200=2 ...
    if (upper(text[i]) == 'G' && i + 1 < text.size() && isDigit(text[i + 1])) {
        int g = 0;
        size_t j = i + 1;
        for (; j < text.size() && isDigit(text[j]) && g < 100000; ++j)
            g = g * 10 + (text[j] - '0');
        if (isParameterCycle(g)) {
            IsoWord word;
            word.key = text.substr(i, 1);
            word.number = g;
            word.offset = i;
            word.valueOffset = j;
            return translateCycle(c, word);
        }
    }
    if (!scanWords(text, i, m_words, m_problem)) return false;
    if (m_words.parametersAt != std::string_view::npos) {
        return fail(m_words.parametersAt,
                    KERF_TR_NOOP("cycle parameters belong to a cycle block (G2xx, G4xx ...)"));
    }
    m_used.assign(m_words.words.size(), false);
    if (!translateWords(c)) return false;
    for (size_t w = 0; w < m_words.words.size(); ++w) {
        if (c.used[w]) continue;
        const IsoWord& word = m_words.words[w];
        std::string shown(word.key);
        if (word.number >= 0) shown += std::to_string(word.number);
        return fail(word.offset, KERF_TR_NOOP("'{1}' is not allowed in this block"), {shown});
    }
    return true;
}

bool IsoTranslator::translateProgramWord(Context& c, size_t at, bool programStart) {
    std::string_view text = c.text;
    size_t end = at + 1;
    while (end < text.size() && text[end] != ' ' && text[end] != '\t' && text[end] != ';' &&
           text[end] != '*')
        ++end;
    const std::string_view name = text.substr(at + 1, end - at - 1);
    if (name.empty()) return fail(at + 1, KERF_TR_NOOP("program name expected after '%'"));
    if (!scanWords(text, end, m_words, m_problem)) return false;
    std::optional<bool> inch;
    for (const IsoWord& w : m_words.words) {
        if (w.key == "G" && (w.number == 70 || w.number == 71) && !inch) {
            inch = w.number == 70;
            continue;
        }
        std::string shown(w.key);
        if (w.number >= 0) shown += std::to_string(w.number);
        return fail(w.offset, KERF_TR_NOOP("'{1}' is not allowed in this block"), {shown});
    }
    ConversationalBlock& b = c.newBlock();
    if (!inch) {
        b.add("CALL PGM", at, 1);
        b.add(name, at + 1, name.size());
        return true;
    }
    // "%NAME G71" opens the program; "N99999999 %NAME G71" (or any later block with the name of
    // the open program) ends it; the first block of a program opens it.
    const bool ending = !programStart && (c.out.blockNumber == 99999999 ||
                                          (!m_open.empty() && m_open.back() == name));
    b.add(ending ? "END PGM" : "BEGIN PGM", at, 1);
    b.add(name, at + 1, name.size());
    b.add(*inch ? "INCH" : "MM", at, 1);
    if (ending) {
        if (!m_open.empty()) m_open.pop_back();
    } else {
        m_open.emplace_back(name);
        c.out.blockNumber = 0;  // the header counts as numbered, as BEGIN PGM is block 0
        m_motion = -1;
        m_incremental = false;
    }
    return true;
}

bool IsoTranslator::translateDFunction(Context& c, size_t at) {
    std::string_view text = c.text;
    size_t i = at + 1;
    int fn = 0;
    while (i < text.size() && isDigit(text[i]) && fn < 1000)
        fn = fn * 10 + (text[i++] - '0');
    const size_t fnEnd = i;
    if (i < text.size() && text[i] == ':') ++i;
    ConversationalBlock& b = c.newBlock();
    b.add("FN " + std::to_string(fn) + ":", at, fnEnd - at);
    const bool arithmetic = fn <= 8 || fn == 13;
    const bool jump = fn >= 9 && fn <= 12;
    if (!arithmetic && !jump && fn != 14) {
        // D15 ... D29 take the conversational words after the number ("D18: SYSREAD Q1 = ID..").
        const size_t from = skipBlanks(text, i);
        const size_t end = contentEnd(text, from);
        if (end > from) b.add(text.substr(from, end - from), from, end - from);
        return true;
    }
    // The target parameter, then P01, P02 (P03: the label of a jump).
    i = skipBlanks(text, i);
    if (arithmetic) {
        const size_t targetEnd = valueEnd(text, i);
        if (targetEnd == std::string_view::npos || upper(text[i]) != 'Q') {
            return fail(i, KERF_TR_NOOP("Q parameter expected"));
        }
        b.add(text.substr(i, targetEnd - i), i, targetEnd - i);
        b.add("=", i, 0);
        i = targetEnd;
    } else if (jump) {
        b.add("IF", at, 0);
    } else {
        b.add("ERROR =", at, 0);
    }
    static const char* const kOperators[] = {"",    "+",   "-",   "*",  "DIV", "SQRT", "SIN",
                                             "COS", "LEN", "EQU", "NE", "GT",  "LT",   "ANG"};
    const int operands = fn == 0 || (fn >= 5 && fn <= 7) || fn == 14 ? 1 : 2;
    for (int p = 1; p <= operands + (jump ? 1 : 0); ++p) {
        i = skipBlanks(text, i);
        const bool named = i + 2 < text.size() && upper(text[i]) == 'P' && text[i + 1] == '0' &&
                           text[i + 2] == static_cast<char>('0' + p);
        if (!named) {
            return fail(i, KERF_TR_NOOP("P0{1} expected"), {std::to_string(p)});
        }
        const size_t valueAt = skipBlanks(text, i + 3);
        if (p == 3) {
            b.add("GOTO LBL", i, 3);
            size_t end = valueAt;
            if (end < text.size() && text[end] == '"') {  // a named label: P03 "NAME"
                const size_t close = text.find('"', end + 1);
                end = close == std::string_view::npos ? end : close + 1;
            }
            while (end < text.size() && (isDigit(text[end]) || isLetter(text[end])))
                ++end;
            if (end == valueAt) return fail(valueAt, KERF_TR_NOOP("label number expected"));
            b.add(text.substr(valueAt, end - valueAt), valueAt, end - valueAt);
            i = end;
            continue;
        }
        const size_t end = valueEnd(text, valueAt);
        if (end == std::string_view::npos) return fail(valueAt, KERF_TR_NOOP("value expected"));
        if (p == 1 && fn >= 5 && fn <= 7) b.add(kOperators[fn], i, 0);
        if (p == 2) b.add(kOperators[fn], i, 0);
        b.add(text.substr(valueAt, end - valueAt), valueAt, end - valueAt);
        i = end;
    }
    i = skipBlanks(text, i);
    if (i < text.size() && text[i] != ';' && text[i] != '*') {
        return fail(i, KERF_TR_NOOP("unexpected '{1}'"), {std::string(1, text[i])});
    }
    return true;
}

bool IsoTranslator::translateWords(Context& c) {
    // G functions first: they say what the block is.
    std::optional<int> motion, comp, plane;
    std::vector<const IsoWord*> others;
    for (size_t w = 0; w < c.words.words.size(); ++w) {
        const IsoWord& word = c.words.words[w];
        if (word.key != "G") continue;
        const int g = word.number;
        if (isMotion(g)) {
            if (motion) return fail(word.offset, KERF_TR_NOOP("two path functions in one block"));
            motion = g;
        } else if (g >= 40 && g <= 42) {
            comp = g;
        } else if (g >= 17 && g <= 19) {
            plane = g;
        } else if (g == 90 || g == 91) {
            m_incremental = g == 91;
        } else if (g == 7 || g == 43 || g == 44) {
            c.out.direct = klartext::Deferred{
                g == 7 ? "G07 (paraxial positioning)" : "G43/G44 (paraxial radius compensation)",
                std::string(c.text)};
            std::fill(c.used.begin(), c.used.end(), true);
            return true;
        } else if (g == 70 || g == 71) {
            return fail(word.offset, KERF_TR_NOOP("G70/G71 belong to the program header '%NAME'"));
        } else {
            others.push_back(&word);
            continue;
        }
        c.used[w] = true;
    }
    if (others.size() > 1) {
        return fail(others[1]->offset, KERF_TR_NOOP("G{1} and G{2} cannot share a block"),
                    {gNumber(others[0]->number), gNumber(others[1]->number)});
    }
    auto markG = [&](int g) {
        for (size_t w = 0; w < c.words.words.size(); ++w) {
            if (c.words.words[w].key == "G" && c.words.words[w].number == g) c.used[w] = true;
        }
    };
    auto addComp = [&](ConversationalBlock& b) {
        if (!comp) return;
        const IsoWord* g = c.words.findG(*comp);
        b.add(*comp == 40 ? "R0" : (*comp == 41 ? "RL" : "RR"), g->offset, c.end(*g) - g->offset);
    };
    auto axisOf = [](int g) { return g == 18 ? "Y" : (g == 19 ? "X" : "Z"); };
    const bool axesPresent =
        std::any_of(c.words.words.begin(), c.words.words.end(), [](const IsoWord& w) {
            return w.key.size() == 1 &&
                   std::string_view("XYZABCUVW").find(w.key[0]) != std::string_view::npos;
        });
    auto addAxes = [&](ConversationalBlock& b, bool incremental) {
        for (size_t w = 0; w < c.words.words.size(); ++w) {
            const IsoWord& word = c.words.words[w];
            if (c.used[w] || word.key.size() != 1 ||
                std::string_view("XYZABCUVW").find(word.key[0]) == std::string_view::npos) {
                continue;
            }
            c.used[w] = true;
            if (word.value.empty()) {
                fail(word.valueOffset, KERF_TR_NOOP("value expected after '{1}'"),
                     {std::string(word.key)});
                return false;
            }
            c.addWord(b, word, std::string(1, upper(word.key[0])), incremental);
        }
        return true;
    };

    if (!others.empty()) {
        const IsoWord& g = *others.front();
        bool handled = false;
        if (!translateOldCycle(c, g, handled)) return false;
        if (handled) {
            markG(g.number);
            return true;
        }
        markG(g.number);
        switch (g.number) {
            case 98: {  // label
                ConversationalBlock& b = c.newBlock();
                b.add("LBL", g.offset, 3);
                if (const IsoWord* name = c.take("\"")) {
                    b.add("\"" + std::string(name->value) + "\"", name->offset,
                          name->value.size() + 2);
                    // G98 L"NAME" as well as G98 "NAME"
                    const IsoWord* l = c.words.find("L");
                    if (l != nullptr && l->value.empty()) c.take("L");
                } else if (const IsoWord* l = c.take("L")) {
                    if (l->repeat)
                        return fail(l->offset, KERF_TR_NOOP("a label has no repeat count"));
                    b.add(l->value, l->valueOffset, l->value.size());
                } else {
                    return fail(c.end(g), KERF_TR_NOOP("label number expected (G98 L1)"));
                }
                return true;
            }
            case 99: {  // tool definition
                const IsoWord* t = c.take("T");
                if (t == nullptr) return fail(c.end(g), KERF_TR_NOOP("tool number expected (T)"));
                ConversationalBlock& b = c.newBlock();
                b.add("TOOL DEF", g.offset, 3);
                b.add(t->value, t->valueOffset, t->value.size());
                if (const IsoWord* l = c.take("L")) c.addWord(b, *l, "L");
                if (const IsoWord* r = c.take("R")) c.addWord(b, *r, "R");
                return true;
            }
            case 30:
            case 31: {  // blank form
                ConversationalBlock& b = c.newBlock();
                b.add(g.number == 30 ? "BLK FORM 0.1" : "BLK FORM 0.2", g.offset, 3);
                if (g.number == 30) {
                    b.add(axisOf(plane.value_or(17)), g.offset, 0);
                } else if (plane) {
                    return fail(c.words.findG(*plane)->offset,
                                KERF_TR_NOOP("the plane belongs to G30"));
                }
                plane.reset();
                return addAxes(b, g.number == 31 && m_incremental);
            }
            case 38: {
                ConversationalBlock& b = c.newBlock();
                b.add("STOP", g.offset, 3);
                c.addM(b);
                return true;
            }
            case 79: {
                ConversationalBlock& b = c.newBlock();
                b.add("CYCL CALL", g.offset, 3);
                if (const IsoWord* pat = c.take("PAT")) b.add("PAT", pat->offset, 3);
                c.addFeedAndM(b);
                return true;
            }
            case 24:
            case 25:
            case 26:
            case 27: {  // chamfer, rounding, tangential approach and departure
                const IsoWord* r = c.take("R");
                if (r == nullptr || r->value.empty()) {
                    return fail(c.end(g), KERF_TR_NOOP("R expected after G{1}"),
                                {gNumber(g.number)});
                }
                ConversationalBlock& b = c.newBlock();
                if (g.number == 24) {
                    b.add("CHF", g.offset, 3);
                    b.add(r->value, r->valueOffset, r->value.size());
                } else {
                    b.add("RND", g.offset, 3);
                    c.addWord(b, *r, "R");
                }
                if (const IsoWord* f = c.take("F")) c.addWord(b, *f, "F");
                return true;
            }
            case 29: {  // the last programmed position becomes the pole
                c.newBlock().add("CC", g.offset, 3);
                return true;
            }
            default:
                return fail(g.offset, KERF_TR_NOOP("unknown G function G{1}"), {gNumber(g.number)});
        }
    }

    // Label calls and tool calls.
    if (const IsoWord* l = c.take("L")) {
        ConversationalBlock& b = c.newBlock();
        b.add("CALL LBL", l->offset, 1);
        if (const IsoWord* name = l->value.empty() ? c.take("\"") : nullptr) {
            b.add("\"" + std::string(name->value) + "\"", name->offset, name->value.size() + 2);
        } else if (l->value.empty() && l->valueOffset < c.text.size() &&
                   upper(c.text[l->valueOffset]) == 'N') {
            return fail(l->offset,
                        KERF_TR_NOOP("LN is the conversational straight line with 3D tool "
                                     "compensation; in ISO write G01 X Y Z NX NY NZ [TX TY TZ]"));
        } else if (l->value.empty()) {
            return fail(l->valueOffset, KERF_TR_NOOP("label number expected"));
        } else {
            b.add(l->value, l->valueOffset, l->value.size());
        }
        if (l->repeat && *l->repeat > 0) b.add("REP " + std::to_string(*l->repeat), c.end(*l), 0);
        return true;
    }
    if (const IsoWord* t = c.take("T")) {
        ConversationalBlock& b = c.newBlock();
        b.add("TOOL CALL", t->offset, 1);
        if (const IsoWord* name = c.take("\"")) {
            b.add("\"" + std::string(name->value) + "\"", name->offset, name->value.size() + 2);
        } else if (!t->value.empty()) {
            b.add(t->value, t->valueOffset, t->value.size());
        }
        if (plane) {
            const IsoWord* g = c.words.findG(*plane);
            b.add(axisOf(*plane), g->offset, c.end(*g) - g->offset);
            plane.reset();
        }
        for (const char* key : {"S", "F", "DL", "DR", "DR2"}) {
            if (const IsoWord* w = c.take(key)) c.addWord(b, *w, key);
        }
        return true;
    }
    // The seed's ISO code of cycle 18 is G18, also the plane ZX: with its parameters P01/P02
    // and neither T nor G30 it is the cycle.
    if (plane == 18 && c.words.hasLetter('P')) return translateThreadCutting(c);
    if (plane) {
        return fail(c.words.findG(*plane)->offset,
                    KERF_TR_NOOP("G17/G18/G19 belong to a tool call (T) or a blank (G30)"));
    }

    // A circle centre (pole) I, J, K, before the path of the same block.
    const IsoWord* centre[3] = {c.take("I"), c.take("J"), c.take("K")};
    if (centre[0] || centre[1] || centre[2]) {
        ConversationalBlock& b = c.newBlock();
        const IsoWord* first = centre[0] ? centre[0] : (centre[1] ? centre[1] : centre[2]);
        b.add("CC", first->offset, 0);
        const char* const kAxes[] = {"X", "Y", "Z"};
        for (int a = 0; a < 3; ++a) {
            if (centre[a] == nullptr) continue;
            if (centre[a]->value.empty()) {
                return fail(centre[a]->valueOffset, KERF_TR_NOOP("value expected after '{1}'"),
                            {std::string(centre[a]->key)});
            }
            c.addWord(b, *centre[a], kAxes[a], m_incremental);
        }
    }
    if (motion) m_motion = *motion;
    const bool pathWords = axesPresent || c.has("R") || c.has("H");
    if (pathWords || (motion && !c.has("S"))) {
        if (m_motion < 0) {
            return fail(c.words.words.front().offset,
                        KERF_TR_NOOP("no path function (G00, G01, G02 ...) is active"));
        }
        if (!translateMotion(c, m_motion)) return false;
        ConversationalBlock& b = c.out.lastBlock();
        addComp(b);
        if (!addAxes(b, m_incremental)) return false;
        if (!addSurfaceVectors(c, b)) return false;
        c.addFeedAndM(b);
        return true;
    }
    if (comp || c.has("F")) {  // "G40", "F200 M3": compensation, feed and M functions alone
        ConversationalBlock& b = c.newBlock();
        b.add("L", c.words.words.front().offset, 0);
        addComp(b);
        c.addFeedAndM(b);
        return true;
    }
    if (const IsoWord* s = c.take("S")) {  // a new spindle speed
        ConversationalBlock& b = c.newBlock();
        b.add("TOOL CALL", s->offset, 0);
        c.addWord(b, *s, "S");
        if (c.has("M")) c.addM(c.newBlock());
        return true;
    }
    if (c.has("M")) c.addM(c.newBlock());
    return true;
}

bool IsoTranslator::addSurfaceVectors(Context& c, ConversationalBlock& b) {
    const IsoWord* vectors[6];
    bool any = false;
    static const char* const kKeys[] = {"NX", "NY", "NZ", "TX", "TY", "TZ"};
    for (int k = 0; k < 6; ++k) {
        vectors[k] = c.take(kKeys[k]);
        any = any || vectors[k] != nullptr;
        if (vectors[k] != nullptr && vectors[k]->value.empty()) {
            return fail(vectors[k]->valueOffset, KERF_TR_NOOP("value expected after '{1}'"),
                        {kKeys[k]});
        }
    }
    if (!any) return true;
    if (m_motion != 0 && m_motion != 1) {
        const IsoWord* first = *std::find_if(std::begin(vectors), std::end(vectors),
                                             [](const IsoWord* w) { return w != nullptr; });
        return fail(first->offset, KERF_TR_NOOP("surface vectors NX NY NZ TX TY TZ belong to a "
                                                "straight line G00/G01"));
    }
    for (int k = 0; k < 6; ++k) {
        if (vectors[k] != nullptr) c.addWord(b, *vectors[k], kKeys[k]);
    }
    return true;
}

bool IsoTranslator::translateMotion(Context& c, int motion) {
    ConversationalBlock& b = c.newBlock();
    const IsoWord* g = c.words.findG(motion);
    const size_t at = g ? g->offset : c.words.words.front().offset;
    const size_t length = g ? c.end(*g) - g->offset : 0;
    const bool polar = motion >= 10;
    const IsoWord* r = c.take("R");
    const IsoWord* h = polar ? c.take("H") : nullptr;
    if (r != nullptr && r->value.empty()) {
        return fail(r->valueOffset, KERF_TR_NOOP("value expected after '{1}'"), {"R"});
    }
    switch (motion) {
        case 0:
        case 1:
            // With a surface normal NX NY NZ the straight line is 3D-compensated: LN.
            b.add(c.has("NX") || c.has("NY") || c.has("NZ") ? "LN" : "L", at, length);
            break;
        case 2:
        case 3:
        case 5:
            b.add(r ? "CR" : "C", at, length);
            break;
        case 6:
            b.add("CT", at, length);
            break;
        case 10:
        case 11:
            b.add("LP", at, length);
            break;
        case 16:
            b.add("CTP", at, length);
            break;
        default:
            b.add("CP", at, length);
            break;
    }
    if (r != nullptr) c.addWord(b, *r, polar ? "PR" : "R", polar && m_incremental);
    if (h != nullptr) {
        if (h->value.empty())
            return fail(h->valueOffset, KERF_TR_NOOP("value expected after '{1}'"), {"H"});
        c.addWord(b, *h, "PA", m_incremental);
    }
    if (motion == 2 || motion == 12) b.add("DR-", at, length);
    if (motion == 3 || motion == 13) b.add("DR+", at, length);
    if (motion == 0 || motion == 10) {
        if (const IsoWord* f = c.words.find("F")) {
            return fail(f->offset, KERF_TR_NOOP("a feed rate F is not allowed with rapid G{1}"),
                        {motion == 0 ? "00" : "10"});
        }
        b.add("FMAX", at, length);
    }
    return true;
}

}  // namespace kerf::tnciso
