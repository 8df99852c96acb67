// FK free contour programming: the blocks feed core/geometry/fk's solver; what it resolves is
// emitted as ordinary lines and arcs, each with the feed, M functions, compensation and source
// location of its own block, so the planner, the graphics and the SL cycles see plain moves.
#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

namespace {

// Lengths of an inch program in millimetres; angles stay.
fk::FkElement scaled(fk::FkElement e, double scale) {
    for (auto* v : {&e.x, &e.y, &e.pr, &e.ccx, &e.ccy, &e.ccpr, &e.pdx, &e.pdy}) {
        if (*v) (*v)->value *= scale;
    }
    for (auto* v : {&e.length, &e.radius, &e.distance}) {
        if (*v) **v *= scale;
    }
    for (auto& p : e.pointsOn) {
        if (p) *p *= scale;
    }
    return e;
}

// The block's data in the working plane: the plane's first and second axis become the element's
// X and Y (ZX plane: Z and X). False with the axis letter of a datum outside the plane.
bool inWorkingPlane(const FkBlock& block, const PlaneAxes& axes, fk::FkElement& out, char& stray) {
    out = block.element;
    const auto first = static_cast<size_t>(axisIndex(axes.first));
    const auto second = static_cast<size_t>(axisIndex(axes.second));
    const auto normal = static_cast<size_t>(axisIndex(axes.normal));
    stray = "XYZ"[normal];
    if (block.end[normal] || block.centre[normal] || block.pointAtDistance[normal]) return false;
    out.x = block.end[first];
    out.y = block.end[second];
    out.ccx = block.centre[first];
    out.ccy = block.centre[second];
    out.pdx = block.pointAtDistance[first];
    out.pdy = block.pointAtDistance[second];
    for (size_t i = 0; i < block.pointsOn.size(); ++i) {
        const auto& p = block.pointsOn[i];
        if (p[normal]) return false;
        if (p[first] && p[second]) out.pointsOn[i] = Vec2(*p[first], *p[second]);
    }
    return true;
}

// An end point given absolutely in both coordinates: the graphics can show it before the
// element is determined.
std::optional<Vec2> givenEnd(const fk::FkElement& e) {
    auto absolute = [](const std::optional<fk::FkValue>& v) {
        return v && !v->incremental && !v->reference;
    };
    if (!absolute(e.x) || !absolute(e.y)) return std::nullopt;
    return Vec2(e.x->value, e.y->value);
}

}  // namespace

bool KlartextInterpreter::routeThroughFk(const Statement& statement) {
    if (!m_fk.active) return false;
    if (std::holds_alternative<FkBlock>(statement) || std::holds_alternative<FkPole>(statement) ||
        std::holds_alternative<FkSelect>(statement) || std::holds_alternative<Empty>(statement) ||
        std::holds_alternative<QAssign>(statement) ||
        std::holds_alternative<QStringAssign>(statement)) {
        return false;
    }
    const bool corner = std::holds_alternative<RoundBlock>(statement) ||
                        std::holds_alternative<ChamferBlock>(statement);
    if (corner && !m_fk.blocks.empty()) {
        // The corner lies after the last FK element given: it is rounded once that is emitted.
        m_fk.blocks.rbegin()->second.after.emplace_back(statement, m_at);
        return true;
    }
    if (corner) return false;
    finishFk();
    return false;
}

void KlartextInterpreter::chooseTentatively() {
    if (m_fkTrace == nullptr || !m_fk.solver.awaitingChoice() || m_fkTrace->ambiguities.empty()) {
        return;
    }
    const SourceLocation here = m_at;
    m_at = m_fkTrace->ambiguities.back().after;
    appendDiagnostic(m_diagnostics,
                     diagnosticAt(Severity::Error, "fk",
                                  KERF_TR_NOOP("FK: this element has {1} solutions: choose one "
                                               "with FSELECT in the next block"),
                                  {std::to_string(m_fk.solver.alternatives().size())}));
    m_at = here;
    m_fk.tentative = true;
    applyFkStep(m_fk.solver.select(1));
}

void KlartextInterpreter::finishFk() {
    if (!m_fk.active) return;
    chooseTentatively();
    const SourceLocation here = m_at;
    applyFkStep(m_fk.solver.finish());
    if (m_status != interp::RunStatus::Failed) m_at = here;
    m_fk.active = false;
    m_fk.tentative = false;
    m_fk.blocks.clear();
}

void KlartextInterpreter::executeFkPole(const FkPole& pole) {
    m_fk.pole = pole;
    for (auto& c : m_fk.pole->coords) {
        if (c) *c *= lengthScale();
    }
}

