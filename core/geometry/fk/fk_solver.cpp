#include "core/geometry/fk/fk_solver.h"

#include <algorithm>
#include <cmath>

#include "core/base/translate.h"
#include "core/geometry/arc_math.h"
#include "core/geometry/fk/fk_candidates.h"

namespace kerf::fk {

namespace {

constexpr size_t kMaxReferences = 64;  // R.. data reach 64 blocks back

double angleDegOf(const Vec2& v) {
    return radToDeg(std::atan2(v.y(), v.x()));
}

PlanarSegment segmentOf(const Carrier& carrier, const Vec2& start, const Vec2& end) {
    if (!carrier.circle) return PlanarSegment::line(start, end);
    PlanarSegment arc = PlanarSegment::arc(start, carrier.centre,
                                           arcSweep(start, end, carrier.centre, carrier.ccw));
    arc.end = end;
    return arc;
}

// Two circles meeting twice: the point reached later along the first one comes first.
void orderAlongCircle(std::vector<Vec2>& points, const Carrier& circle, const Vec2& start) {
    std::stable_sort(points.begin(), points.end(), [&](const Vec2& a, const Vec2& b) {
        return std::fabs(arcSweep(start, a, circle.centre, circle.ccw)) >
               std::fabs(arcSweep(start, b, circle.centre, circle.ccw));
    });
}

bool sameSegment(const PlanarSegment& a, const PlanarSegment& b) {
    const double tol =
        kFkTolerance * std::max({1.0, a.end.cwiseAbs().maxCoeff(), a.center.cwiseAbs().maxCoeff()});
    return a.kind == b.kind && (a.end - b.end).norm() <= tol &&
           (a.kind == PlanarSegment::Kind::Line ||
            ((a.center - b.center).norm() <= tol && std::fabs(a.sweep - b.sweep) <= 1e-9));
}

FkProblem problemAt(size_t tag, const char* messageTemplate, std::vector<std::string> args = {}) {
    return FkProblem{tag, false, messageTemplate, std::move(args)};
}

}  // namespace

void FkSolver::addChoice(std::vector<Choice>& choices, Choice choice) {
    // Different constructions may give the same element (D = 0, a touching pair): one solution.
    for (const Choice& c : choices) {
        if (sameSegment(c.segment, choice.segment) &&
            c.next.has_value() == choice.next.has_value() &&
            (!c.next || c.next->sameAs(*choice.next))) {
            return;
        }
    }
    choices.push_back(std::move(choice));
}

void FkSolver::begin(const Vec2& start, std::optional<Vec2> tangent) {
    m_window.clear();
    m_choices.clear();
    m_alternatives.clear();
    m_start = start;
    m_tangent = tangent;
    m_contourStart.reset();
    m_closing = false;
}

void FkSolver::remember(int64_t blockNumber, const Vec2& end, const Vec2& endTangent,
                        std::optional<Vec2> centre) {
    if (blockNumber < 0) return;
    // An FK element is remembered by the solver and again when the caller emits it.
    if (!m_references.empty() && m_references.back().block == blockNumber) {
        m_references.pop_back();
    }
    m_references.push_back({blockNumber, end, endTangent, centre});
    if (m_references.size() > kMaxReferences) m_references.pop_front();
}

const FkSolver::Reference* FkSolver::reference(int64_t block) const {
    for (auto it = m_references.rbegin(); it != m_references.rend(); ++it)
        if (it->block == block) return &*it;
    return nullptr;
}

bool FkSolver::resolveReferences(FkElement& e, size_t tag, const std::optional<Vec2>& pole,
                                 FkStep& step) const {
    enum class Part : uint8_t { X, Y, Radius, Angle, Direction };
    auto resolve = [&](std::optional<FkValue>& v, Part part) {
        if (!v || !v->reference) return true;
        const Reference* r = reference(*v->reference);
        if (r == nullptr) {
            step.problem = problemAt(tag,
                                     KERF_TR_NOOP("FK: the relative data refer to block {1}, which "
                                                  "is not among the last 64 determined blocks"),
                                     {std::to_string(*v->reference)});
            return false;
        }
        if ((part == Part::Radius || part == Part::Angle) && !pole) {
            step.problem = problemAt(tag, KERF_TR_NOOP("FK: polar data need a pole FPOL"));
            return false;
        }
        double base = 0.0;
        switch (part) {
            case Part::X:
                base = r->end.x();
                break;
            case Part::Y:
                base = r->end.y();
                break;
            case Part::Radius:
                base = (r->end - *pole).norm();
                break;
            case Part::Angle:
                base = angleDegOf(r->end - *pole);
                break;
            case Part::Direction:
                base = angleDegOf(r->tangent);
                break;
        }
        v = FkValue{base + v->value, false, std::nullopt};
        return true;
    };
    return resolve(e.x, Part::X) && resolve(e.y, Part::Y) && resolve(e.pr, Part::Radius) &&
           resolve(e.pa, Part::Angle) && resolve(e.an, Part::Direction) &&
           resolve(e.ccx, Part::X) && resolve(e.ccy, Part::Y) && resolve(e.ccpr, Part::Radius) &&
           resolve(e.ccpa, Part::Angle) && resolve(e.pdx, Part::X) && resolve(e.pdy, Part::Y);
}

FkStep FkSolver::add(const FkElement& element, size_t tag, std::optional<Vec2> pole) {
    FkStep step;
    if (awaitingChoice()) {
        step.problem = problemAt(m_ambiguousTag,
                                 KERF_TR_NOOP("FK: this element has {1} solutions: choose one with "
                                              "FSELECT in the next block"),
                                 {std::to_string(m_choices.size())});
        return step;
    }
    FkElement e = element;
    if (!resolveReferences(e, tag, pole, step)) return step;
    if (!pole && (e.pr || e.pa || e.ccpr || e.ccpa)) {
        step.problem = problemAt(tag, KERF_TR_NOOP("FK: polar data need a pole FPOL"));
        return step;
    }
    if ((e.radius && *e.radius <= 0.0) || (e.length && *e.length <= 0.0) ||
        (e.distance && *e.distance < 0.0)) {
        step.problem = problemAt(tag, KERF_TR_NOOP("FK: R and LEN must be positive, D must not be "
                                                   "negative"));
        return step;
    }
    if (e.closeEnd && !m_closing) {
        step.problem = problemAt(tag, KERF_TR_NOOP("FK: CLSD- without a CLSD+ before it"));
        return step;
    }
    if (e.closeStart) m_closing = true;
    m_window.push_back({e, tag, pole, std::nullopt});
    for (;;) {
        const Outcome outcome = advance(step);
        if (outcome == Outcome::Resolved) continue;
        if (outcome == Outcome::Ambiguous) step.choices = m_choices.size();
        break;
    }
    return step;
}

FkStep FkSolver::select(int choice) {
    FkStep step;
    if (!awaitingChoice()) {
        step.problem = FkProblem{0,
                                 true,
                                 KERF_TR_NOOP("FSELECT without an FK element with several "
                                              "solutions before it"),
                                 {}};
        return step;
    }
    if (choice < 1 || static_cast<size_t>(choice) > m_choices.size()) {
        step.problem = FkProblem{0,
                                 true,
                                 KERF_TR_NOOP("FSELECT {1}: the element has {2} solutions"),
                                 {std::to_string(choice), std::to_string(m_choices.size())}};
        return step;
    }
    const Choice chosen = m_choices[static_cast<size_t>(choice - 1)];
    m_choices.clear();
    m_alternatives.clear();
    commit(chosen, step);
    for (;;) {
        const Outcome outcome = advance(step);
        if (outcome == Outcome::Resolved) continue;
        if (outcome == Outcome::Ambiguous) step.choices = m_choices.size();
        break;
    }
    return step;
}

FkStep FkSolver::finish() {
    FkStep step;
    if (awaitingChoice()) {
        step.problem = problemAt(m_ambiguousTag,
                                 KERF_TR_NOOP("FK: this element has {1} solutions: choose one with "
                                              "FSELECT in the next block"),
                                 {std::to_string(m_choices.size())});
    } else if (!m_window.empty()) {
        step.problem = problemAt(m_window.front().tag,
                                 KERF_TR_NOOP("FK: this element is not determined: the FK "
                                              "sequence ends before enough data are given"));
    }
    begin(m_start, m_tangent);
    return step;
}

FkSolver::Outcome FkSolver::advance(FkStep& step) {
    if (m_window.empty()) return Outcome::Waiting;
    const Pending& first = m_window.front();
    // The standalone carrier of a tangential element: it fixes the element before it.
    auto lookahead = [&](size_t index) -> std::optional<Carrier> {
        if (index >= m_window.size() || !m_window[index].element.isTangent()) return std::nullopt;
        CandidateContext alone;
        alone.pole = m_window[index].pole;
        CarrierCandidates c = carrierCandidates(m_window[index].element, alone);
        if (c.found != Found::Some || c.carriers.size() != 1) return std::nullopt;
        return c.carriers.front();
    };
    auto waiting = [&]() {
        if (m_window.size() <= kMaxWaiting) return Outcome::Waiting;
        step.problem =
            problemAt(first.tag, KERF_TR_NOOP("FK: this element is not determined by the "
                                              "blocks that follow it"));
        return Outcome::Failed;
    };
    CandidateContext context;
    context.start = m_start;
    context.startTangent = m_tangent;
    context.pole = first.pole;
    context.next = lookahead(1);
    context.contourStart = m_contourStart;
    CarrierCandidates carriers;
    if (first.fixed) {
        carriers.found = Found::Some;
        carriers.carriers.push_back(*first.fixed);
    } else {
        carriers = carrierCandidates(first.element, context);
    }
    if (carriers.found == Found::Undetermined) return waiting();
    const size_t blame = m_window.back().tag;
    if (carriers.found == Found::Contradiction) {
        step.problem = problemAt(blame, KERF_TR_NOOP("FK: the data of this block contradict the "
                                                     "contour: no solution"));
        return Outcome::Failed;
    }
    std::vector<Choice> choices;
    bool mustWait = false;
    for (const Carrier& c0 : carriers.carriers) {
        EndCandidates ends = endCandidates(first.element, c0, m_start, context);
        if (ends.found == Found::Some) {
            for (const Vec2& end : ends.ends)
                addChoice(choices, {segmentOf(c0, m_start, end), c0, std::nullopt});
            continue;
        }
        if (ends.found == Found::Contradiction) continue;
        // The end is where the next element starts.
        if (m_window.size() < 2) {
            mustWait = true;
            continue;
        }
        const Pending& second = m_window[1];
        CandidateContext after;
        after.pole = second.pole;
        after.previous = c0;
        after.next = lookahead(2);
        CarrierCandidates nexts = carrierCandidates(second.element, after);
        if (nexts.found == Found::Undetermined) {
            mustWait = true;
            continue;
        }
        for (const Carrier& c1 : nexts.carriers) {
            if (second.element.isTangent() && !c0.circle && !c1.circle) {
                mustWait = true;  // a line continued by a line: nothing marks the joint
                continue;
            }
            std::vector<Vec2> meet;
            if (second.element.isTangent()) {
                if (auto p = touchPoint(c0, c1)) meet.push_back(*p);
            } else {
                meet = intersect(c0, c1);
            }
            if (!c1.circle) {
                orderAlong(meet, c1.dir);
            } else if (!c0.circle) {
                orderAlong(meet, c0.dir);
            } else {
                orderAlongCircle(meet, c0, m_start);
            }
            for (const Vec2& p : meet) {
                if (!runsForward(c0, m_start, p)) continue;
                addChoice(choices, {segmentOf(c0, m_start, p), c0, c1});
            }
        }
    }
    if (mustWait) return waiting();
    if (choices.empty()) {
        step.problem = problemAt(blame, KERF_TR_NOOP("FK: the data of this block contradict the "
                                                     "contour: no solution"));
        return Outcome::Failed;
    }
    if (choices.size() == 1) {
        commit(choices.front(), step);
        return Outcome::Resolved;
    }
    m_choices = std::move(choices);
    m_ambiguousTag = blame;
    m_alternatives.clear();
    for (const Choice& c : m_choices)
        m_alternatives.push_back({first.tag, c.segment});
    return Outcome::Ambiguous;
}

void FkSolver::commit(const Choice& choice, FkStep& step) {
    const Pending first = m_window.front();
    m_window.pop_front();
    step.resolved.push_back({first.tag, choice.segment});
    const Vec2 tangent = choice.segment.endTangent();
    remember(first.element.blockNumber, choice.segment.end, tangent,
             choice.carrier.circle ? std::optional(choice.carrier.centre) : std::nullopt);
    if (first.element.closeStart) m_contourStart = m_start;
    m_start = choice.segment.end;
    m_tangent = tangent;
    if (choice.next && !m_window.empty()) m_window.front().fixed = choice.next;
}

}  // namespace kerf::fk
