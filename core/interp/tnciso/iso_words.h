#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/interp/klartext/formula.h"

namespace kerf::tnciso {

// One address word of a DIN/ISO block as written: "G01", "X+10", "R(Q1*2)", "P01 +5", "L1,2",
// "DR-0.1", "FMAX". Values are kept as text; the conversational parser evaluates them.
struct IsoWord {
    std::string_view key;       // upper-case letters: "G", "X", "DR2", "P", "FMAX", "PAT", "\""
    int number = -1;            // G, M, P and D: the number after the letter
    std::string_view value;     // the value as written ("+10", "Q5", "(Q1+2)"; a name for '"')
    size_t offset = 0;          // where the word starts in the block text
    size_t valueOffset = 0;     // where its value starts
    std::optional<int> repeat;  // "L1,2": 2
};

// An ISO block split into its words. Cycle parameters ("Q200=2 ;comment ...") end the words.
struct IsoWords {
    std::vector<IsoWord> words;
    size_t parametersAt = std::string_view::npos;  // the first "Qnnn=" of a cycle
    uint32_t letters = 0;  // bit n: a word whose key starts with letter 'A' + n (quick lookups)
    bool hasLetter(char upperLetter) const {
        return upperLetter >= 'A' && upperLetter <= 'Z' &&
               (letters & (1u << (upperLetter - 'A'))) != 0;
    }
    const IsoWord* find(std::string_view key) const;
    const IsoWord* findG(int number) const;
};

// "G04" for 4, "G200" for 200: a G number as the manual writes it, without the G.
std::string gNumber(int number);

// Splits `text` from `from` up to the block end '*' or a ';' comment. False (with `problem`) on
// a word that cannot be read.
bool scanWords(std::string_view text, size_t from, IsoWords& out, klartext::ParseProblem& problem);

// The extent of a value after a word letter: signed number, Q/QL/QR reference or "(formula)".
// Returns its end, or npos when no value starts at `at`.
size_t valueEnd(std::string_view text, size_t at);

}  // namespace kerf::tnciso
