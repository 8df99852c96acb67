#pragma once

#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

#include "core/cycles/cycle_descriptor.h"
#include "ui/cycles/cycle_fields.h"

namespace kerf::ui {

// Checks what the operator typed into a field: a number in range (whole where required), a
// Q parameter reference, or a keyword the parameter allows (PREDEF, FAUTO, FMAX, FU.., FZ..).
// Returns the message for the operator, in the UI language, or nothing when it is fine.
std::optional<QString> checkFieldText(const cycles::CycleDescriptor& cycle, const CycleField& field,
                                      const QString& text, bool inch);

// A length or feed range/default in the program's unit (inch programs: mm / 25.4).
double inProgramUnit(const cycles::ParameterDescriptor& parameter, double mmValue, bool inch);
// "+2", "-20", "0.25": at most four decimals; `sign` writes '+' before positive numbers.
QString formatNumber(double value, bool sign);
// The field's default as the dialog prefills it (empty for optional old-style words).
QString defaultText(const CycleField& field, bool inch);

// The NC blocks of a cycle definition without block numbers, one string per block (lines of
// a block joined by '\n'): new-style "CYCL DEF 200 DRILLING ~" then "  Q200=+2 ;SET-UP
// CLEARANCE ~" lines; old-style "CYCL DEF 7.0 DATUM SHIFT", "CYCL DEF 7.1 X+60", ... The
// values must have passed checkFieldText; empty optional values are left out.
QStringList writeCycleBlocks(const cycles::CycleDescriptor& cycle,
                             const std::vector<CycleField>& fields, const QStringList& values);

// A cycle definition read back from its blocks (block numbers removed): the cycle and the
// text of each field, in cycleFields() order (empty where the block has no value).
struct ReadCycle {
    const cycles::CycleDescriptor* cycle = nullptr;
    QStringList values;
};
std::optional<ReadCycle> readCycleBlocks(const QStringList& blocks);

// The number of "CYCL DEF 200 ..." or "CYCL DEF 7.0 ..." (sub-block in *subBlock), if the
// text (block number removed) is a cycle definition.
std::optional<int> cycleDefNumber(const QString& blockText, int* subBlock = nullptr);

}  // namespace kerf::ui
