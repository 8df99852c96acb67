#include "ui/cycles/cycle_fields.h"

#include <algorithm>
#include <iterator>

namespace kerf::ui {

namespace {

struct OldStyleWord {
    int cycle;
    const char* word;
    int parameterIndex;  // into the descriptor's parameters
    int subBlock;        // 0: a sub-block of its own, numbered in order among the non-empty ones
    WordStyle style;
    bool optional;
};

// The sub-block syntax of the old-style cycles (spec §9, §10 and cycle 18).
constexpr OldStyleWord kOldStyleWords[] = {
    {7, "X", 0, 0, WordStyle::Signed, true},
    {7, "Y", 0, 0, WordStyle::Signed, true},
    {7, "Z", 0, 0, WordStyle::Signed, true},
    {8, "", 0, 1, WordStyle::Bare, true},
    {9, "DWELL", 0, 1, WordStyle::Spaced, false},
    {10, "ROT", 0, 1, WordStyle::Signed, false},
    {11, "SCL", 0, 1, WordStyle::Spaced, false},
    {12, "PGM", 0, 1, WordStyle::Spaced, false},
    {13, "ANGLE", 0, 1, WordStyle::Spaced, false},
    {14, "CONTOUR LABEL", 0, 1, WordStyle::Spaced, false},
    {18, "DEPTH", 0, 1, WordStyle::Equals, false},
    {18, "PITCH", 1, 2, WordStyle::Equals, false},
    {19, "A", 0, 1, WordStyle::Signed, true},
    {19, "B", 0, 1, WordStyle::Signed, true},
    {19, "C", 0, 1, WordStyle::Signed, true},
    {19, "F", 1, 1, WordStyle::Joined, true},
    {19, "DIST", 2, 1, WordStyle::Joined, true},
    {26, "X", 0, 1, WordStyle::Spaced, true},
    {26, "Y", 0, 1, WordStyle::Spaced, true},
    {26, "Z", 0, 1, WordStyle::Spaced, true},
    {26, "CCX", 1, 1, WordStyle::Signed, true},
    {26, "CCY", 1, 1, WordStyle::Signed, true},
    {26, "CCZ", 1, 1, WordStyle::Signed, true},
    {32, "T", 0, 1, WordStyle::Joined, false},
    {32, "HSC-MODE", 1, 2, WordStyle::Colon, true},
    {32, "TA", 2, 2, WordStyle::Joined, true},
};

}  // namespace

std::vector<CycleField> cycleFields(const cycles::CycleDescriptor& cycle) {
    std::vector<CycleField> fields;
    if (!cycle.oldStyle) {
        for (const cycles::ParameterDescriptor& p : cycle.parameters) {
            CycleField field;
            field.parameter = &p;
            field.label = QStringLiteral("Q%1").arg(p.q);
            field.optional = p.optional;
            fields.push_back(field);
        }
        return fields;
    }
    for (const OldStyleWord& w : kOldStyleWords) {
        if (w.cycle != cycle.number) continue;
        const auto index = static_cast<size_t>(w.parameterIndex);
        if (index >= cycle.parameters.size()) continue;
        CycleField field;
        field.parameter = &cycle.parameters[index];
        field.word = QString::fromLatin1(w.word);
        field.label = field.word.isEmpty() ? QStringLiteral("X Y Z") : field.word;
        field.subBlock = w.subBlock;
        field.style = w.style;
        field.optional = w.optional;
        fields.push_back(field);
    }
    return fields;
}

}  // namespace kerf::ui
