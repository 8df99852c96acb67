#include "core/cycles/special/engraving_text.h"

#include <array>
#include <cstdio>

#include "core/base/translate.h"
#include "core/cycles/special/engraving_font.h"

namespace kerf::cycles::engraving {

namespace {

CycleError textError(const char* messageTemplate, std::string what) {
    return CycleError{"cycle-text", messageTemplate, {std::move(what)}};
}

// One character of UTF-8; a byte that does not start a valid sequence is read as Latin-1.
char32_t nextCodePoint(std::string_view text, size_t& at) {
    const auto lead = static_cast<unsigned char>(text[at]);
    size_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : 0;
    if (length == 0 || at + length > text.size()) {
        ++at;
        return lead;
    }
    char32_t code = length == 1 ? lead : length == 2 ? (lead & 0x1Fu) : (lead & 0x0Fu);
    for (size_t i = 1; i < length; ++i) {
        const auto c = static_cast<unsigned char>(text[at + i]);
        if ((c & 0xC0u) != 0x80u) {
            ++at;
            return lead;
        }
        code = (code << 6) | (c & 0x3Fu);
    }
    at += length;
    return code;
}

std::string utf8(char32_t code) {
    std::string out;
    if (code < 0x80) {
        out += static_cast<char>(code);
    } else if (code < 0x800) {
        out += static_cast<char>(0xC0 | (code >> 6));
        out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
        out += static_cast<char>(0xE0 | (code >> 12));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
    }
    return out;
}

struct NamedEscape {
    std::string_view name;
    char32_t code;
};

constexpr std::array<NamedEscape, 11> kEscapes = {{{"%", U'%'},
                                                   {"ae", U'\u00E4'},
                                                   {"oe", U'\u00F6'},
                                                   {"ue", U'\u00FC'},
                                                   {"AE", U'\u00C4'},
                                                   {"OE", U'\u00D6'},
                                                   {"UE", U'\u00DC'},
                                                   {"ss", U'\u00DF'},
                                                   {"at", U'@'},
                                                   {"CE", kCeMark},
                                                   {"D", U'\u00F8'}}};

std::string twoDigits(int v) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%02d", v);
    return buffer;
}

}  // namespace

std::optional<std::string> formatTime(int code, const DateTime& t) {
    const std::string dd = twoDigits(t.day), d = std::to_string(t.day), mm = twoDigits(t.month);
    const std::string yyyy = std::to_string(t.year), yy = twoDigits(t.year % 100);
    const std::string hh = twoDigits(t.hour), h = std::to_string(t.hour);
    const std::string mi = twoDigits(t.minute), ss = twoDigits(t.second);
    switch (code) {
        case 0:
            return dd + "." + mm + "." + yyyy + " " + hh + ":" + mi + ":" + ss;
        case 1:
            return d + "." + mm + "." + yyyy + " " + h + ":" + mi + ":" + ss;
        case 2:
            return d + "." + mm + "." + yyyy + " " + h + ":" + mi;
        case 3:
            return d + "." + mm + "." + yy + " " + h + ":" + mi;
        case 4:
            return yyyy + "-" + mm + "-" + dd + " " + hh + ":" + mi + ":" + ss;
        case 5:
            return yyyy + "-" + mm + "-" + dd + " " + hh + ":" + mi;
        case 6:
            return yyyy + "-" + mm + "-" + dd + " " + h + ":" + mi;
        case 7:
            return yy + "-" + mm + "-" + dd + " " + h + ":" + mi;
        case 8:
            return dd + "." + mm + "." + yyyy;
        case 9:
            return d + "." + mm + "." + yyyy;
        case 10:
            return d + "." + mm + "." + yy;
        case 11:
            return yyyy + "-" + mm + "-" + dd;
        case 12:
            return yy + "-" + mm + "-" + dd;
        case 13:
            return hh + ":" + mi + ":" + ss;
        case 14:
            return h + ":" + mi + ":" + ss;
        case 15:
            return h + ":" + mi;
        default:
            return std::nullopt;
    }
}

std::optional<CycleError> decodeText(std::string_view text, const DateTime& now,
                                     unsigned long long counter, std::vector<TextToken>& out) {
    out.clear();
    auto character = [&](char32_t code) -> std::optional<CycleError> {
        if (findGlyph(code) == nullptr) {
            return textError(KERF_TR_NOOP("cycle 225: the character '{1}' cannot be engraved"),
                             utf8(code));
        }
        out.push_back({TextToken::Kind::Character, code});
        return std::nullopt;
    };
    auto plain = [&](std::string_view generated) -> std::optional<CycleError> {
        for (char c : generated) {
            if (auto e = character(static_cast<unsigned char>(c))) return e;
        }
        return std::nullopt;
    };
    size_t at = 0;
    while (at < text.size()) {
        const char c = text[at];
        if (c == '\\') {
            const char next = at + 1 < text.size() ? text[at + 1] : '\0';
            const TextToken::Kind kind = next == 'n'   ? TextToken::Kind::NewLine
                                         : next == 't' ? TextToken::Kind::Tab
                                         : next == 'v' ? TextToken::Kind::VerticalTab
                                                       : TextToken::Kind::Character;
            if (next == '\\') {
                out.push_back({TextToken::Kind::Character, U'\\'});
            } else if (kind != TextToken::Kind::Character) {
                out.push_back({kind, 0});
            } else {
                return textError(KERF_TR_NOOP("cycle 225: unknown formatting character '\\{1}' "
                                              "in the text (write \\\\ for a backslash)"),
                                 std::string(1, next));
            }
            at += 2;
            continue;
        }
        if (c != '%') {
            if (auto e = character(nextCodePoint(text, at))) return e;
            continue;
        }
        const std::string_view rest = text.substr(at + 1);
        if (rest.substr(0, 4) == "time") {
            const std::string_view digits = rest.substr(4, 2);
            const bool valid = digits.size() == 2 && digits[0] >= '0' && digits[0] <= '9' &&
                               digits[1] >= '0' && digits[1] <= '9';
            std::optional<std::string> formatted;
            if (valid) formatted = formatTime((digits[0] - '0') * 10 + (digits[1] - '0'), now);
            if (!formatted) {
                return textError(KERF_TR_NOOP("cycle 225: '%time{1}' is not a date format (use "
                                              "%time00 to %time15)"),
                                 std::string(digits));
            }
            if (auto e = plain(*formatted)) return e;
            at += 7;
            continue;
        }
        if (rest.substr(0, 5) == "count") {
            const char digit = rest.size() > 5 ? rest[5] : '\0';
            if (digit < '1' || digit > '9') {
                return CycleError{"cycle-text",
                                  KERF_TR_NOOP("cycle 225: '%count' needs the number of digits "
                                               "(1 to 9)"),
                                  {}};
            }
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "%0*llu", digit - '0', counter);
            if (auto e = plain(buffer)) return e;
            at += 7;
            continue;
        }
        bool found = false;
        for (const NamedEscape& e : kEscapes) {
            if (rest.substr(0, e.name.size()) == e.name) {
                out.push_back({TextToken::Kind::Character, e.code});
                at += 1 + e.name.size();
                found = true;
                break;
            }
        }
        if (!found) {
            return textError(KERF_TR_NOOP("cycle 225: unknown escape '%{1}' in the text (write "
                                          "%% for a percent sign)"),
                             std::string(rest.substr(0, 2)));
        }
    }
    return std::nullopt;
}

}  // namespace kerf::cycles::engraving
