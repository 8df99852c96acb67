// Path functions: L, C, CR, CT, LP, CP, CTP, CC, RND, CHF, APPR and DEP.
#include <algorithm>
#include <bit>
#include <cmath>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

namespace {

// Difference allowed between the start and end radius of a C block.
constexpr double kCircleTolerance = 0.01;

interp::CompSide sideOf(CompWord comp) {
    switch (comp) {
        case CompWord::Left:
            return interp::CompSide::Left;
        case CompWord::Right:
            return interp::CompSide::Right;
        default:
            return interp::CompSide::None;
    }
}

interp::CompSide flipped(interp::CompSide side) {
    if (side == interp::CompSide::Left) return interp::CompSide::Right;
    if (side == interp::CompSide::Right) return interp::CompSide::Left;
    return side;
}

Vec2 inPlane(Plane plane, const Pose& pose) {
    PlaneAxes axes = planeAxes(plane);
    return {pose[axes.first], pose[axes.second]};
}

void setInPlane(Plane plane, Pose& pose, const Vec2& p) {
    PlaneAxes axes = planeAxes(plane);
    pose[axes.first] = p.x();
    pose[axes.second] = p.y();
}

}  // namespace

Plane KlartextInterpreter::workingPlane() const {
    return planeForToolAxis(m_toolAxis);
}

void KlartextInterpreter::applyPolar(const PolarWords& polar, Pose& target) const {
    // Missing PR/PA keep the current polar coordinates about the pole; I prefixes add to them.
    const Vec2 from = inPlane(m_pole.plane, m_programmed) - m_pole.point;
    const double currentRadius = from.norm();
    const double currentAngle = std::atan2(from.y(), from.x());
    double r = polar.radius ? *polar.radius * lengthScale() : currentRadius;
    if (polar.radius && polar.radiusIncremental) r += currentRadius;
    double a = polar.angle ? degToRad(*polar.angle) : currentAngle;
    if (polar.angle && polar.angleIncremental) a += currentAngle;
    setInPlane(m_pole.plane, target, m_pole.point + r * Vec2(std::cos(a), std::sin(a)));
}

bool KlartextInterpreter::polarWithoutPlaneAxes(const Coordinates& coords) {
    // PR/PA give both working-plane coordinates: a plane axis beside them would be dropped.
    const PlaneAxes axes = planeAxes(m_pole.plane);
    for (Axis axis : {axes.first, axes.second}) {
        if (coords.has(axis)) {
            fail("syntax",
                 KERF_TR_NOOP("{1} is not allowed beside the polar coordinates PR/PA (only the "
                              "tool axis may be programmed)"),
                 {std::string(1, axisLetter(axis))});
            return false;
        }
    }
    return true;
}

Pose KlartextInterpreter::targetOf(const Coordinates& coords) const {
    const double scale = lengthScale();
    const bool machine = m_currentM.count != 0 && (hasM(m_currentM, 91) || hasM(m_currentM, 92));
    // Only the axes the block names (usually two or three of nine).
    if (!machine) {
        Pose target = m_programmed;
        for (auto bits = static_cast<unsigned>(coords.present); bits != 0; bits &= bits - 1) {
            const int i = std::countr_zero(bits);
            const AxisWord& word = coords.axes[static_cast<size_t>(i)];
            const auto axis = static_cast<Axis>(i);
            double& out = target.values[static_cast<size_t>(i)];
            if (axis == Axis::A || axis == Axis::B || axis == Axis::C) {
                out = rotaryTarget(axis, out, word.value, word.incremental);
            } else {
                const double value = word.value * scale;
                out = word.incremental ? out + value : value;
            }
        }
        return target;
    }
    // Machine coordinates bypass the coordinate transformations: set them in the preset frame,
    // of the spindle reference (the tool length is not compensated).
    Pose work = m_frame.toWorkpiece(m_programmed);
    for (auto bits = static_cast<unsigned>(coords.present); bits != 0; bits &= bits - 1) {
        const int i = std::countr_zero(bits);
        const AxisWord& word = coords.axes[static_cast<size_t>(i)];
        const auto axis = static_cast<Axis>(i);
        const bool rotary = axis == Axis::A || axis == Axis::B || axis == Axis::C;
        double& out = work.values[static_cast<size_t>(i)];
        out = (rotary ? word.value : word.value * scale) -
              m_settings.presetInMachine.values[static_cast<size_t>(i)];
        if (axis == m_toolAxis) out -= m_tool.effectiveLength();
    }
    return m_frame.toProgram(work);
}

