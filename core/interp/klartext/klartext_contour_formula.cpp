// The contour formula (spec §8): SEL CONTOUR selects a contour-definition program whose DECLARE
// CONTOUR blocks name contour-description programs and whose last QC formula combines them;
// CONTOUR DEF lists pockets and islands directly. Both are read at each SL cycle call, like the
// labels of cycle 14, and handed to the cycles as subcontours and a postfix formula.
#include <cmath>
#include <map>

#include "core/base/translate.h"
#include "core/geometry/contour_region.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

namespace {

constexpr size_t kMaxFormulaContours = 128;  // spec §8: contours of one SL cycle
constexpr size_t kMaxFormulaSteps = 4096;    // a formula of formulas stays bounded

using Kind = cycles::FormulaStep::Kind;

Kind stepKind(ContourFormulaStep::Kind kind) {
    switch (kind) {
        case ContourFormulaStep::Kind::Union:
            return Kind::Union;
        case ContourFormulaStep::Kind::Intersection:
            return Kind::Intersection;
        case ContourFormulaStep::Kind::Difference:
            return Kind::Difference;
        case ContourFormulaStep::Kind::SymmetricDifference:
            return Kind::SymmetricDifference;
        case ContourFormulaStep::Kind::Descriptor:
            break;
    }
    return Kind::Contour;
}

}  // namespace

// What a definition program declared so far: each descriptor as a postfix formula over the
// captured contours (a declared contour is one step).
struct KlartextInterpreter::FormulaBuild {
    std::filesystem::path folder;
    bool isoCaller = false;  // the definition program is a DIN/ISO one
    cycles::ContourFormula formula;
    std::map<int, std::vector<cycles::FormulaStep>> descriptors;
    std::optional<std::vector<cycles::FormulaStep>> result;
    bool anyDepth = false;
    std::optional<SourceLocation> withoutDepth;  // the first DECLARE without DEPTH
};

void KlartextInterpreter::executeSelectContour(const SelectContour& select) {
    m_contourSource = ContourSource::Formula;
    m_contourProgram = select.path;
    m_contourFolder = m_levels.back().program->folder;
    m_contourIsoCaller = m_levels.back().program->syntax != nullptr;
}

void KlartextInterpreter::executeContourDefinition(const ContourDefinition& definition) {
    m_contourSource = ContourSource::Simple;
    m_simpleContours = definition;
    m_contourFolder = m_levels.back().program->folder;
    m_contourIsoCaller = m_levels.back().program->syntax != nullptr;
}

// Outside a definition program being read (the program itself run or checked) these blocks
// have no effect; the check finds undeclared descriptors.
void KlartextInterpreter::executeDeclareContour(const DeclareContour& declare) {
    FormulaBuild* build = m_formulaBuild;
    if (build == nullptr) return;
    if (build->formula.contours.size() >= kMaxFormulaContours) {
        fail("contour", KERF_TR_NOOP("a contour formula combines at most 128 contours"));
        return;
    }
    cycles::FormulaContour contour;
    if (!captureProgramContour(declare.path, build->folder, build->isoCaller, contour)) return;
    contour.depth = std::fabs(declare.depth);
    if (declare.hasDepth) {
        build->anyDepth = true;
    } else if (!build->withoutDepth) {
        build->withoutDepth = m_at;
    }
    build->descriptors[declare.descriptor] = {
        cycles::FormulaStep{Kind::Contour, build->formula.contours.size()}};
    build->formula.contours.push_back(std::move(contour));
}

