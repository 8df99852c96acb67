// PLANE blocks: the tilted working plane, and FUNCTION TCPM. The form (SPATIAL, PROJECTED, ...) and
// its numbers, then the positioning words in any order:
//   PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN MB MAX FMAX SEQ+ TABLE ROT
//   PLANE RESET STAY
#include <iterator>

#include "core/base/translate.h"
#include "core/interp/klartext/block_parser.h"

namespace kerf::klartext {

namespace {

std::string upperCopyOf(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        c = upper(c);
    return out;
}

struct PlaneForm {
    const char* keyword;
    PlaneBlock::Kind kind;
    std::array<const char*, 9> words;  // the numbers every block of this form gives, in order
    size_t count;
};

constexpr PlaneForm kForms[] = {
    {"SPATIAL", PlaneBlock::Kind::Spatial, {"SPA", "SPB", "SPC"}, 3},
    {"PROJECTED", PlaneBlock::Kind::Projected, {"PROPR", "PROMIN", "ROT"}, 3},
    {"EULER", PlaneBlock::Kind::Euler, {"EULPR", "EULNU", "EULROT"}, 3},
    {"VECTOR", PlaneBlock::Kind::Vector, {"BX", "BY", "BZ", "NX", "NY", "NZ"}, 6},
    {"POINTS",
     PlaneBlock::Kind::Points,
     {"P1X", "P1Y", "P1Z", "P2X", "P2Y", "P2Z", "P3X", "P3Y", "P3Z"},
     9},
    {"RELATIV", PlaneBlock::Kind::Relative, {}, 0},
    {"AXIAL", PlaneBlock::Kind::Axial, {}, 0},
    {"RESET", PlaneBlock::Kind::Reset, {}, 0},
};

}  // namespace

bool BlockParser::parsePlane(const program::LogicalLine& line, size_t at, ParsedBlock& out) {
    Cursor cur(line.text, at);
    PlaneBlock b;
    const PlaneForm* form = nullptr;
    for (const PlaneForm& f : kForms) {
        if (cur.acceptKeyword(f.keyword)) form = &f;
        if (form) break;
    }
    if (!form) {
        cur.skipBlanks();
        return failAt(cur.position(), "syntax",
                      KERF_TR_NOOP("PLANE: SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV, "
                                   "AXIAL or RESET expected"));
    }
    b.kind = form->kind;
    for (size_t i = 0; i < form->count; ++i) {
        cur.skipBlanks();
        if (!cur.acceptPrefix(form->words[i])) {
            return failAt(cur.position(), "syntax", KERF_TR_NOOP("PLANE {1}: {2} expected"),
                          {form->keyword, form->words[i]});
        }
        if (!parseValue(cur, b.values[i])) return false;
    }
    if (b.kind == PlaneBlock::Kind::Relative) {
        static const char* const kAngles[] = {"SPA", "SPB", "SPC"};
        cur.skipBlanks();
        const size_t wordAt = cur.position();
        for (int i = 0; i < 3 && b.relativeAxis == 0; ++i) {
            if (cur.acceptPrefix(kAngles[i])) b.relativeAxis = i + 1;
        }
        if (b.relativeAxis == 0) {
            return failAt(wordAt, "syntax",
                          KERF_TR_NOOP("PLANE RELATIV: SPA, SPB or SPC expected"));
        }
        --b.relativeAxis;
        if (!parseValue(cur, b.values[0])) return false;
    }
    if (b.kind == PlaneBlock::Kind::Axial) {
        for (;;) {
            cur.skipBlanks();
            const char letter = upper(cur.peekRaw());
            const char next =
                cur.position() + 1 < line.text.size() ? line.text[cur.position() + 1] : '\0';
            if (letter < 'A' || letter > 'C' || isLetter(next)) break;
            const auto index = static_cast<size_t>(letter - 'A');
            cur.setPosition(cur.position() + 1);
            if (!parseValue(cur, b.values[index])) return false;
            b.axialPresent[index] = true;
        }
        if (b.axialPresent == std::array<bool, 3>{}) {
            return failAt(cur.position(), "syntax",
                          KERF_TR_NOOP("PLANE AXIAL: an angle of A, B or C expected"));
        }
    }
    // Positioning words, any order.
    bool positioned = false;
    while (!cur.atEnd()) {
        const size_t wordAt = cur.position();
        if (cur.acceptKeyword("STAY") || cur.acceptKeyword("TURN") || cur.acceptKeyword("MOVE")) {
            const char first = upper(line.text[wordAt]);
            b.positioning = first == 'S'   ? PlaneBlock::Positioning::Stay
                            : first == 'T' ? PlaneBlock::Positioning::Turn
                                           : PlaneBlock::Positioning::Move;
            positioned = true;
        } else if (cur.acceptPrefix("MB")) {
            if (cur.acceptKeyword("MAX")) {
                b.retractMax = true;
            } else {
                double v = 0.0;
                if (!parseValue(cur, v)) return false;
                b.retract = v;
            }
        } else if (cur.acceptPrefix("DIST") || cur.acceptPrefix("ABST")) {
            if (!parseValue(cur, b.distance)) return false;
        } else if (cur.acceptKeyword("FMAX")) {
            b.feed.kind = FeedWord::Kind::Max;
        } else if (cur.acceptPrefix("F")) {
            b.feed.kind = FeedWord::Kind::Value;
            if (!parseValue(cur, b.feed.value)) return false;
        } else if (cur.acceptPrefix("SEQ")) {
            const char sign = cur.peekRaw();
            if (sign != '+' && sign != '-') {
                return failAt(cur.position(), "syntax", KERF_TR_NOOP("SEQ+ or SEQ- expected"));
            }
            cur.setPosition(cur.position() + 1);
            b.sequence =
                sign == '+' ? PlaneBlock::Sequence::Positive : PlaneBlock::Sequence::Negative;
        } else if (cur.acceptKeyword("TABLE") || cur.acceptKeyword("COORD")) {
            b.tableRotation = upper(line.text[wordAt]) == 'T';
            if (!cur.acceptKeyword("ROT")) {
                return failAt(cur.position(), "syntax", KERF_TR_NOOP("ROT expected"));
            }
        } else {
            return failAt(wordAt, "syntax", KERF_TR_NOOP("PLANE: unexpected '{1}'"),
                          {std::string(cur.word())});
        }
    }
    if (!positioned) {
        return failAt(cur.position(), "syntax", KERF_TR_NOOP("PLANE: MOVE, TURN or STAY expected"));
    }
    out.statement = b;
    return true;
}

bool BlockParser::parseTcpm(const program::LogicalLine& line, size_t at, ParsedBlock& out,
                            bool& handled) {
    Cursor cur(line.text, at);
    const bool reset = cur.acceptKeyword("RESET");
    if (!cur.acceptKeyword("TCPM")) return false;
    handled = true;
    if (reset) {
        if (!cur.atEnd()) {
            return failAt(cur.position(), "syntax", KERF_TR_NOOP("unexpected '{1}'"),
                          {std::string(cur.word())});
        }
        out.statement = TcpmBlock{false};
        return true;
    }
    // Each option with the values Kerf implements: F TCP|CONT, AXIS POS|SPAT, PATHCTRL
    // AXIS|VECTOR and the reference points of the TNC's default (tip to tip).
    TcpmBlock b;
    b.on = true;
    struct Option {
        const char* keyword;
        const char* values[2];
        bool* second;  // set when the second value is written
    };
    bool unused = false;
    const Option options[] = {{"F", {"TCP", "CONT"}, &b.feedContour},
                              {"AXIS", {"POS", "SPAT"}, &b.spatialAngles},
                              {"PATHCTRL", {"AXIS", "VECTOR"}, &b.vectorPath},
                              {"REFPNT", {"TIP-TIP", nullptr}, &unused}};
    while (!cur.atEnd()) {
        const size_t wordAt = cur.position();
        bool known = false;
        for (const Option& option : options) {
            if (!cur.acceptKeyword(option.keyword)) continue;
            cur.skipBlanks();
            const std::string value = upperCopyOf(cur.word());
            known = value == option.values[0] ||
                    (option.values[1] != nullptr && value == option.values[1]);
            if (known) *option.second = value != option.values[0];
            break;
        }
        if (!known) {
            cur.setPosition(wordAt);
            return failAt(wordAt, "not-supported",
                          KERF_TR_NOOP("FUNCTION TCPM: only F TCP|CONT, AXIS POS|SPAT, PATHCTRL "
                                       "AXIS|VECTOR and REFPNT TIP-TIP are supported, not '{1}'"),
                          {std::string(cur.restUntilComment())});
        }
    }
    out.statement = b;
    return true;
}

bool BlockParser::parseFunctionMode(Cursor& cur, ParsedBlock& out) {
    cur.skipBlanks();
    const size_t modeAt = cur.position();
    if (cur.acceptKeyword("MILL")) {
        // A kinematics name after MILL would switch the machine's kinematics, which Kerf's
        // machine file fixes.
        cur.skipBlanks();
        const size_t nameAt = cur.position();
        if (!cur.atEnd()) {
            cur.setPosition(nameAt);
            return failAt(nameAt, "not-supported",
                          KERF_TR_NOOP("FUNCTION MODE MILL: the machine file sets the kinematics; "
                                       "'{1}' cannot be selected"),
                          {std::string(cur.restUntilComment())});
        }
        out.statement = Empty{};
        return true;
    }
    if (cur.acceptKeyword("TURN")) {
        return failAt(modeAt, "not-supported",
                      KERF_TR_NOOP("FUNCTION MODE TURN: this machine has no turning mode"));
    }
    return failAt(modeAt, "syntax", KERF_TR_NOOP("FUNCTION MODE: MILL or TURN expected"));
}

}  // namespace kerf::klartext