void KlartextInterpreter::submitMove(const ContourElement& element, bool rapid, double feed,
                                     const CommonWords& words) {
    (void)words;
    interp::PathMove move;
    const bool direct = !pathInTiltedPlane() && m_frame.identity();
    if (direct) {
        move.geometry = element;  // what toPathSpace() would return, without its copy
    } else {
        auto transformed = toPathSpace(element);
        if (!transformed) return;
        move.geometry = *transformed;
    }
    move.rapid = rapid;
    move.feed = feed;
    move.side = sideOf(m_comp);
    // A mirror image puts the tool on the other side of the mirrored contour.
    if (!direct && pathFlipsOrientation(element.plane)) move.side = flipped(move.side);
    move.location = m_at;
    if (!checkPathError(activePath().addMove(move))) return;
    m_programmed = element.end;
    if (element.movesInPlane()) {
        const Vec2 tangent = element.endTangent();
        m_lastTangent = tangent;
        m_lastTangentPlane = element.plane;
        // FK relative data (RX 12 ...) may refer to this block.
        if (element.plane == workingPlane()) {
            const bool arc = element.kind == ContourElement::Kind::Arc;
            m_fk.solver.remember(m_at.blockNumber, element.end2(), tangent,
                                 arc ? std::optional(element.center) : std::nullopt);
        }
    }
}