void KlartextInterpreter::executeContourFormula(const ContourFormula& formula) {
    FormulaBuild* build = m_formulaBuild;
    if (build == nullptr) return;
    std::vector<cycles::FormulaStep> steps;
    for (const ContourFormulaStep& step : formula.steps) {
        if (step.kind != ContourFormulaStep::Kind::Descriptor) {
            steps.push_back(cycles::FormulaStep{stepKind(step.kind), 0});
            continue;
        }
        auto it = build->descriptors.find(step.descriptor);
        if (it == build->descriptors.end()) {
            fail("contour", KERF_TR_NOOP("QC{1} is not declared (DECLARE CONTOUR)"),
                 {std::to_string(step.descriptor)});
            return;
        }
        steps.insert(steps.end(), it->second.begin(), it->second.end());
        if (steps.size() > kMaxFormulaSteps) {
            fail("contour", KERF_TR_NOOP("the contour formula is too long"));
            return;
        }
    }
    build->descriptors[formula.target] = steps;
    build->result = std::move(steps);
}

bool KlartextInterpreter::captureFormula(std::optional<cycles::ContourFormula>& out) {
    out.reset();
    if (m_contourSource == ContourSource::Labels) return true;
    m_subcontourFrame = cycles::CoordinateFrame{};
    cycles::ContourFormula formula;
    if (m_contourSource == ContourSource::Formula) {
        if (!runDefinitionProgram(formula)) return false;
        out = std::move(formula);
        return true;
    }
    // CONTOUR DEF: the pockets united, the islands taken away (spec §8.2).
    std::vector<cycles::FormulaStep> islands;
    for (const ContourDefinition::Item& item : m_simpleContours.items) {
        cycles::FormulaContour contour;
        const bool captured = item.label ? captureLabelContour(*item.label, contour)
                                         : captureProgramContour(item.path, m_contourFolder,
                                                                 m_contourIsoCaller, contour);
        if (!captured) return false;
        contour.depth = std::fabs(item.depth);
        contour.island = item.island;
        const cycles::FormulaStep operand{Kind::Contour, formula.contours.size()};
        formula.contours.push_back(std::move(contour));
        if (item.island) {
            islands.push_back(operand);
            islands.push_back(cycles::FormulaStep{Kind::Difference, 0});
        } else {
            formula.steps.push_back(operand);
            if (formula.steps.size() > 1) formula.steps.push_back({Kind::Union, 0});
        }
    }
    formula.steps.insert(formula.steps.end(), islands.begin(), islands.end());
    out = std::move(formula);
    return true;
}

// A contour program (SEL CONTOUR's definition program or a contour description), loaded and
// checked; nullptr after a failure that names it.
const ProgramFile* KlartextInterpreter::loadContourProgram(const std::string& name,
                                                           const std::filesystem::path& folder,
                                                           bool isoCaller) {
    auto path = calledProgramPath(name, folder, isoCaller);
    if (!path) {
        fail("path", path.error().messageTemplate.c_str(), path.error().args);
        return nullptr;
    }
    std::string error;
    const ProgramFile* program = loadProgram(*path, &error, Origin::Called);
    if (program == nullptr) {
        fail("io", KERF_TR_NOOP("cannot read the contour program {1}: {2}"), {name, error});
        return nullptr;
    }
    if (hasErrors(program->diagnostics)) {
        appendDiagnostics(m_diagnostics, program->diagnostics);
        fail("call", KERF_TR_NOOP("the contour program {1} has errors"), {name});
        return nullptr;
    }
    return program;
}

