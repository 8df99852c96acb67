#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/geometry/axes.h"
#include "core/program/source_text.h"

namespace kerf::fagor {

// Where a block starts.
struct BlockPosition {
    size_t offset = 0;
    uint32_t line = 0;
};

struct SubroutineEntry {
    int number = 0;
    BlockPosition body;  // the block after (SUB n)
    BlockPosition end;   // the block after (RET)
};

// An EXEC or MEXEC of a program given by a constant number.
struct ProgramCall {
    int number = 0;
    uint32_t line = 0;
    uint32_t column = 0;
};

// A loaded FAGOR program with its label and subroutine index, built by the program check.
struct FagorProgram {
    std::shared_ptr<const program::SourceText> source;
    uint32_t fileId = 0;
    std::filesystem::path path;
    int number = -1;           // from the file name (P012345.PIM, 012345): -1 if it has none
    bool oem = false;          // the header's attributes contain O
    bool keepLabels = false;   // keep the label index even without jumps (RPT P, GPOS from others)
    bool userChannel = false;  // a user customisation program: screen instructions, no ISO blocks
    size_t end = SIZE_MAX;     // an end-of-file character stops the text here
    AxisMask machineAxes = (1u << kAxisCount) - 1;  // the machine's axes; all without a machine
    std::vector<std::pair<uint32_t, BlockPosition>> labels;  // sorted; first occurrence only
    std::vector<SubroutineEntry> subroutines;                // sorted by number
    std::vector<ProgramCall> calls;                          // in the order written
    std::vector<int> opened;     // programs OPEN writes (constant numbers)
    bool opensAny = false;       // an OPEN whose number is known only at run time
    DiagnosticList diagnostics;  // errors mean the program cannot run

    // For a check running alongside execution (see FagorInterpreter::CheckMode).
    std::atomic<size_t> executionOffset{SIZE_MAX};
    bool followExecution = false;

    const BlockPosition* findLabel(int64_t label) const;
    const SubroutineEntry* findSubroutine(int subroutine) const;
};

// Checks every block's syntax and the static rules, indexes labels (a duplicate label warns: the
// first one is used) and subroutines, and reports jumps to labels that do not exist,
// subroutines without RET or defined twice, axis words for axes the machine lacks, and what this
// release does not run (errors: a program that passes the check runs).
void checkProgram(FagorProgram& program);

// The program number a file name gives ("P012345.PIM", "12345", "p7.pit"), or -1.
int programNumberOf(const std::filesystem::path& path);

}  // namespace kerf::fagor
