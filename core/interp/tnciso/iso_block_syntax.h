#pragma once

#include "core/interp/klartext/block_parser.h"
#include "core/interp/tnciso/iso_translator.h"

namespace kerf::tnciso {

// The DIN/ISO syntax of the TNC: each block is written as the conversational block(s) it means
// and parsed by the conversational parser, so values, formulas, cycle parameters and their
// errors are the same in both dialects. Problems point at the ISO text.
class IsoBlockSyntax final : public klartext::BlockSyntax {
public:
    explicit IsoBlockSyntax(klartext::FormulaEnvironment* environment) : m_parser(environment) {}

    bool parse(const program::LogicalLine& line, klartext::ParsedBlock& out) override;
    const klartext::ParseProblem& problem() const override { return m_problem; }
    // A cycle block ("N10 G200 ...", "G251") takes the indented parameter lines below it.
    bool takesParameterLines(std::string_view text) const override;
    void startProgram() override { m_translator.startProgram(); }

private:
    // Parses one conversational block into `out` (its statement; number and skip mark are the
    // ISO block's).
    bool parseBlock(const program::LogicalLine& isoLine, const ConversationalBlock& block,
                    klartext::ParsedBlock& out);

    klartext::BlockParser m_parser;
    IsoTranslator m_translator;
    Translation m_translation;
    program::LogicalLine m_line;  // the conversational block being parsed
    klartext::ParsedBlock m_parsed;
    klartext::ParseProblem m_problem;
};

}  // namespace kerf::tnciso
