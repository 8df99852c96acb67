// FK free contour blocks: FPOL X.. Y.., FSELECT n, and FL/FLT/FC/FCT with their data words.
#include <algorithm>
#include <array>
#include <string>

#include "core/base/translate.h"
#include "core/interp/klartext/block_parser.h"

namespace kerf::klartext {

namespace {

using fk::FkValue;

// Where a data word's value goes in the block.
using Slot = std::optional<FkValue>& (*)(FkBlock&);
template <size_t Axis>
std::optional<FkValue>& endAt(FkBlock& b) {
    return b.end[Axis];
}
template <size_t Axis>
std::optional<FkValue>& centreAt(FkBlock& b) {
    return b.centre[Axis];
}
template <size_t Axis>
std::optional<FkValue>& distancePointAt(FkBlock& b) {
    return b.pointAtDistance[Axis];
}
template <std::optional<FkValue> fk::FkElement::*Member>
std::optional<FkValue>& elementDatum(FkBlock& b) {
    return b.element.*Member;
}

// A data word with a value: the keyword, where the value goes, whether it is incremental.
struct ValueWord {
    const char* keyword;
    Slot slot;
    bool incremental;
};

// Longest keywords first where one is the prefix of another.
constexpr std::array<ValueWord, 28> kValueWords{{
    {"ICCPR", &elementDatum<&fk::FkElement::ccpr>, true},
    {"ICCPA", &elementDatum<&fk::FkElement::ccpa>, true},
    {"ICCX", &centreAt<0>, true},
    {"ICCY", &centreAt<1>, true},
    {"ICCZ", &centreAt<2>, true},
    {"CCPR", &elementDatum<&fk::FkElement::ccpr>, false},
    {"CCPA", &elementDatum<&fk::FkElement::ccpa>, false},
    {"CCX", &centreAt<0>, false},
    {"CCY", &centreAt<1>, false},
    {"CCZ", &centreAt<2>, false},
    {"IPDX", &distancePointAt<0>, true},
    {"IPDY", &distancePointAt<1>, true},
    {"IPDZ", &distancePointAt<2>, true},
    {"PDX", &distancePointAt<0>, false},
    {"PDY", &distancePointAt<1>, false},
    {"PDZ", &distancePointAt<2>, false},
    {"IPR", &elementDatum<&fk::FkElement::pr>, true},
    {"IPA", &elementDatum<&fk::FkElement::pa>, true},
    {"IAN", &elementDatum<&fk::FkElement::an>, true},
    {"PR", &elementDatum<&fk::FkElement::pr>, false},
    {"PA", &elementDatum<&fk::FkElement::pa>, false},
    {"AN", &elementDatum<&fk::FkElement::an>, false},
    {"IX", &endAt<0>, true},
    {"IY", &endAt<1>, true},
    {"IZ", &endAt<2>, true},
    {"X", &endAt<0>, false},
    {"Y", &endAt<1>, false},
    {"Z", &endAt<2>, false},
}};

// Relative data: the keyword names the quantity, the number after it the block it refers to.
struct ReferenceWord {
    const char* keyword;
    Slot slot;
    const char* valueKeyword;  // the incremental value the reference belongs to
};
constexpr std::array<ReferenceWord, 14> kReferenceWords{{
    {"RCCPR", &elementDatum<&fk::FkElement::ccpr>, "ICCPR"},
    {"RCCPA", &elementDatum<&fk::FkElement::ccpa>, "ICCPA"},
    {"RCCX", &centreAt<0>, "ICCX"},
    {"RCCY", &centreAt<1>, "ICCY"},
    {"RCCZ", &centreAt<2>, "ICCZ"},
    {"RPDX", &distancePointAt<0>, "IPDX"},
    {"RPDY", &distancePointAt<1>, "IPDY"},
    {"RPDZ", &distancePointAt<2>, "IPDZ"},
    {"RPR", &elementDatum<&fk::FkElement::pr>, "IPR"},
    {"RPA", &elementDatum<&fk::FkElement::pa>, "IPA"},
    {"RAN", &elementDatum<&fk::FkElement::an>, "IAN"},
    {"RX", &endAt<0>, "IX"},
    {"RY", &endAt<1>, "IY"},
    {"RZ", &endAt<2>, "IZ"},
}};

int axisIndexOf(char upperLetter) {
    return upperLetter == 'X' ? 0 : (upperLetter == 'Y' ? 1 : (upperLetter == 'Z' ? 2 : -1));
}

}  // namespace

bool BlockParser::parseFk(std::string_view head, const program::LogicalLine& line, size_t at,
                          ParsedBlock& out) {
    Cursor cur(line.text, at);
    if (head == "FSELECT" || head == "FSELCT") {
        cur.skipBlanks();
        const size_t numberAt = cur.position();
        auto choice = cur.unsignedInteger();
        if (!choice || *choice < 1 || *choice > 99) {
            return failAt(numberAt, "syntax",
                          KERF_TR_NOOP("FSELECT needs the number of a solution (1 to 99)"));
        }
        if (!cur.atEnd()) return failAt(cur.position(), "syntax", KERF_TR_NOOP("unexpected text"));
        out.statement = FkSelect{static_cast<int>(*choice)};
        return true;
    }
    if (head == "FPOL") {
        FkPole pole;
        size_t given = 0;
        while (!cur.atEnd()) {
            const size_t wordAt = cur.position();
            const int axis = axisIndexOf(upper(cur.peek()));
            if (axis < 0 || pole.coords[static_cast<size_t>(axis)]) {
                return failAt(wordAt, "syntax", KERF_TR_NOOP("FPOL takes X and Y once each"));
            }
            cur.setPosition(cur.position() + 1);
            double v = 0.0;
            if (!parseValue(cur, v)) return false;
            pole.coords[static_cast<size_t>(axis)] = v;
            ++given;
        }
        if (given != 2) {
            return failAt(cur.position(), "syntax", KERF_TR_NOOP("FPOL needs X and Y"));
        }
        out.statement = pole;
        return true;
    }
    FkBlock b;
    b.element.kind = head == "FL"    ? fk::FkKind::Line
                     : head == "FLT" ? fk::FkKind::TangentLine
                     : head == "FC"  ? fk::FkKind::Arc
                                     : fk::FkKind::TangentArc;
    b.element.blockNumber = out.blockNumber;
    std::array<size_t, 3> auxiliaryAt{};  // where P1.., P2.., P3.. start
    std::array<std::optional<int64_t>, kReferenceWords.size()> references{};
    std::array<size_t, kReferenceWords.size()> referenceAt{};
    auto duplicate = [&](size_t wordAt) {
        return failAt(wordAt, "syntax", KERF_TR_NOOP("this FK datum is programmed twice"));
    };
    while (!cur.atEnd()) {
        const size_t wordAt = cur.position();
        double v = 0.0;
        if (cur.acceptPrefix("CLSD")) {
            const char sign = cur.peekRaw();
            if (sign != '+' && sign != '-') {
                return failAt(cur.position(), "syntax", KERF_TR_NOOP("CLSD+ or CLSD- expected"));
            }
            cur.setPosition(cur.position() + 1);
            (sign == '+' ? b.element.closeStart : b.element.closeEnd) = true;
            continue;
        }
        if (cur.acceptPrefix("DR")) {
            cur.skipBlanks();
            const char sign = cur.peekRaw();
            if (sign != '+' && sign != '-') {
                return failAt(cur.position(), "syntax", KERF_TR_NOOP("DR+ or DR- expected"));
            }
            cur.setPosition(cur.position() + 1);
            b.element.rotation = sign == '+' ? fk::FkRotation::Ccw : fk::FkRotation::Cw;
            continue;
        }
        // R0 ends compensation; R0.5 or R05 would be a radius.
        const bool compOff = upper(cur.peek()) == 'R' && cur.position() + 1 < line.text.size() &&
                             line.text[cur.position() + 1] == '0' &&
                             (cur.position() + 2 >= line.text.size() ||
                              std::string_view(" \t;").find(line.text[cur.position() + 2]) !=
                                  std::string_view::npos);
        if (compOff) cur.setPosition(cur.position() + 2);
        if (compOff || cur.acceptKeyword("RL") || cur.acceptKeyword("RR")) {
            const char side = upper(line.text[wordAt + 1]);
            b.words.comp = side == 'L'   ? CompWord::Left
                           : side == 'R' ? CompWord::Right
                                         : CompWord::Off;
            continue;
        }
        bool matched = false;
        for (size_t i = 0; i < kReferenceWords.size() && !matched; ++i) {
            if (!cur.acceptPrefix(kReferenceWords[i].keyword)) continue;
            cur.skipBlanks();
            auto block = cur.unsignedInteger();
            if (!block) {
                return failAt(cur.position(), "syntax",
                              KERF_TR_NOOP("the block number relative data refer to expected"));
            }
            if (references[i]) return duplicate(wordAt);
            references[i] = static_cast<int64_t>(*block);
            referenceAt[i] = wordAt;
            matched = true;
        }
        if (matched) continue;
        for (const ValueWord& word : kValueWords) {
            if (!cur.acceptPrefix(word.keyword)) continue;
            std::optional<FkValue>& slot = word.slot(b);
            if (slot) return duplicate(wordAt);
            if (!parseValue(cur, v)) return false;
            slot = FkValue{v, word.incremental, std::nullopt};
            matched = true;
            break;
        }
        if (matched) continue;
        const char c = upper(cur.peek());
        if (c == 'P' && cur.position() + 2 < line.text.size()) {
            const char number = line.text[cur.position() + 1];
            const char axis = upper(line.text[cur.position() + 2]);
            if (number >= '1' && number <= '3' && axisIndexOf(axis) >= 0) {
                cur.setPosition(cur.position() + 3);
                const auto point = static_cast<size_t>(number - '1');
                auto& slot = b.pointsOn[point][static_cast<size_t>(axisIndexOf(axis))];
                if (slot) return duplicate(wordAt);
                if (auxiliaryAt[point] == 0) auxiliaryAt[point] = wordAt;
                if (!parseValue(cur, v)) return false;
                slot = v;
                continue;
            }
        }
        std::optional<double>* scalar = nullptr;
        if (cur.acceptPrefix("LEN")) {
            scalar = &b.element.length;
        } else if (cur.acceptPrefix("CCA")) {
            scalar = &b.element.endAngleAboutCentre;
        } else if (c == 'D') {
            cur.setPosition(cur.position() + 1);
            scalar = &b.element.distance;
        } else if (c == 'R') {
            cur.setPosition(cur.position() + 1);
            scalar = &b.element.radius;
        }
        if (scalar != nullptr) {
            if (*scalar) return duplicate(wordAt);
            if (!parseValue(cur, v)) return false;
            *scalar = v;
            continue;
        }
        if (c == 'F') {
            cur.setPosition(cur.position() + 1);
            if (cur.acceptKeyword("MAX")) {
                b.words.feed.kind = FeedWord::Kind::Max;
            } else if (cur.acceptKeyword("AUTO")) {
                b.words.feed.kind = FeedWord::Kind::Auto;
            } else {
                if (!parseValue(cur, v)) return false;
                if (v < 0.0 && m_env != nullptr) {
                    return failAt(wordAt, "range",
                                  KERF_TR_NOOP("the feed rate must not be negative"));
                }
                b.words.feed = {FeedWord::Kind::Value, v};
            }
            continue;
        }
        if (c == 'M') {
            cur.setPosition(cur.position() + 1);
            auto number = cur.unsignedInteger();
            if (!number || *number > 9999 || b.words.m.count >= b.words.m.list.size()) {
                return failAt(wordAt, "syntax", KERF_TR_NOOP("M function number expected"));
            }
            b.words.m.list[b.words.m.count++].number = static_cast<int>(*number);
            continue;
        }
        return failAt(wordAt, "syntax", KERF_TR_NOOP("unexpected '{1}' in an FK block"),
                      {std::string(cur.rest().substr(0, cur.rest().find(' ')))});
    }
    // A point on the element has the two coordinates of the working plane.
    for (size_t i = 0; i < 3; ++i) {
        const auto given = std::count_if(b.pointsOn[i].begin(), b.pointsOn[i].end(),
                                         [](const auto& v) { return v.has_value(); });
        if (given != 0 && given != 2) {
            return failAt(auxiliaryAt[i], "syntax",
                          KERF_TR_NOOP("P{1}X and P{1}Y are given together"),
                          {std::to_string(i + 1)});
        }
    }
    for (size_t i = 0; i < kReferenceWords.size(); ++i) {
        if (!references[i]) continue;
        std::optional<FkValue>& value = kReferenceWords[i].slot(b);
        if (!value || !value->incremental) {
            return failAt(referenceAt[i], "syntax",
                          KERF_TR_NOOP("{1} needs an incremental value {2} in the same block"),
                          {kReferenceWords[i].keyword, kReferenceWords[i].valueKeyword});
        }
        value->reference = references[i];
    }
    out.statement = std::move(b);
    return true;
}

}  // namespace kerf::klartext
