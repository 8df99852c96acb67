// FK free contour blocks: FPOL X.. Y.., FSELECT n, and FL/FLT/FC/FCT with their data words.
#include <array>
#include <string>

#include "core/base/translate.h"
#include "core/interp/klartext/block_parser.h"

namespace kerf::klartext {

namespace {

using fk::FkValue;

// A data word with a value: the keyword, where the value goes, whether it is incremental.
struct ValueWord {
    const char* keyword;
    std::optional<FkValue> fk::FkElement::*target;
    bool incremental;
};

// Longest keywords first where one is the prefix of another.
constexpr std::array<ValueWord, 22> kValueWords{{
    {"ICCPR", &fk::FkElement::ccpr, true}, {"ICCPA", &fk::FkElement::ccpa, true},
    {"ICCX", &fk::FkElement::ccx, true},   {"ICCY", &fk::FkElement::ccy, true},
    {"CCPR", &fk::FkElement::ccpr, false}, {"CCPA", &fk::FkElement::ccpa, false},
    {"CCX", &fk::FkElement::ccx, false},   {"CCY", &fk::FkElement::ccy, false},
    {"IPDX", &fk::FkElement::pdx, true},   {"IPDY", &fk::FkElement::pdy, true},
    {"PDX", &fk::FkElement::pdx, false},   {"PDY", &fk::FkElement::pdy, false},
    {"IPR", &fk::FkElement::pr, true},     {"IPA", &fk::FkElement::pa, true},
    {"IAN", &fk::FkElement::an, true},     {"PR", &fk::FkElement::pr, false},
    {"PA", &fk::FkElement::pa, false},     {"AN", &fk::FkElement::an, false},
    {"IX", &fk::FkElement::x, true},       {"IY", &fk::FkElement::y, true},
    {"X", &fk::FkElement::x, false},       {"Y", &fk::FkElement::y, false},
}};

// Relative data: the keyword names the quantity, the number after it the block it refers to.
struct ReferenceWord {
    const char* keyword;
    std::optional<FkValue> fk::FkElement::*target;
    const char* valueKeyword;  // the incremental value the reference belongs to
};
constexpr std::array<ReferenceWord, 11> kReferenceWords{{
    {"RCCPR", &fk::FkElement::ccpr, "ICCPR"},
    {"RCCPA", &fk::FkElement::ccpa, "ICCPA"},
    {"RCCX", &fk::FkElement::ccx, "ICCX"},
    {"RCCY", &fk::FkElement::ccy, "ICCY"},
    {"RPDX", &fk::FkElement::pdx, "IPDX"},
    {"RPDY", &fk::FkElement::pdy, "IPDY"},
    {"RPR", &fk::FkElement::pr, "IPR"},
    {"RPA", &fk::FkElement::pa, "IPA"},
    {"RAN", &fk::FkElement::an, "IAN"},
    {"RX", &fk::FkElement::x, "IX"},
    {"RY", &fk::FkElement::y, "IY"},
}};

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
        std::optional<double> x, y;
        while (!cur.atEnd()) {
            double v = 0.0;
            const size_t wordAt = cur.position();
            if (cur.acceptPrefix("X") && !x) {
                if (!parseValue(cur, v)) return false;
                x = v;
            } else if (cur.acceptPrefix("Y") && !y) {
                if (!parseValue(cur, v)) return false;
                y = v;
            } else {
                return failAt(wordAt, "syntax", KERF_TR_NOOP("FPOL takes X and Y once each"));
            }
        }
        if (!x || !y) {
            return failAt(cur.position(), "syntax", KERF_TR_NOOP("FPOL needs X and Y"));
        }
        out.statement = FkPole{*x, *y};
        return true;
    }
    FkBlock b;
    b.element.kind = head == "FL"    ? fk::FkKind::Line
                     : head == "FLT" ? fk::FkKind::TangentLine
                     : head == "FC"  ? fk::FkKind::Arc
                                     : fk::FkKind::TangentArc;
    b.element.blockNumber = out.blockNumber;
    std::array<std::optional<double>, 6> auxiliary{};  // P1X P1Y P2X P2Y P3X P3Y
    std::array<size_t, 6> auxiliaryAt{};
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
            if (b.element.*word.target) return duplicate(wordAt);
            if (!parseValue(cur, v)) return false;
            b.element.*word.target = FkValue{v, word.incremental, std::nullopt};
            matched = true;
            break;
        }
        if (matched) continue;
        const char c = upper(cur.peek());
        if (c == 'P' && cur.position() + 2 < line.text.size()) {
            const char number = line.text[cur.position() + 1];
            const char axis = upper(line.text[cur.position() + 2]);
            if (number >= '1' && number <= '3' && (axis == 'X' || axis == 'Y')) {
                cur.setPosition(cur.position() + 3);
                const auto index = static_cast<size_t>((number - '1') * 2 + (axis == 'Y'));
                auto& slot = auxiliary[index];
                if (slot) return duplicate(wordAt);
                auxiliaryAt[index] = wordAt;
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
    for (size_t i = 0; i < 3; ++i) {
        const auto& px = auxiliary[i * 2];
        const auto& py = auxiliary[i * 2 + 1];
        if (px.has_value() != py.has_value()) {
            return failAt(px ? auxiliaryAt[i * 2] : auxiliaryAt[i * 2 + 1], "syntax",
                          KERF_TR_NOOP("P{1}X and P{1}Y are given together"),
                          {std::to_string(i + 1)});
        }
        if (px) b.element.pointsOn[i] = Vec2(*px, *py);
    }
    for (size_t i = 0; i < kReferenceWords.size(); ++i) {
        if (!references[i]) continue;
        std::optional<FkValue>& value = b.element.*kReferenceWords[i].target;
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
