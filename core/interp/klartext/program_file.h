#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/geometry/axes.h"
#include "core/interp/klartext/block_syntax.h"
#include "core/program/source_text.h"
#include "core/tables/tool_table.h"

namespace kerf::klartext {

// Where execution continues after a label: the line after the LBL block.
struct LabelPosition {
    size_t offset = 0;
    uint32_t line = 0;
};

// A `CALL PGM` block as the check found it, so the called program can be checked too.
struct ProgramCall {
    std::string name;
    uint32_t line = 0;
    uint32_t column = 0;
};

// A table a block selects (SEL TABLE, SEL PATTERN), so the check can read it before the run.
struct TableReference {
    enum class Kind { Datum, Point };
    std::string name;
    Kind kind = Kind::Datum;
    uint32_t line = 0;
    uint32_t column = 0;
};

// A loaded conversational program with its label index, built by a full syntax check.
struct ProgramFile {
    std::shared_ptr<const program::SourceText> source;
    uint32_t fileId = 0;
    std::filesystem::path folder;
    std::unordered_map<int, LabelPosition> numberedLabels;
    std::unordered_map<std::string, LabelPosition> namedLabels;
    bool inch = false;
    DiagnosticList diagnostics;  // from the check; errors mean the program cannot run
    std::vector<ProgramCall> calls;
    std::vector<TableReference> tables;
    // The program's syntax when it is not conversational (a DIN/ISO program); not owned.
    const SyntaxMaker* syntax = nullptr;
    // The tool table the program runs with (nullptr: none): literal TOOL CALLs are checked
    // against it and the program's own TOOL DEFs.
    const tables::ToolTable* tools = nullptr;
    AxisMask machineAxes =
        kAllAxesMask;  // the axes the machine has; every axis when there is no machine

    // For a check running alongside execution: how far execution has read. The check stays
    // within a window ahead of it so the text between them is all that is resident; SIZE_MAX lets
    // it run freely (execution waits for it).
    std::atomic<size_t> executionOffset{SIZE_MAX};
    bool followExecution = false;
    // The program the run starts with (not one it calls): only its flow is known from its start.
    bool mainProgram = false;

    const LabelPosition* findLabel(int number) const;
    const LabelPosition* findLabel(const std::string& name) const;
};

// Checks every block of the program's syntax, indexes its labels and reports what cannot run:
// unknown jump targets, labels defined twice, features this release parses but does not execute
// (errors: the program could not run to its end), missing BEGIN/END PGM and block numbers out of
// order (warnings).
void checkProgram(ProgramFile& program);

// The program a `CYCL DEF 12.1 PGM name` block calls: its text after "12.1" without "PGM" and
// quotes (empty when it names none).
std::string cycle12Program(std::string_view rest);

// Whether the program's BEGIN PGM block says INCH (its first block; MM otherwise).
bool programUsesInch(const ProgramFile& program);

// A parser for the program's syntax, evaluating through `environment` (nullptr: check only).
std::unique_ptr<BlockSyntax> makeSyntax(const ProgramFile& program,
                                        FormulaEnvironment* environment);

}  // namespace kerf::klartext
