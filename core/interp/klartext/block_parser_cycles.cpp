// CYCL DEF, GLOBAL DEF and PATTERN DEF blocks.
#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/base/translate.h"
#include "core/interp/klartext/block_parser.h"
#include "core/interp/klartext/cycle_parameter_spans.h"

namespace kerf::klartext {

namespace {

std::string upperText(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        c = upper(c);
    return out;
}

// A value follows: a number, a sign, a formula in parentheses or a Q parameter.
bool valueStarts(std::string_view rest) {
    if (rest.empty()) return false;
    const char c = rest[0];
    if (isDigit(c) || c == '.' || c == '+' || c == '-' || c == '(') return true;
    if (upper(c) != 'Q' || rest.size() < 2) return false;
    const char next = upper(rest[1]);
    return isDigit(next) || next == 'L' || next == 'R';
}

// Where the text of segment `s` ends in the joined line.
size_t segmentEnd(const program::LogicalLine& line, size_t s) {
    return s + 1 < line.segments.size() ? line.segments[s + 1].joinedOffset : line.text.size();
}

// "CYCL DEF9 .0": older files put blanks between the cycle number and ".sub". Only one digit
// followed by a blank or the end counts, so a cycle name such as ".5MM" stays a name.
struct SubNumber {
    int number = 0;
    size_t end = 0;
};
std::optional<SubNumber> detachedSubNumber(std::string_view text, size_t at) {
    size_t i = at;
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t'))
        ++i;
    if (i == at || i + 1 >= text.size() || (text[i] != '.' && text[i] != ',')) return std::nullopt;
    if (!isDigit(text[i + 1])) return std::nullopt;
    if (i + 2 < text.size() && text[i + 2] != ' ' && text[i + 2] != '\t' && text[i + 2] != ';') {
        return std::nullopt;
    }
    return SubNumber{text[i + 1] - '0', i + 2};
}

}  // namespace

bool BlockParser::failAt(size_t offset, const char* code, const char* messageTemplate,
                         std::vector<std::string> args) {
    m_problem = ParseProblem{offset, code, messageTemplate, std::move(args)};
    return false;
}

// A signed value; blanks may follow the sign ("Z + 0").
bool BlockParser::parseValue(Cursor& cur, double& out) {
    cur.skipBlanks();
    double sign = 1.0;
    if (cur.peekRaw() == '+' || cur.peekRaw() == '-') {
        sign = cur.peekRaw() == '-' ? -1.0 : 1.0;
        cur.setPosition(cur.position() + 1);
        cur.skipBlanks();
    }
    const size_t at = cur.position();
    FormulaParser formula(cur, m_env);
    auto value = formula.wordValue();
    if (!value) {
        if (formula.problem()) {
            m_problem = *formula.problem();
            return false;
        }
        return failAt(at, "syntax", KERF_TR_NOOP("value expected"));
    }
    out = sign * *value;
    return true;
}

bool BlockParser::parseCycleDef(const program::LogicalLine& line, size_t at, ParsedBlock& out,
                                bool probe) {
    const std::string_view text = line.text;
    Cursor cur(text, at);
    CycleDefinition b;
    auto number = cur.unsignedNumber();
    if (!number || *number < 0.0 || *number > 9999.0) {
        return failAt(cur.position(), "syntax", KERF_TR_NOOP("cycle number expected"));
    }
    const double whole = std::floor(*number + 1e-9);
    b.number = static_cast<int>(whole);
    std::string_view numberText = text.substr(0, cur.position());
    const size_t separator = numberText.find_last_of(".,");
    const bool oldStyle =
        separator != std::string_view::npos && separator > numberText.find_last_of(' ');
    if (oldStyle) {
        b.subNumber = static_cast<int>(std::lround((*number - whole) * 10.0));
    } else if (auto sub = detachedSubNumber(text, cur.position())) {
        b.subNumber = sub->number;
        cur.setPosition(sub->end);
    }
    // Only the first segment is the header; further segments are "Qnnn=value ;comment".
    const size_t headerEnd = line.segments.size() > 1 ? line.segments[1].joinedOffset : text.size();
    const size_t headerTextEnd = std::max(headerEnd, cur.position());
    // Parameters may follow the name on the header line (new-style cycles only).
    const CycleParameterSpans onHeader = cycleParameterSpans(text, cur.position(), headerTextEnd);
    const size_t parametersAt = b.subNumber < 0 && !onHeader.starts.empty()
                                    ? onHeader.starts.front()
                                    : std::string_view::npos;
    Cursor hc(text.substr(0, std::min(headerTextEnd, parametersAt)), cur.position());
    const size_t restAt = hc.position();
    std::string header(hc.restUntilComment());
    if (b.subNumber >= 0) {
        // Sub-blocks of the cycles Kerf runs are words with values; the others (12.1 PGM with
        // a file name, obsolete and SL cycles) stay text.
        static constexpr int kWordCycles[] = {1,  2,  3,  4,  5,  7,  8,  9,
                                              10, 11, 13, 17, 18, 19, 26, 32};
        // Touch-probe sub-blocks with positions or a vector: 0.1, 1.2 and 4.2.
        const bool probeWords =
            probe && ((b.number == 0 && b.subNumber == 1) || (b.number == 1 && b.subNumber == 2) ||
                      (b.number == 4 && b.subNumber == 2));
        const bool words =
            probeWords || (!probe && std::find(std::begin(kWordCycles), std::end(kWordCycles),
                                               b.number) != std::end(kWordCycles));
        if (b.subNumber > 0 && words) {
            if (!parseCycleWords(text.substr(0, std::max(headerEnd, cur.position())), restAt,
                                 b.words)) {
                return false;
            }
        }
        b.rest = std::move(header);
    } else {
        b.name = std::move(header);
    }
    if (!parseCycleParameters(line, b.parameters, parametersAt)) return false;
    out.statement = std::move(b);
    return true;
}

bool BlockParser::parseCycleParameters(const program::LogicalLine& line,
                                       std::vector<CycleParameter>& out, size_t headerFrom) {
    const std::string_view text = line.text;
    for (size_t s = 0; s < line.segments.size(); ++s) {
        if (s == 0 && headerFrom == std::string_view::npos) continue;
        const size_t from = s == 0 ? headerFrom : line.segments[s].joinedOffset;
        const size_t to = segmentEnd(line, s);
        Cursor first(text.substr(0, to), from);
        if (first.atEnd()) continue;
        // Several parameters side by side: each ends where the next one starts.
        const CycleParameterSpans spans = cycleParameterSpans(text, first.position(), to);
        if (spans.starts.empty() || spans.starts.front() != first.position()) {
            if (!parseCycleParameter(text.substr(0, to), first.position(), out)) return false;
            continue;
        }
        for (size_t k = 0; k < spans.starts.size(); ++k) {
            const size_t end = k + 1 < spans.starts.size() ? spans.starts[k + 1] : to;
            if (!parseCycleParameter(text.substr(0, end), spans.starts[k], out)) return false;
        }
    }
    return true;
}

// One "Qnnn=value ;comment" of text[at, end).
bool BlockParser::parseCycleParameter(std::string_view text, size_t at,
                                      std::vector<CycleParameter>& out) {
    Cursor sc(text, at);
    CycleParameter p;
    p.offset = sc.position();
    if (!sc.acceptPrefix("Q")) {
        return failAt(sc.position(), "syntax", KERF_TR_NOOP("cycle parameter Qnnn= expected"));
    }
    if (sc.acceptPrefix("S")) p.isString = true;
    auto q = sc.unsignedInteger();
    if (!q || *q >= kQCount) {
        return failAt(sc.position(), "syntax", KERF_TR_NOOP("cycle parameter number expected"));
    }
    p.q = static_cast<uint16_t>(*q);
    if (!sc.acceptChar('=')) return failAt(sc.position(), "syntax", KERF_TR_NOOP("'=' expected"));
    p.raw = std::string(sc.restUntilComment());
    p.comment = std::string(sc.comment());
    if (!p.isString) {
        // Plain numbers and Q references are evaluated now (the TNC captures cycle
        // parameters at definition); keywords such as PREDEF stay in `raw`.
        Cursor vc(p.raw);
        FormulaParser fp(vc, m_env);
        const char lead = upper(vc.peek());
        if (p.raw == "?") {
            // A nominal position not known (semi-automatic mode); the check says where.
            p.unknown = true;
            p.actualOffset = text.find('?', p.offset);
        } else if (lead == '+' || lead == '-' || isDigit(lead) || lead == 'Q' || lead == '(' ||
                   lead == '.') {
            auto v = fp.wordValue();
            std::optional<double> actual;
            if (v && vc.acceptChar('@')) {
                // "nominal@actual": a 14xx cycle's actual position; the check says where.
                p.actualOffset = text.find('@', p.offset);
                actual = fp.wordValue();
                if (!actual) v.reset();
            }
            if (v && vc.atEnd()) {
                p.value = *v;
                p.actual = actual;
                p.literal = p.raw.find_first_of("Qq") == std::string::npos;
            }
        }
    }
    out.push_back(std::move(p));
    return true;
}

// "X+60", "IROT+45", "SCL 0.75", "#5", "HSC-MODE:1 TA5", "DEPTH = -20", "X Y" ...
bool BlockParser::parseCycleWords(std::string_view text, size_t from, cycles::CycleWords& out) {
    Cursor cur(text, from);
    while (!cur.atEnd()) {
        cycles::CycleWord word;
        const char first = cur.peekRaw();
        if (first == '#') {
            cur.setPosition(cur.position() + 1);
            word.key = "#";
        } else if (isLetter(first)) {
            size_t i = cur.position();
            while (i < text.size() &&
                   (isLetter(text[i]) || ((text[i] == '-' || text[i] == '.') &&
                                          i + 1 < text.size() && isLetter(text[i + 1])))) {
                ++i;
            }
            word.key = upperText(text.substr(cur.position(), i - cur.position()));
            cur.setPosition(i);
            if (cur.peekRaw() == ':') cur.setPosition(cur.position() + 1);
            const bool axis = word.key.size() == 2 && axisFromLetter(word.key[1]).has_value();
            if (word.key[0] == 'I' && (axis || word.key == "IROT")) {
                word.incremental = true;
                word.key.erase(0, 1);
            }
        } else if (!valueStarts(cur.rest())) {
            return failAt(cur.position(), "syntax", KERF_TR_NOOP("unexpected '{1}'"),
                          {std::string(1, first)});
        }
        // The direction of the old pocket cycles is a sign alone: DR+ / DR-.
        const char sign = cur.peekRaw();
        const std::string_view afterSign =
            cur.rest().substr(std::min<size_t>(1, cur.rest().size()));
        if (word.key == "DR" && (sign == '+' || sign == '-') &&
            (afterSign.empty() || afterSign.front() == ' ' || afterSign.front() == ';')) {
            cur.setPosition(cur.position() + 1);
            word.value = sign == '+' ? 1.0 : -1.0;
            out.push_back(std::move(word));
            cur.skipBlanks();
            continue;
        }
        cur.skipBlanks();
        if (cur.peekRaw() == '=') {
            cur.setPosition(cur.position() + 1);
            cur.skipBlanks();
        }
        if (word.key == "#" || valueStarts(cur.rest())) {
            double value = 0.0;
            if (!parseValue(cur, value)) return false;
            word.value = value;
        }
        out.push_back(std::move(word));
        cur.skipBlanks();
    }
    return true;
}

bool BlockParser::parseGlobalDef(const program::LogicalLine& line, size_t at, ParsedBlock& out) {
    Cursor cur(line.text, at);
    auto number = cur.unsignedInteger();
    if (!number || *number > 9999) {
        return failAt(cur.position(), "syntax", KERF_TR_NOOP("GLOBAL DEF group number expected"));
    }
    GlobalDefinition b;
    b.group = static_cast<int>(*number);
    const size_t headerEnd = segmentEnd(line, 0);
    const CycleParameterSpans onHeader = cycleParameterSpans(line.text, cur.position(), headerEnd);
    const size_t parametersAt =
        onHeader.starts.empty() ? std::string_view::npos : onHeader.starts.front();
    if (!parseCycleParameters(line, b.parameters, parametersAt)) return false;
    out.statement = std::move(b);
    return true;
}

// PATTERN DEF POS1 (X+25 Y+33.5 Z+0) ROW1 (X+25 Y+33.5 D+8 NUM5 ROT+0 Z+0) ..., elements on the
// header line or on the following (indented) lines.
bool BlockParser::parsePatternDef(const program::LogicalLine& line, size_t at, ParsedBlock& out) {
    using Kind = cycles::PatternElement::Kind;
    struct Name {
        const char* text;
        Kind kind;
    };
    static constexpr Name kKinds[] = {{"POS", Kind::Pos},   {"ROW", Kind::Row},
                                      {"PAT", Kind::Pat},   {"FRAME", Kind::Frame},
                                      {"CIRC", Kind::Circ}, {"PITCHCIRC", Kind::PitchCirc}};
    PatternDefinition b;
    for (size_t s = 0; s < line.segments.size(); ++s) {
        const size_t begin = s == 0 ? at : line.segments[s].joinedOffset;
        Cursor cur(line.text.substr(0, segmentEnd(line, s)), begin);
        while (!cur.atEnd()) {
            const size_t elementAt = cur.position();
            size_t i = elementAt;
            while (i < line.text.size() && isLetter(line.text[i]))
                ++i;
            const std::string name = upperText(line.text.substr(elementAt, i - elementAt));
            cycles::PatternElement e;
            bool known = false;
            for (const Name& n : kKinds) {
                if (name == n.text) {
                    e.kind = n.kind;
                    known = true;
                }
            }
            if (!known) {
                return failAt(elementAt, "syntax",
                              KERF_TR_NOOP("pattern element POS, ROW, PAT, FRAME, CIRC or "
                                           "PITCHCIRC expected"));
            }
            cur.setPosition(i);
            if (auto index = cur.unsignedInteger())
                e.index = static_cast<int>(std::min(*index, 99LL));
            if (!cur.acceptChar('('))
                return failAt(cur.position(), "syntax", KERF_TR_NOOP("'(' expected"));
            while (!cur.acceptChar(')')) {
                if (cur.atEnd())
                    return failAt(cur.position(), "syntax", KERF_TR_NOOP("')' expected"));
                const size_t wordAt = cur.position();
                size_t j = wordAt;
                while (j < line.text.size() && isLetter(line.text[j]))
                    ++j;
                std::string key = upperText(line.text.substr(wordAt, j - wordAt));
                bool incremental = false;
                if (key == "IX" || key == "IY" || key == "IZ") {
                    incremental = true;
                    key.erase(0, 1);
                }
                cycles::PatternElement::Word* word = nullptr;
                struct Slot {
                    const char* key;
                    cycles::PatternElement::Word cycles::PatternElement::*member;
                };
                static constexpr Slot kSlots[] = {{"X", &cycles::PatternElement::x},
                                                  {"Y", &cycles::PatternElement::y},
                                                  {"Z", &cycles::PatternElement::z},
                                                  {"D", &cycles::PatternElement::d},
                                                  {"DX", &cycles::PatternElement::dx},
                                                  {"DY", &cycles::PatternElement::dy},
                                                  {"NUM", &cycles::PatternElement::num},
                                                  {"NUMX", &cycles::PatternElement::numX},
                                                  {"NUMY", &cycles::PatternElement::numY},
                                                  {"ROT", &cycles::PatternElement::rot},
                                                  {"ROTX", &cycles::PatternElement::rotX},
                                                  {"ROTY", &cycles::PatternElement::rotY},
                                                  {"START", &cycles::PatternElement::start},
                                                  {"STEP", &cycles::PatternElement::step}};
                for (const Slot& slot : kSlots) {
                    if (key == slot.key) word = &(e.*slot.member);
                }
                if (word == nullptr || (incremental && e.kind != Kind::Pos)) {
                    return failAt(wordAt, "syntax", KERF_TR_NOOP("unexpected '{1}'"), {key});
                }
                cur.setPosition(j);
                double value = 0.0;
                if (!parseValue(cur, value)) return false;
                *word = {value, incremental, true};
            }
            b.elements.push_back(e);
        }
    }
    if (b.elements.empty()) {
        return failAt(at, "syntax", KERF_TR_NOOP("PATTERN DEF needs at least one pattern element"));
    }
    out.statement = std::move(b);
    return true;
}

}  // namespace kerf::klartext
