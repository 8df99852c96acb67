#pragma once

#include <QString>
#include <QStringView>
#include <optional>

#include "core/program/dialect.h"

namespace kerf::ui {

// Block numbers as the controls write them: Klartext starts every line with its 0-based index
// ("0 BEGIN PGM ..."); ISO programs use N words ("N10 G00 ..."), usually in steps of 10.

// The line's block number and how many characters it takes (leading spaces and N included).
struct BlockNumber {
    long long number = 0;
    int length = 0;
};
std::optional<BlockNumber> readBlockNumber(QStringView line, program::Dialect dialect);

// The text that starts a new line after `line` ("13 " after "12 L X+0"; "N30 " after "N20 ..."
// with step 10); empty when the line carries no block number.
QString nextBlockPrefix(QStringView line, QStringView previousLine, program::Dialect dialect);

// `line` with its block number replaced by `number`; unchanged if it has none.
QString withBlockNumber(QStringView line, long long number, program::Dialect dialect);

}  // namespace kerf::ui
