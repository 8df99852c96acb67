#pragma once

#include <string>
#include <string_view>

namespace kerf::program {

// Text encodings seen in NC files: comments written on controls and PCs in Europe (cp1252) and
// China (GBK), and "Unicode" text of Windows editors (UTF-16 with a byte order mark). Syntax is
// ASCII, so only comments, strings and messages depend on the first three.
enum class Encoding : uint8_t { Utf8, Cp1252, Gbk, Utf16Le, Utf16Be };

const char* encodingName(Encoding encoding);

bool isValidUtf8(std::string_view bytes);

// Guesses the encoding: a UTF-16 byte order mark decides; then valid UTF-8 wins; otherwise GBK if
// its high bytes come mostly in pairs (Chinese text), else cp1252 (isolated accented letters
// between ASCII ones).
Encoding detectEncoding(std::string_view bytes);

// Converts to UTF-8 (without the UTF-16 byte order mark); bytes the encoding does not define
// become U+FFFD.
std::string toUtf8(std::string_view bytes, Encoding encoding);

// Converts UTF-8 text back to the encoding, for saving a file as it was read; characters the
// encoding cannot hold become '?'. UTF-16 gets its byte order mark again.
std::string fromUtf8(std::string_view text, Encoding encoding);

}  // namespace kerf::program
