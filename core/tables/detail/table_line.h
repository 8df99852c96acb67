#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::tables::detail {

enum class LineEnding : uint8_t { None, Lf, CrLf };

// What a line is to the table; everything but Header and Row is kept as opaque bytes.
enum class LineKind : uint8_t { Begin, Description, Header, Row, Blank, End, Trailer };

// One line of a table file without its line ending, which is remembered separately so that the
// file can be written back byte for byte.
struct TableLine {
    std::string text;
    LineEnding ending = LineEnding::Lf;
    LineKind kind = LineKind::Trailer;
};

// Splits at '\n'; a '\r' just before it belongs to the ending. A last line without '\n' gets
// LineEnding::None; no empty line is invented after a final '\n'.
std::vector<TableLine> splitLines(std::string_view bytes);

std::string_view endingText(LineEnding ending);

std::string_view trimSpaces(std::string_view text);

}  // namespace kerf::tables::detail
