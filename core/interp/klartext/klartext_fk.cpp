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

void KlartextInterpreter::finishFk() {
    if (!m_fk.active) return;
    const SourceLocation here = m_at;
    applyFkStep(m_fk.solver.finish());
    if (m_status != interp::RunStatus::Failed) m_at = here;
    m_fk.active = false;
    m_fk.blocks.clear();
}

void KlartextInterpreter::executeFkPole(const FkPole& pole) {
    m_fk.pole = Vec2(pole.x, pole.y) * lengthScale();
}

void KlartextInterpreter::executeFk(const FkBlock& block) {
    if (workingPlane() != Plane::XY) {
        fail("fk", KERF_TR_NOOP("FK programming works in the XY plane only (tool axis Z)"));
        return;
    }
    std::optional<Vec2> sequenceStart;
    if (!m_fk.active) {
        sequenceStart = Vec2(m_programmed[Axis::X], m_programmed[Axis::Y]);
        const std::optional<Vec2> tangent =
            m_lastTangentPlane == Plane::XY ? m_lastTangent : std::nullopt;
        m_fk.solver.begin(*sequenceStart, tangent);
        m_fk.active = true;
        m_fk.blocks.clear();
    }
    const size_t tag = m_fk.nextTag++;
    m_fk.blocks[tag] = FkBlockState{m_at, block.words, {}};
    const fk::FkElement element = scaled(block.element, lengthScale());
    if (m_fkTrace != nullptr)
        m_fkTrace->elements.push_back({m_at, std::nullopt, givenEnd(element), sequenceStart});
    applyFkStep(m_fk.solver.add(element, tag, m_fk.pole));
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
    Pose target = m_programmed;
    target[Axis::X] = s.end.x();
    target[Axis::Y] = s.end.y();
    submitMove(arc ? ContourElement::arc(Plane::XY, m_programmed, target, s.center, s.sweep)
                   : ContourElement::line(Plane::XY, m_programmed, target),
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
