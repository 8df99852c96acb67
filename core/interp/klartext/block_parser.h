#pragma once

#include "core/interp/klartext/block_syntax.h"

namespace kerf::klartext {

// Parses one logical line of a conversational program into a statement, evaluating the values it
// contains through `environment` (nullptr: syntax check only, values read as 0).
class BlockParser final : public BlockSyntax {
public:
    explicit BlockParser(FormulaEnvironment* environment) : m_env(environment) {}

    // False on a syntax error; problem() then says where (offset in line.text) and what.
    bool parse(const program::LogicalLine& line, ParsedBlock& out) override;
    const ParseProblem& problem() const override { return m_problem; }
    // CYCL DEF, GLOBAL DEF, PATTERN DEF and TCH PROBE take indented parameter lines.
    bool takesParameterLines(std::string_view text) const override;

    // The head word of a block (after its number), for callers that need to know the block kind
    // before parsing it, e.g. "CYCL" or "LBL".
    static std::string_view headWord(std::string_view text);

    struct Context;  // parse state shared by the helpers in block_parser.cpp

private:
    bool parseStatement(Context& c, const program::LogicalLine& line, ParsedBlock& out);
    // A literal L block read in one pass (block_parser_literal_line.cpp); false leaves the block
    // to parseStatement, with `out` to be overwritten.
    bool parseLiteralLine(std::string_view text, size_t at, ParsedBlock& out);
    // Cycle blocks (block_parser_cycles.cpp). Each reports a problem in m_problem.
    // `probe`: TCH PROBE n, whose sub-blocks stay text (31.1 CHECK: 1 Q5).
    bool parseCycleDef(const program::LogicalLine& line, size_t at, ParsedBlock& out,
                       bool probe = false);
    // The parameters on the lines after the header, and from `headerFrom` on the header line.
    bool parseCycleParameters(const program::LogicalLine& line, std::vector<CycleParameter>& out,
                              size_t headerFrom = std::string_view::npos);
    bool parseCycleParameter(std::string_view text, size_t at, std::vector<CycleParameter>& out);
    bool parseCycleWords(std::string_view text, size_t from, cycles::CycleWords& out);
    bool parseGlobalDef(const program::LogicalLine& line, size_t at, ParsedBlock& out);
    bool parsePatternDef(const program::LogicalLine& line, size_t at, ParsedBlock& out);
    bool parsePlane(const program::LogicalLine& line, size_t at, ParsedBlock& out);
    // FUNCTION TCPM / FUNCTION RESET TCPM; false with nothing reported for other FUNCTIONs.
    bool parseTcpm(const program::LogicalLine& line, size_t at, ParsedBlock& out, bool& handled);
    // FUNCTION MODE MILL (after MODE): the only mode of a milling machine, so nothing changes.
    bool parseFunctionMode(Cursor& cur, ParsedBlock& out);
    bool parseValue(Cursor& cursor, double& out);
    // FK free contour blocks (block_parser_fk.cpp); `head` is FPOL, FL, FLT, FC, FCT or FSELECT.
    bool parseFk(std::string_view head, const program::LogicalLine& line, size_t at,
                 ParsedBlock& out);
    // Contour formula blocks (block_parser_contour_formula.cpp); `head` is SEL or DECLARE (before
    // CONTOUR), CONTOUR (before DEF) or QC, whose `at` is where QC starts.
    bool parseContourFormula(std::string_view head, const program::LogicalLine& line, size_t at,
                             ParsedBlock& out);
    bool failAt(size_t offset, const char* code, const char* messageTemplate,
                std::vector<std::string> args = {});

    FormulaEnvironment* m_env;
    // The text of the last line parseLiteralLine gave up on (compared by address and length).
    std::string_view m_generalLine;
    FormulaCache m_formulas;  // Q formulas of loops and subprograms, compiled
    ParseProblem m_problem;
};

}  // namespace kerf::klartext
