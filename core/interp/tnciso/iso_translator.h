#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/interp/klartext/formula.h"
#include "core/interp/klartext/statements.h"
#include "core/interp/tnciso/iso_words.h"
#include "core/program/line_reader.h"

namespace kerf::tnciso {

// A conversational block written for one DIN/ISO block, piece by piece, remembering where each
// piece came from so that a problem found in it points at the ISO text.
class ConversationalBlock {
public:
    struct Piece {
        size_t start = 0;      // in text()
        size_t length = 0;     // in text()
        size_t isoOffset = 0;  // in the ISO block
        size_t isoLength = 0;
    };

    // Appends `text` made from the ISO text at isoOffset..+isoLength, then a blank unless
    // `joined` (a word's key joined to its value).
    void add(std::string_view text, size_t isoOffset, size_t isoLength = 0, bool joined = false);
    // Starts a further line: the cycle parameter lines of a CYCL DEF.
    void newLine() { m_lineStarts.push_back(m_text.size()); }

    void clear();
    const std::string& text() const { return m_text; }
    const std::vector<size_t>& lineStarts() const { return m_lineStarts; }
    // The ISO offset of an offset in text().
    size_t isoOffset(size_t offset) const;

private:
    std::string m_text;
    std::vector<Piece> m_pieces;
    std::vector<size_t> m_lineStarts{0};
};

struct Translation {
    std::optional<klartext::Statement> direct;  // a statement made without a conversational twin
    int64_t blockNumber = -1;
    bool hidden = false;

    std::span<const ConversationalBlock> blocks() const { return {m_blocks.data(), m_count}; }
    ConversationalBlock& newBlock();  // reuses the storage of earlier blocks
    ConversationalBlock& lastBlock() { return m_blocks[m_count - 1]; }
    void clear();

private:
    std::vector<ConversationalBlock> m_blocks;
    size_t m_count = 0;
};

// A special function written with its conversational words at `at` ("SEL TABLE", "GLOBAL DEF",
// "PATTERN DEF", "FUNCTION", "PLANE", "CONTOUR DEF", "DECLARE CONTOUR", "QC1 = ...").
bool isSpecialFunction(std::string_view text, size_t at);  // iso_translator_special.cpp

// Turns DIN/ISO blocks into conversational ones. The path function (G00, G01, G02 ...) and
// absolute/incremental dimensions (G90/G91) are modal: the translator keeps them, so blocks must
// be given in the order they run.
class IsoTranslator {
public:
    bool translate(const program::LogicalLine& line, Translation& out);
    const klartext::ParseProblem& problem() const { return m_problem; }
    // The next block is the first of a program: a "%NAME G71" there opens it, even when NAME is
    // the open program (a program that calls itself), instead of ending it.
    void startProgram() { m_atProgramStart = true; }

private:
    struct Context;
    bool translateWords(Context& c);
    bool translateProgramWord(Context& c, size_t at, bool programStart);
    bool translateDFunction(Context& c, size_t at);
    bool translateMotion(Context& c, int motion);
    // NX NY NZ [TX TY TZ] of a G00/G01 block: the words of the LN block it becomes.
    bool addSurfaceVectors(Context& c, ConversationalBlock& b);
    bool translateCycle(Context& c, const IsoWord& g);  // iso_translator_cycles.cpp
    bool translateOldCycle(Context& c, const IsoWord& g,
                           bool& handled);                       // iso_translator_cycles.cpp
    bool translateThreadCutting(Context& c);                     // iso_translator_cycles.cpp
    bool translateReferencePlane(Context& c, const IsoWord& g);  // iso_translator_cycles.cpp
    void translateSpecialFunction(Context& c, size_t at);        // iso_translator_special.cpp
    bool fail(size_t offset, const char* messageTemplate, std::vector<std::string> args = {});

    klartext::ParseProblem m_problem;
    IsoWords m_words;
    std::vector<bool> m_used;         // per word of m_words: taken by the translation
    std::vector<std::string> m_open;  // names of the programs whose header "%NAME G71" was read
    int m_motion = -1;                // modal path function: 0, 1, 2, 3, 5, 6, 10 ... 16
    bool m_incremental = false;       // G91
    bool m_atProgramStart = false;    // no block of the program read yet (startProgram)
};

}  // namespace kerf::tnciso
