#pragma once

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/interp/klartext/block_reader.h"
#include "core/interp/klartext/program_file.h"

namespace kerf::klartext {

// The check of one program (checkProgram), block by block in file order. A run that reads the
// program in the same order hands over the blocks it has parsed (take), so a plain program is
// parsed once: the check parses only what the run has not, or what it parses differently.
class ProgramCheck {
public:
    explicit ProgramCheck(ProgramFile& target);
    ~ProgramCheck();
    ProgramCheck(const ProgramCheck&) = delete;
    ProgramCheck& operator=(const ProgramCheck&) = delete;

    // The run parsed `runBlock` from `runLine`. If that is the block the check reads next, it is
    // checked: as parsed when the check's own parse would be the same (a literal L, C, CC, CR,
    // CT, LP, CP or empty block of conversational text: no Q parameter, no formula), else parsed
    // again. Any other block is left for the check to read itself.
    void take(const program::LogicalLine& runLine, const ParsedBlock& runBlock);
    // Checks the rest of the program and completes the findings (labels, tools, structure) in
    // ProgramFile::diagnostics.
    void finish();

private:
    struct PendingTarget {
        LabelTarget target;
        uint32_t line;
        uint32_t column;
    };
    // Literal TOOL CALLs, checked at the end against the table and the program's TOOL DEFs.
    struct PendingTool {
        ToolCall call;
        uint32_t line = 0;
    };

    static bool sameParse(const program::LogicalLine& line, const ParsedBlock& block);
    bool step();  // reads, parses and checks the next block; false at the end
    void check(const program::LogicalLine& line, const ParsedBlock& block);
    void diag(Severity s, const char* code, uint32_t l, uint32_t c, const char* text,
              std::vector<std::string> args = {});

    ProgramFile& checked;
    DiagnosticList& out;
    const std::string& file;
    std::unique_ptr<BlockSyntax> parser;
    BlockReader reader;
    program::LogicalLine ownLine;
    ParsedBlock ownBlock;
    std::vector<PendingTarget> targets;
    std::vector<PendingTool> toolCalls;
    std::set<int> definedNumbers;
    std::set<std::string> definedNames;
    std::set<int> declaredContours;  // QC descriptors (contour formula)
    bool sawBegin = false, sawEnd = false, firstBlock = true;
    std::string beginName;
    int64_t lastNumber = -1;
    size_t numbered = 0, unnumbered = 0;
    uint32_t firstUnnumberedLine = 0;
    bool reportedOrder = false;
    bool followFeed;
    bool feedKnown = false;
    bool toolCallFeedKnown = false;  // FAUTO takes the feed of a TOOL CALL
    // After FUNCTION TCPM ... AXIS SPAT, A, B and C are the tool's spatial angles, not axes.
    AxisMask spatialAngles = 0;
};

}  // namespace kerf::klartext
