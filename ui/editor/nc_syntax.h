#pragma once

#include <QStringView>
#include <cstdint>
#include <vector>

#include "core/program/dialect.h"

namespace kerf::ui {

enum class NcToken : uint8_t {
    BlockNumber,
    Keyword,
    Address,
    Number,
    Parameter,
    Function,
    Comment
};

struct NcSpan {
    int start = 0;
    int length = 0;
    NcToken token = NcToken::Keyword;

    friend bool operator==(const NcSpan&, const NcSpan&) = default;
};

// Splits one program line into coloured spans. Every dialect's syntax is line-local, so a
// line can be coloured without looking at its neighbours: this is what lets the editor colour
// only the lines on screen of a million-line program.
//   Klartext: "12 L X+10 Y-5 R0 FMAX M3 ; comment", Q/QL/QR/QS parameters, FN, CYCL DEF ...
//   ISO (TNC and Fagor): "N10 G01 X10 F200 M3 ; comment"; Fagor arithmetic parameters P;
//   after a Fagor canned cycle (G66-G89) its parameter letters are parameters, not functions.
std::vector<NcSpan> scanNcLine(QStringView line, program::Dialect dialect);

}  // namespace kerf::ui
