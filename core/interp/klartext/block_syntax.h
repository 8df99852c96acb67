#pragma once

#include <functional>
#include <memory>
#include <string_view>

#include "core/interp/klartext/formula.h"
#include "core/interp/klartext/statements.h"
#include "core/program/line_reader.h"

namespace kerf::klartext {

// The surface syntax of one TNC dialect: turns a block of text into the statements the TNC
// engine executes. Conversational text (BlockParser) and DIN/ISO (core/interp/tnciso) share the
// engine, the Q parameters, the cycles and the tables; only this part is their own.
class BlockSyntax {
public:
    virtual ~BlockSyntax() = default;
    // False on a syntax or evaluation error; problem() then says where (offset in line.text).
    virtual bool parse(const program::LogicalLine& line, ParsedBlock& out) = 0;
    virtual const ParseProblem& problem() const = 0;
    // Whether the indented "Qnnn=value" lines below this block (first line) belong to it.
    virtual bool takesParameterLines(std::string_view text) const = 0;
    // The reader starts a program at its beginning (the main program or a called one): its
    // first block is its header even while a program of the same name is open (a self call).
    virtual void startProgram() {}
};

// Makes a syntax that evaluates through `environment` (nullptr: syntax check only).
using SyntaxMaker = std::function<std::unique_ptr<BlockSyntax>(FormulaEnvironment* environment)>;

}  // namespace kerf::klartext