void KlartextInterpreter::executeLinear(const LinearBlock& block) {
    bool rapid = false;
    double feed = 0.0;
    // Only the functions up to the count are read (hasM): the rest is not copied.
    m_currentM.count = block.words.m.count;
    std::copy_n(block.words.m.list.begin(), block.words.m.count, m_currentM.list.begin());
    if (!resolveFeed(block.words.feed, rapid, feed)) return;
    if (block.words.comp != CompWord::None) m_comp = block.words.comp;
    applyMFunctions(block.words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    auto moved = moveTarget(block.coords);
    if (!moved) return;
    Pose target = *moved;
    if (!rotaryWithinLimits(target)) return;
    submitMove(ContourElement::line(workingPlane(), m_programmed, target), rapid, feed,
               block.words);
    applyMFunctions(block.words.m, false);
    afterPositioning(block.words.m);
}

void KlartextInterpreter::executeCircleCenter(const CircleCenter& block) {
    Plane plane = workingPlane();
    Axis first = Axis::X, second = Axis::Y;
    int count = 0;
    for (int i = 0; i < kAxisCount; ++i) {
        if (!block.coords.axes[static_cast<size_t>(i)].present) continue;
        if (count == 0) first = static_cast<Axis>(i);
        if (count == 1) second = static_cast<Axis>(i);
        ++count;
    }
    if (count == 2) {
        auto p = planeFromAxes(first, second);
        if (!p) {
            fail("geometry", KERF_TR_NOOP("CC axes {1} and {2} do not span a plane"),
                 {std::string(1, axisLetter(first)), std::string(1, axisLetter(second))});
            return;
        }
        plane = *p;
    } else if (count > 2) {
        fail("geometry", KERF_TR_NOOP("CC takes two coordinates of a plane"));
        return;
    }
    // Missing coordinates come from the last programmed position.
    Pose point = targetOf(block.coords);
    m_pole.point = inPlane(plane, point);
    m_pole.plane = plane;
    m_pole.set = true;
}

void KlartextInterpreter::executeCircle(const Coordinates& coords, Direction direction,
                                        const CommonWords& words, std::optional<double> radius) {
    bool rapid = false;
    double feed = 0.0;
    m_currentM = words.m;
    if (!resolveFeed(words.feed, rapid, feed)) return;
    if (rapid) {
        fail("feed", KERF_TR_NOOP("circular moves cannot use FMAX"));
        return;
    }
    if (words.comp != CompWord::None) m_comp = words.comp;
    if (direction == Direction::None) direction = m_direction;
    if (direction == Direction::None) {
        fail("geometry", KERF_TR_NOOP("direction of rotation DR+ or DR- missing"));
        return;
    }
    m_direction = direction;
    const bool ccw = direction == Direction::Ccw;
    applyMFunctions(words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    auto moved = moveTarget(coords);
    if (!moved) return;
    Pose target = *moved;
    Plane plane;
    Vec2 center;
    if (radius) {
        plane = workingPlane();
        auto c = arcCenterFromRadius(inPlane(plane, m_programmed), inPlane(plane, target),
                                     *radius * lengthScale(), ccw);
        if (!c) {
            fail("geometry",
                 KERF_TR_NOOP("no circle of radius {1} passes through the start and end point"),
                 {formatFixed(*radius, 4)});
            return;
        }
        center = *c;
    } else {
        if (!m_pole.set) {
            fail("geometry", KERF_TR_NOOP("circle centre CC is not defined"));
            return;
        }
        plane = m_pole.plane;
        center = m_pole.point;
        double r0 = (inPlane(plane, m_programmed) - center).norm();
        double r1 = (inPlane(plane, target) - center).norm();
        if (std::fabs(r0 - r1) > kCircleTolerance) {
            fail("geometry",
                 KERF_TR_NOOP("the end point is not on the circle: radius {1} at the start, {2} at "
                              "the end"),
                 {formatFixed(r0, 4), formatFixed(r1, 4)});
            return;
        }
    }
    double sweep = arcSweep(inPlane(plane, m_programmed), inPlane(plane, target), center, ccw);
    submitMove(ContourElement::arc(plane, m_programmed, target, center, sweep), false, feed, words);
    applyMFunctions(words.m, false);
}

void KlartextInterpreter::executeTangentCircle(const Coordinates& coords, const PolarWords* polar,
                                               const CommonWords& words) {
    bool rapid = false;
    double feed = 0.0;
    m_currentM = words.m;
    if (!resolveFeed(words.feed, rapid, feed)) return;
    if (words.comp != CompWord::None) m_comp = words.comp;
    const Plane plane = polar ? m_pole.plane : workingPlane();
    if (!m_lastTangent || m_lastTangentPlane != plane) {
        fail("geometry", KERF_TR_NOOP("a tangential arc needs a contour element before it"));
        return;
    }
    applyMFunctions(words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    auto moved = moveTarget(coords);
    if (!moved) return;
    Pose target = *moved;
    if (polar) {
        if (!m_pole.set) {
            fail("geometry", KERF_TR_NOOP("pole CC is not defined"));
            return;
        }
        applyPolar(*polar, target);
    }
    auto arc = tangentArc(inPlane(plane, m_programmed), *m_lastTangent, inPlane(plane, target));
    if (!arc) {
        fail("geometry", KERF_TR_NOOP("the end point lies on the tangent: no arc possible"));
        return;
    }
    submitMove(ContourElement::arc(plane, m_programmed, target, arc->center, arc->sweep), false,
               feed, words);
    applyMFunctions(words.m, false);
}

void KlartextInterpreter::executeLinePolar(const LinePolarBlock& block) {
    bool rapid = false;
    double feed = 0.0;
    m_currentM = block.words.m;
    if (!resolveFeed(block.words.feed, rapid, feed)) return;
    if (block.words.comp != CompWord::None) m_comp = block.words.comp;
    if (!m_pole.set) {
        fail("geometry", KERF_TR_NOOP("pole CC is not defined"));
        return;
    }
    if (!polarWithoutPlaneAxes(block.coords)) return;
    applyMFunctions(block.words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    const Plane plane = m_pole.plane;
    auto moved = moveTarget(block.coords);
    if (!moved) return;
    Pose target = *moved;
    applyPolar(block.polar, target);
    submitMove(ContourElement::line(plane, m_programmed, target), rapid, feed, block.words);
    applyMFunctions(block.words.m, false);
    afterPositioning(block.words.m);
}

void KlartextInterpreter::executeCirclePolar(const CirclePolarBlock& block) {
    bool rapid = false;
    double feed = 0.0;
    m_currentM = block.words.m;
    if (!resolveFeed(block.words.feed, rapid, feed)) return;
    if (rapid) {
        fail("feed", KERF_TR_NOOP("circular moves cannot use FMAX"));
        return;
    }
    if (block.words.comp != CompWord::None) m_comp = block.words.comp;
    if (!m_pole.set) {
        fail("geometry", KERF_TR_NOOP("pole CC is not defined"));
        return;
    }
    if (!block.polar.angle) {
        fail("geometry", KERF_TR_NOOP("CP needs a polar angle PA or IPA"));
        return;
    }
    if (!polarWithoutPlaneAxes(block.coords)) return;
    Direction direction = block.direction;
    if (block.polar.angleIncremental && direction == Direction::None) {
        direction = *block.polar.angle >= 0.0 ? Direction::Ccw : Direction::Cw;
    }
    if (direction == Direction::None) direction = m_direction;
    if (direction == Direction::None) {
        fail("geometry", KERF_TR_NOOP("direction of rotation DR+ or DR- missing"));
        return;
    }
    m_direction = direction;
    const bool ccw = direction == Direction::Ccw;
    if (block.polar.angleIncremental && *block.polar.angle != 0.0 &&
        (*block.polar.angle > 0.0) != ccw) {
        fail("geometry", KERF_TR_NOOP("the sign of IPA does not match DR"));
        return;
    }
    applyMFunctions(block.words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    const Plane plane = m_pole.plane;
    auto moved = moveTarget(block.coords);
    if (!moved) return;
    Pose target = *moved;
    Vec2 from = inPlane(plane, m_programmed) - m_pole.point;
    const double r = from.norm();
    const double current = std::atan2(from.y(), from.x());
    double sweep;
    Vec2 end;
    if (block.polar.angleIncremental) {
        sweep = degToRad(*block.polar.angle);
        end = m_pole.point + r * Vec2(std::cos(current + sweep), std::sin(current + sweep));
    } else {
        double a = degToRad(*block.polar.angle);
        end = m_pole.point + r * Vec2(std::cos(a), std::sin(a));
        sweep = arcSweep(inPlane(plane, m_programmed), end, m_pole.point, ccw);
    }
    setInPlane(plane, target, end);
    submitMove(ContourElement::arc(plane, m_programmed, target, m_pole.point, sweep), false, feed,
               block.words);
    applyMFunctions(block.words.m, false);
}

void KlartextInterpreter::executeCorner(bool chamfer, double size, const FeedWord& feedWord) {
    std::optional<double> feed;
    if (feedWord.kind != FeedWord::Kind::None) {
        bool rapid = false;
        double value = 0.0;
        double modal = m_feed;
        bool modalSet = m_feedSet;
        if (!resolveFeed(feedWord, rapid, value)) return;
        // The feed of RND/CHF applies to the rounding only.
        m_feed = modal;
        m_feedSet = modalSet;
        feed = value;
    }
    size *= lengthScale() * m_frame.planeScale(workingPlane());
    auto error = chamfer ? activePath().addChamfer(size, feed, m_at)
                         : activePath().addRounding(size, feed, m_at);
    checkPathError(error);
}

void KlartextInterpreter::executeApproach(const ApproachBlock& block) {
    bool rapid = false;
    double feed = 0.0;
    m_currentM = block.words.m;
    if (!resolveFeed(block.words.feed, rapid, feed)) return;
    interp::ApproachSpec spec;
    switch (block.kind) {
        case ApproachKind::LT:
            spec.kind = interp::ApproachKind::Tangent;
            break;
        case ApproachKind::LN:
            spec.kind = interp::ApproachKind::Normal;
            break;
        case ApproachKind::CT:
            spec.kind = interp::ApproachKind::Circle;
            break;
        case ApproachKind::LCT:
            spec.kind = interp::ApproachKind::LineCircle;
            break;
    }
    const char* name = block.depart ? "DEP" : "APPR";
    const bool needsLength = block.kind == ApproachKind::LT || block.kind == ApproachKind::LN;
    if (needsLength && (!block.length || *block.length <= 0.0)) {
        fail("geometry", KERF_TR_NOOP("{1} needs a positive length LEN"), {name});
        return;
    }
    if (block.kind == ApproachKind::CT && (!block.angle || !block.radius || *block.radius == 0.0 ||
                                           *block.angle <= 0.0 || *block.angle > 360.0)) {
        fail("geometry", KERF_TR_NOOP("{1} CT needs an angle CCA (0 to 360) and a radius R"),
             {name});
        return;
    }
    if (block.kind == ApproachKind::LCT && (!block.radius || *block.radius == 0.0)) {
        fail("geometry", KERF_TR_NOOP("{1} LCT needs a radius R"), {name});
        return;
    }
    const double frameScale = m_frame.planeScale(workingPlane());
    spec.length = block.length.value_or(0.0) * lengthScale() * frameScale;
    spec.angleDeg = block.angle.value_or(0.0);
    spec.radius = block.radius.value_or(0.0) * lengthScale() * frameScale;
    spec.feed = feed;
    spec.rapidToHelper = rapid;
    spec.location = m_at;
    auto moved = moveTarget(block.coords);
    if (!moved) return;
    Pose target = *moved;
    if (block.polar) {
        if (!m_pole.set) {
            fail("geometry", KERF_TR_NOOP("pole CC is not defined"));
            return;
        }
        applyPolar(block.polarWords, target);
    }
    applyMFunctions(block.words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    if (!block.depart) {
        if (block.words.comp != CompWord::Left && block.words.comp != CompWord::Right) {
            fail("geometry", KERF_TR_NOOP("APPR needs radius compensation RL or RR"));
            return;
        }
        m_comp = block.words.comp;
        spec.side = sideOf(m_comp);
        if (pathFlipsOrientation(workingPlane())) spec.side = flipped(spec.side);
        spec.contourPoint = pathOfProgram(target);
        spec.moveToolAxis = block.coords.has(m_toolAxis);
        if (!checkPathError(activePath().addApproach(spec))) return;
        m_programmed = target;
    } else {
        if (block.kind == ApproachKind::LCT && !block.polar &&
            (block.coords.present & ~axisBit(m_toolAxis)) == 0) {
            fail("geometry", KERF_TR_NOOP("DEP LCT needs the end point"));
            return;
        }
        spec.endPoint = pathOfProgram(target);
        if (!checkPathError(activePath().addDeparture(spec))) return;
        m_comp = CompWord::Off;
        m_programmed = programOfPath(activePath().toolPosition());
        m_lastTangent.reset();
    }
    applyMFunctions(block.words.m, false);
}

}  // namespace kerf::klartext