// Reads the definition program of SEL CONTOUR: Q parameter assignments, DECLARE CONTOUR and
// formulas; the last formula is the contour.
bool KlartextInterpreter::runDefinitionProgram(cycles::ContourFormula& out) {
    const ProgramFile* program =
        loadContourProgram(m_contourProgram, m_contourFolder, m_contourIsoCaller);
    if (program == nullptr) return false;
    FormulaBuild build;
    build.folder = program->folder;
    build.isoCaller = program->syntax != nullptr;
    m_formulaBuild = &build;
    const SourceLocation callAt = m_at;
    std::unique_ptr<BlockSyntax> ownParser;
    BlockSyntax& parser = parserFor(*program, ownParser);
    BlockReader reader(program->source->text(), &parser);
    program::LogicalLine line;
    ParsedBlock parsed;
    while (m_status != interp::RunStatus::Failed && reader.next(line)) {
        m_at = SourceLocation{program->fileId, line.firstLine, 1, -1};
        if (!parser.parse(line, parsed)) {
            const ParseProblem& p = parser.problem();
            m_at.line = line.lineAt(p.offset);
            m_at.column = line.columnAt(p.offset);
            fail(p.code.c_str(), p.messageTemplate.c_str(), p.args);
            break;
        }
        m_at.blockNumber = parsed.blockNumber;
        const Statement& s = parsed.statement;
        if (std::holds_alternative<EndPgm>(s)) break;
        if (std::holds_alternative<BeginPgm>(s) || std::holds_alternative<Empty>(s)) continue;
        if (!std::holds_alternative<QAssign>(s) && !std::holds_alternative<QStringAssign>(s) &&
            !std::holds_alternative<DeclareContour>(s) &&
            !std::holds_alternative<ContourFormula>(s)) {
            fail("contour",
                 KERF_TR_NOOP("this block is not allowed in a contour-definition program"));
            break;
        }
        execute(s);
    }
    m_formulaBuild = nullptr;
    if (m_status == interp::RunStatus::Failed) {
        m_at = callAt;
        return false;
    }
    // Spec §8.1: when one contour has its own depth, every contour needs one.
    if (build.anyDepth && build.withoutDepth) {
        m_at = *build.withoutDepth;
        fail("contour", KERF_TR_NOOP("every contour needs a DEPTH when one has it (DEPTH0: the "
                                     "depth of cycle 20)"));
        m_at = callAt;
        return false;
    }
    m_at = callAt;
    if (!build.result) {
        fail("contour", KERF_TR_NOOP("the contour program {1} has no formula QC.. = ..."),
             {m_contourProgram});
        return false;
    }
    out = std::move(build.formula);
    out.steps = std::move(*build.result);
    return true;
}

// A label of the running program as a closed contour (CONTOUR DEF P1 = LBL 1): read like a
// contour-description program, pocket or island by P or I rather than by RL/RR.
bool KlartextInterpreter::captureLabelContour(const LabelTarget& label,
                                              cycles::FormulaContour& out) {
    const LabelPosition* position = resolveLabel(label);
    if (position == nullptr) return false;
    const std::string name =
        "LBL " + (label.number ? std::to_string(*label.number) : "\"" + *label.name + "\"");
    ChainRules rules;
    rules.formula = true;
    CapturedChain chain;
    if (!captureChain(*m_levels.back().program, *position, rules, chain)) return false;
    if (!checkContourReach(chain.segments, name,
                           KERF_TR_NOOP("the contour subprogram {1} has no contour"))) {
        return false;
    }
    ClosedContour contour;
    if (!closeContour(std::move(chain.segments), name, contour)) return false;
    out.contour = std::move(contour);
    return true;
}

// A contour-description program as a closed contour (a contour that ends elsewhere is closed
// with a straight line, as cycle 14's are).
bool KlartextInterpreter::captureProgramContour(const std::string& name,
                                                const std::filesystem::path& folder, bool isoCaller,
                                                cycles::FormulaContour& out) {
    const ProgramFile* program = loadContourProgram(name, folder, isoCaller);
    if (program == nullptr) return false;
    ChainRules rules;
    rules.formula = true;
    CapturedChain chain;
    if (!captureChain(*program, LabelPosition{0, 1}, rules, chain)) return false;
    if (!checkContourReach(chain.segments, name,
                           KERF_TR_NOOP("the contour program {1} has no contour"))) {
        return false;
    }
    ClosedContour contour;
    if (!closeContour(std::move(chain.segments), name, contour)) return false;
    out.contour = std::move(contour);
    return true;
}

}  // namespace kerf::klartext
