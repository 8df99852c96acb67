#pragma once

#include <string_view>

#include "core/interp/fagor/parsed_block.h"
#include "core/interp/fagor/problem.h"
#include "core/interp/fagor/scanner.h"

namespace kerf::fagor {

// Reads one line of a FAGOR program into a ParsedBlock (spec part 1 §3): skip marks, label,
// an ISO body (words with parameters substituted through `source`) or a high-level body in
// parentheses, repetition count and comment. High-level bodies are only delimited here; the
// statement runner reads them.
class BlockParser {
public:
    explicit BlockParser(ParameterSource* source) : m_source(source) {}

    // `firstLine`: the line may be the "%..." transfer header. False on an error: problem().
    bool parse(std::string_view text, bool firstLine, ParsedBlock& out);
    const Problem& problem() const { return m_problem; }

private:
    bool header(Scanner& s, ParsedBlock& out);
    bool body(Scanner& s, ParsedBlock& out);
    bool highLevel(Scanner& s, ParsedBlock& out);
    bool trailer(Scanner& s, ParsedBlock& out);
    bool isoWords(Scanner& s, ParsedBlock& out);
    bool gArguments(Scanner& s, int g, IsoBlock& iso);
    bool cycleWord(Scanner& s, char letter, size_t offset, CycleWords& cycle);
    bool cycleComplete(const IsoBlock& iso);
    bool known(const WordValue& w) const { return !(w.parameter && m_source == nullptr); }
    bool value(Scanner& s, char letter, WordValue& out);
    bool format(const WordValue& w, char letter, int intDigits, int decDigits, bool sign);
    bool integer(const WordValue& w, char letter, double lo, double hi);
    bool fail(size_t offset, const char* code, const char* messageTemplate,
              std::vector<std::string> args = {});

    ParameterSource* m_source;
    Problem m_problem;
    // Digits of the literal just read by value() (0 for parameters and bare letters).
    ScannedNumber m_literal;
    bool m_negative = false;
};

}  // namespace kerf::fagor
