#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/cycles/cycle_context.h"

// The text of cycle 225 (QS500) decoded into what is engraved: characters of the font and the
// formatting characters. Escapes: %% and \\ for the characters themselves, %ae %oe %ue %AE %OE
// %UE %ss %D %at %CE, \n \t \v, %time00..%time15 (date and time) and %count1..%count9.
namespace kerf::cycles::engraving {

struct TextToken {
    enum class Kind : uint8_t { Character, NewLine, Tab, VerticalTab };
    Kind kind = Kind::Character;
    char32_t code = 0;
};

// Error when an escape is unknown or a character is not in the font.
std::optional<CycleError> decodeText(std::string_view text, const DateTime& now,
                                     unsigned long long counter, std::vector<TextToken>& out);

// The date/time format %time<code> (0..15), e.g. 8 -> "DD.MM.YYYY"; nullopt for other codes.
std::optional<std::string> formatTime(int code, const DateTime& now);

}  // namespace kerf::cycles::engraving