void KlartextInterpreter::executeFk(const FkBlock& block) {
    // FK works in the active working plane (G17/G18/G19: tool axis Z, Y or X).
    const Plane plane = workingPlane();
    const PlaneAxes axes = planeAxes(plane);
    fk::FkElement inPlane;
    char stray = 'Z';
    if (!inWorkingPlane(block, axes, inPlane, stray)) {
        fail("fk", KERF_TR_NOOP("FK: {1} is not an axis of the working plane"),
             {std::string(1, stray)});
        return;
    }
    std::optional<Vec2> pole;
    if (m_fk.pole) {
        const auto& c = m_fk.pole->coords;
        const auto first = static_cast<size_t>(axisIndex(axes.first));
        const auto second = static_cast<size_t>(axisIndex(axes.second));
        if (!c[first] || !c[second]) {
            fail("fk", KERF_TR_NOOP("FK: {1} is not an axis of the working plane"),
                 {std::string(1, "XYZ"[axisIndex(axes.normal)])});
            return;
        }
        pole = Vec2(*c[first], *c[second]);
    }
    std::optional<Vec2> sequenceStart;
    if (!m_fk.active) {
        sequenceStart = Vec2(m_programmed[axes.first], m_programmed[axes.second]);
        const std::optional<Vec2> tangent =
            m_lastTangentPlane == plane ? m_lastTangent : std::nullopt;
        m_fk.solver.begin(*sequenceStart, tangent);
        m_fk.active = true;
        m_fk.plane = plane;
        m_fk.blocks.clear();
    }
    chooseTentatively();
    if (m_status == interp::RunStatus::Failed) return;
    const size_t tag = m_fk.nextTag++;
    m_fk.blocks[tag] = FkBlockState{m_at, block.words, {}};
    const fk::FkElement element = scaled(inPlane, lengthScale());
    if (m_fkTrace != nullptr) {
        m_fkTrace->plane = m_fk.plane;
        m_fkTrace->elements.push_back({m_at, std::nullopt, givenEnd(element), sequenceStart});
    }
    applyFkStep(m_fk.solver.add(element, tag, pole));
}

void KlartextInterpreter::executeFkSelect(const FkSelect& select) {
    if (!m_fk.active) {
        fail("fk", KERF_TR_NOOP("FSELECT without an FK element with several solutions before it"));
        return;
    }
    // The choice answers the last ambiguity recorded (selecting may open the next one).
    const bool traced =
        m_fkTrace != nullptr && m_fk.solver.awaitingChoice() && !m_fkTrace->ambiguities.empty();
    const size_t answered = traced ? m_fkTrace->ambiguities.size() - 1 : 0;
    const SourceLocation here = m_at;
    applyFkStep(m_fk.solver.select(select.choice));
    if (traced && m_status != interp::RunStatus::Failed) {
        m_fkTrace->ambiguities[answered].selectAt = here;
        m_fkTrace->ambiguities[answered].selected = select.choice;
    }
}

void KlartextInterpreter::applyFkStep(const fk::FkStep& step) {
    for (const fk::FkResolved& resolved : step.resolved) {
        if (m_status == interp::RunStatus::Failed) return;
        emitFkElement(resolved);
    }
    if (step.choices > 1 && m_fkTrace != nullptr) traceAmbiguity();
    if (!step.problem || m_status == interp::RunStatus::Failed) return;
    if (!step.problem->atCaller) {
        auto blamed = m_fk.blocks.find(step.problem->tag);
        if (blamed != m_fk.blocks.end()) m_at = blamed->second.at;
    }
    fail("fk", step.problem->messageTemplate, step.problem->args);
}

void KlartextInterpreter::traceAmbiguity() {
    const std::vector<fk::FkAlternative>& alternatives = m_fk.solver.alternatives();
    auto element = m_fk.blocks.find(alternatives.front().tag);
    FkTrace::Ambiguity ambiguity;
    ambiguity.at = element != m_fk.blocks.end() ? element->second.at : m_at;
    ambiguity.after = m_at;
    for (const fk::FkAlternative& alternative : alternatives)
        ambiguity.alternatives.push_back(alternative.segment);
    m_fkTrace->ambiguities.push_back(std::move(ambiguity));
}

void KlartextInterpreter::emitFkElement(const fk::FkResolved& resolved) {
    auto found = m_fk.blocks.find(resolved.tag);
    if (found == m_fk.blocks.end()) return;
    const FkBlockState block = std::move(found->second);
    m_fk.blocks.erase(found);
    if (m_fkTrace != nullptr) {
        for (auto it = m_fkTrace->elements.rbegin(); it != m_fkTrace->elements.rend(); ++it) {
            if (it->at == block.at) {
                it->segment = resolved.segment;
                it->tentative = m_fk.tentative;
                break;
            }
        }
    }
    const SourceLocation here = m_at;
    m_at = block.at;
    bool rapid = false;
    double feed = 0.0;
    m_currentM = block.words.m;
    if (!resolveFeed(block.words.feed, rapid, feed)) return;
    const PlanarSegment& s = resolved.segment;
    const bool arc = s.kind == PlanarSegment::Kind::Arc;
    if (rapid && arc) {
        fail("feed", KERF_TR_NOOP("circular moves cannot use FMAX"));
        return;
    }
    if (block.words.comp != CompWord::None) m_comp = block.words.comp;
    applyMFunctions(block.words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    const PlaneAxes axes = planeAxes(m_fk.plane);
    Pose target = m_programmed;
    target[axes.first] = s.end.x();
    target[axes.second] = s.end.y();
    submitMove(arc ? ContourElement::arc(m_fk.plane, m_programmed, target, s.center, s.sweep)
                   : ContourElement::line(m_fk.plane, m_programmed, target),
               rapid, feed, block.words);
    applyMFunctions(block.words.m, false);
    // An FK arc computes its own centre: a CC before it is no longer valid (enter it again).
    if (arc) m_pole.set = false;
    for (const auto& [statement, at] : block.after) {
        if (m_status == interp::RunStatus::Failed) return;
        m_at = at;
        if (const auto* round = std::get_if<RoundBlock>(&statement)) {
            executeCorner(false, round->radius, round->feed);
        } else if (const auto* chamfer = std::get_if<ChamferBlock>(&statement)) {
            executeCorner(true, chamfer->length, chamfer->feed);
        }
    }
    m_at = here;
}

}  // namespace kerf::klartext
