#pragma once

#include <string>
#include <string_view>

namespace kerf::program {

// Text encodings seen in NC files: comments written on controls and PCs in Europe (cp1252) and
// China (GBK). Syntax is ASCII, so only comments, strings and messages depend on it.
enum class Encoding : uint8_t { Utf8, Cp1252, Gbk };

const char* encodingName(Encoding encoding);

bool isValidUtf8(std::string_view bytes);

// Guesses the encoding: valid UTF-8 wins; otherwise GBK if its high bytes come mostly in pairs
// (Chinese text), else cp1252 (isolated accented letters between ASCII ones).
Encoding detectEncoding(std::string_view bytes);

// Converts to UTF-8; bytes the encoding does not define become U+FFFD.
std::string toUtf8(std::string_view bytes, Encoding encoding);

// Converts UTF-8 text back to the encoding, for saving a file as it was read; characters the
// encoding cannot hold become '?'.
std::string fromUtf8(std::string_view text, Encoding encoding);

}  // namespace kerf::program
