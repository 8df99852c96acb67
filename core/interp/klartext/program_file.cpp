#include "core/interp/klartext/program_file.h"

#include <chrono>
#include <set>
#include <thread>
#include <type_traits>
#include <vector>

#include "core/cycles/cycle_registry.h"
#include "core/cycles/legacy/legacy_cycles.h"
#include "core/cycles/probing/probing_cycle.h"
#include "core/cycles/probing/single_touch.h"
#include "core/interp/klartext/block_parser.h"
#include "core/interp/klartext/block_reader.h"
#include "core/interp/klartext/contour_labels.h"
#include "core/interp/klartext/cursor.h"
#include "core/interp/klartext/cycle_definition_check.h"
#include "core/interp/klartext/statement_axes.h"
#include "core/program/mapped_copy.h"

namespace kerf::klartext {

const LabelPosition* ProgramFile::findLabel(int number) const {
    auto it = numberedLabels.find(number);
    return it == numberedLabels.end() ? nullptr : &it->second;
}

const LabelPosition* ProgramFile::findLabel(const std::string& name) const {
    auto it = namedLabels.find(name);
    return it == namedLabels.end() ? nullptr : &it->second;
}

namespace {

struct PendingTarget {
    LabelTarget target;
    uint32_t line;
    uint32_t column;
};

std::string labelText(const LabelTarget& t) {
    if (t.number) return std::to_string(*t.number);
    std::string quoted(1, '"');
    quoted.append(t.name.value_or(std::string()));
    quoted.push_back('"');
    return quoted;
}

}  // namespace

std::unique_ptr<BlockSyntax> makeSyntax(const ProgramFile& program,
                                        FormulaEnvironment* environment) {
    if (program.syntax != nullptr && *program.syntax) return (*program.syntax)(environment);
    return std::make_unique<BlockParser>(environment);
}

std::string cycle12Program(std::string_view rest) {
    Cursor c(rest);
    c.acceptKeyword("PGM");
    std::string_view path = c.restUntilComment();
    if (path.size() >= 2 && path.front() == '"' && path.back() == '"') {
        path = path.substr(1, path.size() - 2);
    }
    return std::string(path);
}

bool programUsesInch(const ProgramFile& program) {
    auto parser = makeSyntax(program, nullptr);
    BlockReader reader(program.source->text(), parser.get());
    program::LogicalLine line;
    ParsedBlock block;
    while (reader.next(line)) {
        if (!parser->parse(line, block)) return false;
        if (std::holds_alternative<Empty>(block.statement)) continue;
        const auto* begin = std::get_if<BeginPgm>(&block.statement);
        return begin != nullptr && begin->inch;
    }
    return false;
}

void checkProgram(ProgramFile& program) {
    DiagnosticList& out = program.diagnostics;
    out.clear();
    program.numberedLabels.clear();
    program.namedLabels.clear();
    program.calls.clear();
    const std::string& file = program.source->path();
    auto parser = makeSyntax(program, nullptr);
    BlockReader reader(program.source->text(), parser.get());
    program::LogicalLine line;
    ParsedBlock block;
    std::vector<PendingTarget> targets;
    // Literal TOOL CALLs, checked at the end against the table and the program's TOOL DEFs.
    struct PendingTool {
        ToolCall call;
        uint32_t line = 0;
    };
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

    auto diag = [&](Severity s, const char* code, uint32_t l, uint32_t c, const char* text,
                    std::vector<std::string> args = {}) {
        Diagnostic d = Diagnostic::make(s, code, file, l, c, text);
        d.args = std::move(args);
        appendDiagnostic(out, std::move(d));
    };

    // A feed move before any feed is programmed stops the run ("feed rate is missing"). Followed
    // from the main program's start in file order while that is the order of execution: until
    // the first label, call or jump.
    bool followFeed = program.mainProgram;
    bool feedKnown = false;
    bool toolCallFeedKnown = false;  // FAUTO takes the feed of a TOOL CALL
    // After FUNCTION TCPM ... AXIS SPAT, A, B and C are the tool's spatial angles, not axes.
    AxisMask spatialAngles = 0;
    auto feedMove = [&](const FeedWord& feed) {
        if (!followFeed) return;
        if (feed.kind == FeedWord::Kind::Max) return;  // FMAX needs none and sets none
        if (feed.kind == FeedWord::Kind::Auto && !toolCallFeedKnown) {
            diag(Severity::Error, "feed", line.firstLine, 1,
                 KERF_TR_NOOP("FAUTO: the TOOL CALL block gave no feed rate F"));
            followFeed = false;
            return;
        }
        if (feed.kind != FeedWord::Kind::None) {
            feedKnown = true;  // F words and FAUTO set the feed
            return;
        }
        if (feedKnown) return;
        diag(Severity::Error, "feed", line.firstLine, 1, KERF_TR_NOOP("feed rate is missing"));
        followFeed = false;  // one report; the run stops here
    };

    // Beside a run, the check keeps at most this far ahead of it, so that only the text between
    // them is resident (a long program's mapped copy, mapped_copy.h); alone, it lets the text
    // behind it go.
    constexpr size_t kWindow = 4 * program::kTextReleaseStep;
    size_t releasedBefore = 0;
    while (reader.next(line)) {
        if (program.followExecution) {
            while (line.offset > kWindow &&
                   line.offset - kWindow > program.executionOffset.load()) {
                std::this_thread::sleep_for(std::chrono::microseconds(200));
            }
        } else if (line.offset >= releasedBefore + program::kTextReleaseStep) {
            releasedBefore = line.offset;
            program::releasePagesBefore(program.source->text(), line.offset);
        }
        if (!parser->parse(line, block)) {
            const ParseProblem& p = parser->problem();
            Diagnostic d = Diagnostic::make(Severity::Error, p.code, file, line.lineAt(p.offset),
                                            line.columnAt(p.offset), p.messageTemplate);
            d.args = p.args;
            appendDiagnostic(out, std::move(d));
            firstBlock = false;
            continue;
        }
        const bool empty = std::holds_alternative<Empty>(block.statement);
        if (block.blockNumber >= 0) {
            ++numbered;
            if (block.blockNumber <= lastNumber && !reportedOrder) {
                diag(Severity::Warning, "block-number", line.firstLine, 1,
                     KERF_TR_NOOP("block number {1} is out of order (after {2})"),
                     {std::to_string(block.blockNumber), std::to_string(lastNumber)});
                reportedOrder = true;
            }
            lastNumber = block.blockNumber;
        } else if (!line.text.empty()) {
            if (unnumbered++ == 0) firstUnnumberedLine = line.firstLine;
        }
        // A program the block names (CALL PGM, the contour formula's programs) is checked too.
        auto addCall = [&](const std::string& name) {
            const size_t at = line.text.find(name);
            program.calls.push_back({name, line.lineAt(at == std::string_view::npos ? 0 : at),
                                     line.columnAt(at == std::string_view::npos ? 0 : at)});
        };
        auto addTable = [&](const std::string& name, TableReference::Kind kind) {
            const size_t at = line.text.find(name);
            program.tables.push_back({name, kind,
                                      line.lineAt(at == std::string_view::npos ? 0 : at),
                                      line.columnAt(at == std::string_view::npos ? 0 : at)});
        };
        // Cycle 14's labels must exist in the program, as CALL LBL's do.
        auto contourLabelTargets = [&](const CycleDefinition& cycle) {
            const std::string& text = cycle.subNumber == 1 ? cycle.rest : cycle.name;
            const size_t found = line.text.find(text);
            const size_t base = found == std::string_view::npos ? 0 : found;
            const ContourLabelList list = parseContourLabels(text);
            if (list.error != nullptr) {
                diag(Severity::Error, "cycle-syntax", line.lineAt(base + list.errorOffset),
                     line.columnAt(base + list.errorOffset), list.error);
                return;
            }
            for (const ContourLabel& label : list.labels) {
                LabelTarget target;
                target.number = label.number;
                targets.push_back(
                    {target, line.lineAt(base + label.offset), line.columnAt(base + label.offset)});
            }
        };
        auto checkStatement = [&](const Statement& s) {
            if (const auto* tcpm = std::get_if<TcpmBlock>(&s))
                spatialAngles = tcpm->on && tcpm->spatialAngles ? axisMaskOf("ABC") : 0;
            if (auto missing = axisMissingFrom(s, program.machineAxes | spatialAngles)) {
                diag(Severity::Error, "axis", line.firstLine, columnOfAxisWord(line.text, *missing),
                     KERF_TR_NOOP("this machine has no axis {1}"),
                     {std::string(1, axisLetter(*missing))});
            }
            std::visit(
                [&](const auto& b) {
                    using T = std::decay_t<decltype(b)>;
                    if constexpr (std::is_same_v<T, Label> || std::is_same_v<T, CallLabel> ||
                                  std::is_same_v<T, CallPgm> ||
                                  std::is_same_v<T, ConditionalJump>) {
                        followFeed = false;
                    } else if constexpr (std::is_same_v<T, ToolCall>) {
                        if (b.feed) toolCallFeedKnown = true;
                    } else if constexpr (std::is_same_v<T, RoundBlock> ||
                                         std::is_same_v<T, ChamferBlock>) {
                        if (b.feed.kind != FeedWord::Kind::None) feedMove(b.feed);
                    } else if constexpr (std::is_same_v<T, PlaneBlock>) {
                        if (b.feed.kind != FeedWord::Kind::None) feedMove(b.feed);
                    } else if constexpr (std::is_same_v<T, CycleCall> ||
                                         std::is_same_v<T, MFunctionBlock>) {
                        if (b.words.feed.kind != FeedWord::Kind::None) feedMove(b.words.feed);
                    } else if constexpr (requires { b.words.feed; }) {
                        feedMove(b.words.feed);  // L, C, CR, CT, LP, CP, CTP, APPR/DEP, FK
                    }
                },
                s);
            if (const auto* begin = std::get_if<BeginPgm>(&s)) {
                if (!firstBlock || sawBegin) {
                    diag(Severity::Error, "structure", line.firstLine, 1,
                         KERF_TR_NOOP("BEGIN PGM must be the first block"));
                }
                sawBegin = true;
                beginName = begin->name;
                program.inch = begin->inch;
            } else if (const auto* end = std::get_if<EndPgm>(&s)) {
                if (sawBegin && end->name != beginName) {
                    diag(Severity::Warning, "structure", line.firstLine, 1,
                         KERF_TR_NOOP("END PGM {1} does not match BEGIN PGM {2}"),
                         {end->name, beginName});
                }
                sawEnd = true;
            } else if (const auto* label = std::get_if<Label>(&s)) {
                LabelPosition position{line.nextOffset, reader.line()};
                bool duplicate = false;
                if (label->target.number) {
                    if (*label->target.number != 0) {
                        duplicate =
                            !program.numberedLabels.emplace(*label->target.number, position).second;
                    }
                } else if (label->target.name) {
                    duplicate = !program.namedLabels.emplace(*label->target.name, position).second;
                }
                if (duplicate) {
                    diag(Severity::Error, "label", line.firstLine, 1,
                         KERF_TR_NOOP("label {1} is defined twice"), {labelText(label->target)});
                }
            } else if (const auto* callPgm = std::get_if<CallPgm>(&s)) {
                addCall(callPgm->path);
            } else if (const auto* selected = std::get_if<SelectProgram>(&s)) {
                // A name from a string parameter is only known when the block runs.
                if (!selected->fromParameter) addCall(selected->path);
            } else if (const auto* table = std::get_if<SelectTable>(&s)) {
                addTable(table->path, TableReference::Kind::Datum);
            } else if (const auto* pattern = std::get_if<SelectPattern>(&s)) {
                addTable(pattern->path, TableReference::Kind::Point);
            } else if (const auto* select = std::get_if<SelectContour>(&s)) {
                addCall(select->path);
            } else if (const auto* declare = std::get_if<DeclareContour>(&s)) {
                addCall(declare->path);
                declaredContours.insert(declare->descriptor);
            } else if (const auto* definition = std::get_if<ContourDefinition>(&s)) {
                for (const ContourDefinition::Item& item : definition->items) {
                    if (!item.label) {
                        addCall(item.path);
                        continue;
                    }
                    targets.push_back(
                        {*item.label, line.lineAt(item.offset), line.columnAt(item.offset)});
                }
            } else if (const auto* formula = std::get_if<ContourFormula>(&s)) {
                for (const ContourFormulaStep& step : formula->steps) {
                    if (step.kind == ContourFormulaStep::Kind::Descriptor &&
                        !declaredContours.count(step.descriptor)) {
                        diag(Severity::Error, "contour", line.lineAt(step.offset),
                             line.columnAt(step.offset),
                             KERF_TR_NOOP("QC{1} is not declared (DECLARE CONTOUR)"),
                             {std::to_string(step.descriptor)});
                    }
                }
                declaredContours.insert(formula->target);
            } else if (const auto* tool = std::get_if<ToolCall>(&s)) {
                if (program.tools != nullptr) toolCalls.push_back({*tool, line.firstLine});
            } else if (const auto* def = std::get_if<ToolDef>(&s)) {
                if (def->number) definedNumbers.insert(*def->number);
                if (def->name) definedNames.insert(*def->name);
            } else if (const auto* call = std::get_if<CallLabel>(&s)) {
                targets.push_back({call->target, line.firstLine, 1});
            } else if (const auto* jump = std::get_if<ConditionalJump>(&s)) {
                targets.push_back({jump->target, line.firstLine, 1});
            } else if (const auto* deferred = std::get_if<Deferred>(&s)) {
                diag(Severity::Error, "not-supported", line.firstLine, 1,
                     KERF_TR_NOOP(
                         "{1} is not supported yet; the program cannot run past this block"),
                     {deferred->feature});
            } else if (const auto* cycle = std::get_if<CycleDefinition>(&s)) {
                const bool known =
                    cycle->subNumber >= 0
                        ? cycles::probing::findOldToolProbeCycle(cycle->number) != nullptr ||
                              cycles::probing::isSingleTouchCycle(cycle->number)
                        : cycles::probing::findProbingCycle(cycle->number) != nullptr;
                if (cycle->probe && !known) {
                    diag(Severity::Error, "not-supported", line.firstLine, 1,
                         KERF_TR_NOOP("touch probe cycle {1} is not supported yet; the program "
                                      "cannot run past this block"),
                         {std::to_string(cycle->number)});
                } else if (!cycle->probe && cycle->subNumber <= 0 &&
                           cycles::findCycle(cycle->number) == nullptr &&
                           cycles::findLegacyCycle(cycle->number) == nullptr) {
                    diag(Severity::Error, "not-supported", line.firstLine, 1,
                         KERF_TR_NOOP("cycle {1} is not supported yet; the program cannot run past "
                                      "this block"),
                         {std::to_string(cycle->number)});
                }
                if (cycle->number == 12 && cycle->subNumber == 1 && !cycle->probe) {
                    const std::string called = cycle12Program(cycle->rest);
                    if (!called.empty()) addCall(called);
                }
                checkCycleParameters(*cycle, line, file, out);
                if (!cycle->probe && cycle->number == 14 &&
                    (cycle->subNumber == 1 || cycle->subNumber < 0)) {
                    contourLabelTargets(*cycle);
                }
            }
        };
        checkStatement(block.statement);
        for (const Statement& s : block.more)
            checkStatement(s);
        if (!empty) firstBlock = false;
    }
    for (const PendingTarget& t : targets) {
        if (t.target.stringParameter) continue;  // resolved at run time
        bool known = t.target.number ? program.findLabel(*t.target.number) != nullptr
                                     : program.findLabel(*t.target.name) != nullptr;
        if (!known) {
            diag(Severity::Error, "label", t.line, t.column,
                 KERF_TR_NOOP("label {1} is not defined"), {labelText(t.target)});
        }
    }
    // As the run would: a tool neither in the table nor defined in the program stops it. Tool 0
    // (no tool) and tools named by Q parameters (0 or "" here) are the run's to check.
    for (const PendingTool& t : toolCalls) {
        const ToolCall& c = t.call;
        const bool byNumber = c.number && *c.number != 0;
        const bool byName = !c.number && c.name && !c.name->empty();
        if (byNumber && (definedNumbers.count(*c.number) || program.tools->byNumber(*c.number)))
            continue;
        if (byName && (definedNames.count(*c.name) || program.tools->byName(*c.name))) continue;
        if (!byNumber && !byName) continue;
        diag(Severity::Error, "tool", t.line, 1, KERF_TR_NOOP("tool {1} is not in the tool table"),
             {byNumber ? std::to_string(*c.number) : "\"" + *c.name + "\""});
    }
    if (numbered > 0 && unnumbered > 0) {
        diag(Severity::Warning, "block-number", firstUnnumberedLine, 1,
             KERF_TR_NOOP("block has no number while others have"));
    }
    if (!sawBegin) {
        diag(Severity::Warning, "structure", 1, 1,
             KERF_TR_NOOP("the program has no BEGIN PGM block"));
    }
    if (sawBegin && !sawEnd) {
        diag(Severity::Warning, "structure", reader.line(), 1,
             KERF_TR_NOOP("the program has no END PGM block"));
    }
}

}  // namespace kerf::klartext
