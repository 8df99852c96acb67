#include <cmath>

#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/klartext/statement_axes.h"

namespace kerf::klartext {

namespace {

bool compare(Comparison comparison, double a, double b) {
    // Decimal program values rarely add up exactly in binary: equality allows rounding noise.
    const bool equal = std::fabs(a - b) <= 1e-9 * std::max({1.0, std::fabs(a), std::fabs(b)});
    switch (comparison) {
        case Comparison::Equal:
            return equal;
        case Comparison::NotEqual:
            return !equal;
        case Comparison::Greater:
            return a > b && !equal;
        case Comparison::Less:
            return a < b && !equal;
    }
    return false;
}

}  // namespace

void KlartextInterpreter::execute(const Statement& statement) {
    struct Visitor {
        KlartextInterpreter& self;

        void operator()(const Empty&) {}
        void operator()(const BeginPgm&) {}
        void operator()(const EndPgm&) { self.endOfProgram(true); }
        void operator()(const BlkForm& b) { self.executeBlkForm(b); }
        void operator()(const ToolCall& b) { self.executeToolCall(b); }
        void operator()(const ToolDef& b) { self.executeToolDef(b); }
        void operator()(const LinearBlock& b) { self.executeLinear(b); }
        void operator()(const LineNormalBlock& b) { self.executeLineNormal(b); }
        void operator()(const CircleCenter& b) { self.executeCircleCenter(b); }
        void operator()(const CircleBlock& b) {
            self.executeCircle(b.coords, b.direction, b.words, std::nullopt);
        }
        void operator()(const CircleRadiusBlock& b) {
            self.executeCircle(b.coords, b.direction, b.words, b.radius);
        }
        void operator()(const CircleTangentBlock& b) {
            self.executeTangentCircle(b.coords, nullptr, b.words);
        }
        void operator()(const RoundBlock& b) { self.executeCorner(false, b.radius, b.feed); }
        void operator()(const ChamferBlock& b) { self.executeCorner(true, b.length, b.feed); }
        void operator()(const LinePolarBlock& b) { self.executeLinePolar(b); }
        void operator()(const CirclePolarBlock& b) { self.executeCirclePolar(b); }
        void operator()(const CircleTangentPolarBlock& b) {
            self.executeTangentCircle(b.coords, &b.polar, b.words);
        }
        void operator()(const ApproachBlock& b) { self.executeApproach(b); }
        void operator()(const Label& b) {
            if (b.target.number && *b.target.number == 0) self.returnFromLabel();
        }
        void operator()(const CallLabel& b) { self.callLabel(b); }
        void operator()(const CallPgm& b) { self.callProgram(b); }
        void operator()(const StopBlock& b) {
            if (!self.hasM(b.m, 0) && !self.hasM(b.m, 1)) {
                self.emit(canon::ProgramStop{canon::StopKind::Program, -1});
            }
            CommonWords words;
            words.m = b.m;
            self.executeMOnly(words);
        }
        void operator()(const MFunctionBlock& b) { self.executeMOnly(b.words); }
        void operator()(const QAssign& b) { self.m_q.set(b.target, b.value); }
        void operator()(const QStringAssign& b) { self.m_q.setString(b.index, b.value); }
        void operator()(const ConditionalJump& b) {
            if (compare(b.comparison, b.left, b.right)) self.gotoLabel(b.target);
        }
        void operator()(const ErrorBlock& b) { self.executeError(b); }
        void operator()(const PrintBlock& b) { self.executePrint(b); }
        void operator()(const SysRead& b) { self.executeSysRead(b); }
        void operator()(const WaitForSync&) { self.waitForSync(); }
        void operator()(const CircleData& b) { self.executeCircleData(b); }
        void operator()(const TableOpen& b) { self.executeTableOpen(b); }
        void operator()(const TableAccess& b) { self.executeTableAccess(b); }
        void operator()(const CycleDefinition& b) { self.executeCycleDefinition(b); }
        void operator()(const GlobalDefinition& b) { self.executeGlobalDef(b); }
        void operator()(const PatternDefinition& b) { self.executePatternDef(b); }
        void operator()(const SelectTable& b) { self.executeSelectTable(b); }
        void operator()(const SelectPattern& b) { self.executeSelectPattern(b); }
        void operator()(const SelectProgram& b) { self.m_selectedProgram = b.path; }
        void operator()(const CallSelectedProgram&) { self.callSelectedProgram(); }
        void operator()(const SelectContour& b) { self.executeSelectContour(b); }
        void operator()(const DeclareContour& b) { self.executeDeclareContour(b); }
        void operator()(const ContourFormula& b) { self.executeContourFormula(b); }
        void operator()(const ContourDefinition& b) { self.executeContourDefinition(b); }
        void operator()(const CycleCall& b) { self.executeCycleCall(b); }
        void operator()(const FkBlock& b) { self.executeFk(b); }
        void operator()(const FkPole& b) { self.executeFkPole(b); }
        void operator()(const FkSelect& b) { self.executeFkSelect(b); }
        void operator()(const PlaneBlock& b) { self.executePlane(b); }
        void operator()(const TcpmBlock& b) { self.switchTcpm(b); }
        void operator()(const Deferred& b) {
            self.fail("not-supported", KERF_TR_NOOP("{1} is not supported yet"), {b.feature});
        }
    };
    // With AXIS SPAT, A, B and C are the tool's spatial angles (klartext_tcpm.cpp).
    const AxisMask spatial = m_tcpmSpatial ? axisMaskOf("ABC") : 0;
    if (auto missing = axisMissingFrom(statement, m_machineAxes | spatial)) {
        fail("axis", KERF_TR_NOOP("this machine has no axis {1}"),
             {std::string(1, axisLetter(*missing))});
        return;
    }
    if (routeThroughFk(statement) || m_status == interp::RunStatus::Failed) return;
    // Cycle 3 is complete after 3.3; an optional 3.4 ERRORMODE may still follow.
    if (m_oldProbe.pending && !continuesOldProbe(statement)) runOldProbe();
    if (m_status == interp::RunStatus::Failed) return;
    std::visit(Visitor{*this}, statement);
}

}  // namespace kerf::klartext
