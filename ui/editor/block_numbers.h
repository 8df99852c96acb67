#pragma once

#include <QString>
#include <QStringView>
#include <optional>

#include "core/program/dialect.h"

class QTextDocument;

namespace kerf::ui {

// Block numbers as the controls write them. Klartext counts blocks from 0 ("0 BEGIN PGM ..."); a
// block may span several lines (a '~' at the end of a line continues it, cycle parameters follow
// their CYCL DEF on lines of their own) and only its first line carries the number. ISO programs
// use N words ("N10 G00 ..."), usually in steps of 10.

// The line's block number and how many characters it takes (leading spaces and N included).
struct BlockNumber {
    long long number = 0;
    int length = 0;
};
std::optional<BlockNumber> readBlockNumber(QStringView line, program::Dialect dialect);

// True if a Klartext line ends with the continuation mark '~' (blanks after it allowed).
bool continuesOnNextLine(QStringView line);

// How ISO (TNC DIN/ISO, FAGOR) blocks are numbered: from `first` (nullopt: the program's own
// first number) in steps of `step`. Klartext counts by one from 0 whatever this says.
struct BlockNumbering {
    std::optional<long long> first;
    long long step = 10;
};

// Reads a program's lines in order and says which number each numbered line should carry:
// Klartext the previous block's number + 1 (the first block 0); ISO as `numbering` says. Lines
// continuing a Klartext block carry none, even if they start with digits.
class BlockCounter {
public:
    // `last`: the number of the block before the first line read; -1 at the start of a program.
    explicit BlockCounter(program::Dialect dialect, long long last = -1,
                          BlockNumbering numbering = {})
        : m_dialect(dialect), m_last(last), m_numbering(numbering) {}

    struct Numbered {
        BlockNumber current;
        long long wanted = 0;
    };
    // The next line's number and the one it should carry; nullopt if the line carries none.
    std::optional<Numbered> next(QStringView line);
    long long last() const { return m_last; }
    program::Dialect dialect() const { return m_dialect; }

private:
    program::Dialect m_dialect;
    long long m_last;
    BlockNumbering m_numbering;
    bool m_continued = false;  // the previous line ended with '~'
};

// The text that starts a new line after `line` ("13 " after "12 L X+0"; "N30 " after "N20 ..."
// with step 10); empty when the line carries no block number or continues the previous line.
QString nextBlockPrefix(QStringView line, QStringView previousLine, program::Dialect dialect);

// `line` with its block number replaced by `number`; unchanged if it has none.
QString withBlockNumber(QStringView line, long long number, program::Dialect dialect);

// Places in a document as the operator names them (ui/common/block_name.h). Lines are 1-based.

// The block number line `line` carries; -1 for a line without one, for a line continuing a
// Klartext block (after a '~') and for a line the document does not have.
long long blockNumberOfLine(const QTextDocument& document, int line, program::Dialect dialect);
// The first line that carries block number `number`; nullopt when no line does.
std::optional<int> lineOfBlock(const QTextDocument& document, long long number,
                               program::Dialect dialect);
// True when the program numbers its blocks (one of its first lines carries a number): then the
// operator gives block numbers, otherwise file lines.
bool numbersBlocks(const QTextDocument& document, program::Dialect dialect);

}  // namespace kerf::ui
