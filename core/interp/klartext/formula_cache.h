#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "core/interp/klartext/compiled_formula.h"

namespace kerf::klartext {

// The Q formulas of recently executed blocks, compiled. Keyed on the formula's text to the end of
// its block, which alone decides how it parses; direct-mapped, so its size stays the same however
// long the program is, and a formula that executes once costs one recording.
class FormulaCache {
public:
    struct Entry {
        std::string text;   // the formula and the rest of its block; empty: nothing recorded
        size_t length = 0;  // characters the formula takes
        CompiledFormula formula;
    };

    // The only entry that can hold the formula starting `text`; it holds it if its text is equal.
    Entry& entryFor(std::string_view text);

private:
    static constexpr size_t kEntries = 256;
    std::vector<Entry> m_entries = std::vector<Entry>(kEntries);
};

}  // namespace kerf::klartext
