// Motion blocks: coordinates (Cartesian, polar, angle and one coordinate), lines, the arc forms,
// threads, G53 and G52, into the path pipeline.
#include <cmath>

#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"
#include "core/interp/fagor/location_codes.h"

namespace kerf::fagor {

namespace {

constexpr double kMaxCentre = 214748.3647;  // mm, the manual's limit for centres and radii

bool rotary(Axis axis) {
    return axis == Axis::A || axis == Axis::B || axis == Axis::C;
}

// The centre letter of an axis: X U A -> I, Y V B -> J, Z W C -> K.
char centreLetter(Axis axis) {
    switch (axis) {
        case Axis::X:
        case Axis::U:
        case Axis::A:
            return 'I';
        case Axis::Y:
        case Axis::V:
        case Axis::B:
            return 'J';
        default:
            return 'K';
    }
}

const WordValue& centreWord(const IsoBlock& iso, char letter) {
    return letter == 'I' ? iso.i1 : letter == 'J' ? iso.j : iso.k;
}

}  // namespace

double FagorInterpreter::length(double programmed) const {
    return m_modal.inch ? programmed * 25.4 : programmed;
}

double FagorInterpreter::xValue(double programmed) const {
    return length(programmed) / (m_modal.diameter ? 2.0 : 1.0);
}

double FagorInterpreter::axisValue(Axis axis, double programmed) const {
    if (rotary(axis)) return programmed;
    return axis == Axis::X ? xValue(programmed) : length(programmed);
}

// ---- frames: program (part zero, before mirror and scale) <-> stream ---------------------------

Pose FagorInterpreter::toStream(const Pose& programmed) const {
    Pose p = programmed;
    for (int i = 0; i < kAxisCount; ++i) {
        const auto axis = static_cast<Axis>(i);
        double v = programmed[axis];
        if (!rotary(axis)) v *= m_modal.scale;
        if ((m_modal.mirror & axisBit(axis)) != 0) v = -v;
        p[axis] = v + m_offset[axis] - m_startOffset[axis];
    }
    return p;
}

Pose FagorInterpreter::programmedPosition() const {
    return fromStream(m_position);
}

Pose FagorInterpreter::fromStream(const Pose& stream) const {
    Pose p = stream;
    for (int i = 0; i < kAxisCount; ++i) {
        const auto axis = static_cast<Axis>(i);
        double v = stream[axis] - m_offset[axis] + m_startOffset[axis];
        if ((m_modal.mirror & axisBit(axis)) != 0) v = -v;
        if (!rotary(axis)) v /= m_modal.scale;
        p[axis] = v;
    }
    return p;
}

bool FagorInterpreter::transformFlipsSense() const {
    const PlaneFrame& plane = m_modal.plane;
    const bool a = (m_modal.mirror & axisBit(plane.abscissa)) != 0;
    const bool b = (m_modal.mirror & axisBit(plane.ordinate)) != 0;
    return a != b;
}

// ---- targets ---------------------------------------------------------------------------------

bool FagorInterpreter::hasMotion(const IsoBlock& iso) const {
    if (iso.axisMask != 0) return true;
    const int form = m_functions.arcForm != 0 ? m_functions.arcForm : m_modal.motion;
    if (form == 2 || form == 3 || form == 8 || form == 9) {
        return iso.q.present || iso.r.present || iso.i1.present || iso.j.present || iso.k.present;
    }
    if (form == 0 || form == 1) return iso.r.present || iso.q.present;
    return false;
}

bool FagorInterpreter::targetOf(const IsoBlock& iso, Pose& target, bool& polar) {
    const Pose current = programmedPosition();
    const PlaneFrame& plane = m_modal.plane;
    target = current;
    polar = false;
    for (uint8_t i = 0; i < iso.axisCount; ++i) {
        const Axis axis = iso.axisOrder[i];
        const double v = axisValue(axis, iso.axes[static_cast<size_t>(axisIndex(axis))].value);
        target[axis] = m_modal.incremental ? current[axis] + v : v;
    }
    const int form = m_functions.arcForm != 0 ? m_functions.arcForm : m_modal.motion;
    // Threads use Q as their start angle; G02/G03 R is the arc radius and Q its end angle.
    const bool thread = form == 33 || form == 34;
    const bool arc = form == 2 || form == 3;
    if (thread || arc || (!iso.r.present && !iso.q.present)) return true;
    const bool a = iso.has(plane.abscissa);
    const bool o = iso.has(plane.ordinate);
    const Vec2 p0 = plane.point(current);
    if (iso.r.present || (iso.q.present && !a && !o)) {
        // Polar coordinates about the polar origin: R and Q absolute (G90) or incremental (G91).
        if (a || o) {
            fail("geometry", KERF_TR_NOOP("polar coordinates (R, Q) and Cartesian coordinates of "
                                          "the plane in one block"));
            return false;
        }
        const Vec2 rel = p0 - m_polarOrigin;
        const double r0 = rel.norm();
        const double q0 = r0 > 1e-12 ? angleDeg(rel) : 0.0;
        const double r = iso.r.present ? length(iso.r.value) : (m_modal.incremental ? 0.0 : r0);
        const double q = iso.q.present ? iso.q.value : (m_modal.incremental ? 0.0 : q0);
        const double radius = m_modal.incremental ? r0 + r : r;
        const double angle = m_modal.incremental ? q0 + q : q;
        if (radius < 0.0) {
            fail("geometry", KERF_TR_NOOP("the polar radius becomes negative"));
            return false;
        }
        plane.setPoint(target, m_polarOrigin + radius * unitAtDeg(angle));
        polar = true;
        return true;
    }
    // An angle and one coordinate of the plane: the other one follows from the direction.
    if (a && o) {
        fail("geometry", KERF_TR_NOOP("an angle Q with both coordinates of the plane"));
        return false;
    }
    const Vec2 d = unitAtDeg(iso.q.value);
    Vec2 p1 = plane.point(target);
    if (a) {
        if (std::fabs(d.x()) < 1e-9) {
            fail("geometry", KERF_TR_NOOP("angle Q {1}: the path cannot reach that abscissa"),
                 {std::to_string(iso.q.value)});
            return false;
        }
        p1.y() = p0.y() + (p1.x() - p0.x()) * d.y() / d.x();
    } else {
        if (std::fabs(d.y()) < 1e-9) {
            fail("geometry", KERF_TR_NOOP("angle Q {1}: the path cannot reach that ordinate"),
                 {std::to_string(iso.q.value)});
            return false;
        }
        p1.x() = p0.x() + (p1.y() - p0.y()) * d.x() / d.y();
    }
    plane.setPoint(target, p1);
    return true;
}

// ---- arcs ------------------------------------------------------------------------------------

bool FagorInterpreter::arcElement(const IsoBlock& iso, int form, const Pose& start,
                                  const Pose& targetIn, bool polar, ContourElement& out) {
    const PlaneFrame& plane = m_modal.plane;
    Pose target = targetIn;
    const Vec2 s = plane.point(start);
    Vec2 e = plane.point(target);
    Vec2 centre;
    double sweep = 0.0;
    // Centre words: relative to the start, always radius; with G06 absolute, X per G151/G152.
    auto centreOf = [&](bool& given) {
        Vec2 c = s;
        given = false;
        for (int k = 0; k < 2; ++k) {
            const Axis axis = k == 0 ? plane.abscissa : plane.ordinate;
            const WordValue& w = centreWord(iso, centreLetter(axis));
            double& coordinate = k == 0 ? c.x() : c.y();
            if (w.present) given = true;
            if (m_functions.absoluteCentre) {
                coordinate = axisValue(axis, w.value);
            } else {
                coordinate += rotary(axis) ? w.value : length(w.value);
            }
        }
        return c;
    };
    if (iso.j.present && plane.abscissa != Axis::Y && plane.ordinate != Axis::Y) {
        fail("geometry", KERF_TR_NOOP("J is the centre of the Y axis: the ZX plane uses I and K"));
        return false;
    }
    if (form == 8) {
        if (!m_lastTangent) {
            fail("geometry",
                 KERF_TR_NOOP("G08 needs a previous path in the plane to be tangent to"));
            return false;
        }
        if ((e - s).norm() < 1e-9) {
            fail("geometry", KERF_TR_NOOP("G08 cannot program a full circle"));
            return false;
        }
        auto arc = tangentArc(s, *m_lastTangent, e);
        if (!arc) {
            fail("geometry",
                 KERF_TR_NOOP("G08: the end point lies on the tangent of the previous path"));
            return false;
        }
        centre = arc->center;
        sweep = arc->sweep;
    } else if (form == 9) {
        Vec2 middle = s;
        const Pose current = start;
        for (int k = 0; k < 2; ++k) {
            const Axis axis = k == 0 ? plane.abscissa : plane.ordinate;
            const WordValue& w = centreWord(iso, centreLetter(axis));
            const double v = axisValue(axis, w.value);
            double& coordinate = k == 0 ? middle.x() : middle.y();
            coordinate = m_modal.incremental ? current[axis] + v : (w.present ? v : current[axis]);
        }
        if ((e - s).norm() < 1e-9) {
            fail("geometry", KERF_TR_NOOP("G09 cannot program a full circle"));
            return false;
        }
        auto circle = circleThrough(s, middle, e);
        if (!circle) {
            fail("geometry", KERF_TR_NOOP("G09: the three points lie on a line"));
            return false;
        }
        centre = circle->center;
        sweep = arcSweep(s, e, centre, cross2(middle - s, e - s) > 0.0);
    } else {
        const bool ccw = form == 3;
        if (iso.q.present) {
            // Polar arc: to angle Q about the centre (I/K, or the polar origin without them).
            bool given = false;
            centre = centreOf(given);
            if (!given) centre = m_polarOrigin;
            const double radius = (s - centre).norm();
            const double angle =
                m_modal.incremental ? angleDeg(s - centre) + iso.q.value : iso.q.value;
            e = centre + radius * unitAtDeg(angle);
            plane.setPoint(target, e);
        } else if (iso.r.present && !polar) {
            const double r = length(iso.r.value);
            if ((e - s).norm() < 1e-9) {
                fail("geometry", KERF_TR_NOOP("a full circle cannot be programmed with R"));
                return false;
            }
            auto c = arcCenterFromRadius(s, e, r, ccw);
            if (!c) {
                fail("geometry", KERF_TR_NOOP("the arc radius R is too small for the end point"));
                return false;
            }
            centre = *c;
        } else {
            bool given = false;
            centre = centreOf(given);
            const double rs = (s - centre).norm();
            const double re = (e - centre).norm();
            if (std::fabs(rs - re) > m_settings.circleToleranceMm) {
                fail("geometry",
                     KERF_TR_NOOP("the start and end radii differ by {1} mm (more than CIRINERR)"),
                     {std::to_string(std::fabs(rs - re))});
                return false;
            }
        }
        sweep = arcSweep(s, e, centre, ccw);
        if ((e - centre).norm() < 1e-9) {
            fail("geometry", KERF_TR_NOOP("the arc has no radius"));
            return false;
        }
    }
    if (centre.cwiseAbs().maxCoeff() > kMaxCentre || (s - centre).norm() > kMaxCentre) {
        fail("geometry", KERF_TR_NOOP("arc centre or radius beyond 214748.3647 mm"));
        return false;
    }
    if (m_settings.polarOriginFollowsArcs && form != 8 && form != 9) m_polarOrigin = centre;
    out = ContourElement::arc(plane.plane, start, target, plane.toGeometry(centre),
                              plane.toGeometrySweep(sweep));
    return true;
}

// ---- submission ----------------------------------------------------------------------------

void FagorInterpreter::ensureStreamFeedMode(canon::FeedMode mode) {
    if (mode == m_streamFeedMode) return;
    m_streamFeedMode = mode;
    emit(canon::SetFeedMode{mode});
}

bool FagorInterpreter::feedFor(MoveKind kind, const ContourElement& element, const IsoBlock& iso,
                               double& feed) {
    (void)iso;
    const double maximum = m_settings.machine->maxFeedMmPerS * 60.0;
    if (kind == MoveKind::Rapid) {
        feed = m_feed > 0.0 ? m_feed : maximum;
        return true;
    }
    if (!m_feedSet || m_feed <= 0.0) {
        // No F, or F0: the maximum feed.
        ensureStreamFeedMode(canon::FeedMode::PerMinute);
        feed = maximum;
        return true;
    }
    switch (m_modal.feed) {
        case FeedKind::PerMinute:
            ensureStreamFeedMode(canon::FeedMode::PerMinute);
            feed = m_feed;
            return true;
        case FeedKind::PerRevolution:
            ensureStreamFeedMode(canon::FeedMode::PerRevolution);
            feed = m_feed;
            return true;
        case FeedKind::InverseTime: {
            // The block takes 1/F minutes: the feed is its length times F (rotary degrees count
            // as millimetres).
            ensureStreamFeedMode(canon::FeedMode::PerMinute);
            double axial = 0.0;
            const PlaneAxes axes = planeAxes(element.plane);
            for (int i = 0; i < kAxisCount; ++i) {
                const auto a = static_cast<Axis>(i);
                if (a == axes.first || a == axes.second) continue;
                const double d = element.end[a] - element.start[a];
                axial += d * d;
            }
            const double len = std::sqrt(element.planarLength() * element.planarLength() + axial);
            feed = len * m_feed;
            return true;
        }
    }
    return true;
}

bool FagorInterpreter::threadData(const IsoBlock& iso, const ContourElement& element,
                                  ThreadData& out) {
    const bool variable = m_modal.motion == 34;
    const bool chained = m_thread.previousWasThread && m_modal.corner == CornerKind::Round;
    if (iso.q.present) {
        if (m_settings.m19Type == 0) {
            fail("thread", KERF_TR_NOOP("Q (spindle angle) needs M19TYPE = 1"));
            return false;
        }
        if (chained) {
            fail("thread", KERF_TR_NOOP("only the first thread of a joined chain may have Q"));
            return false;
        }
        if (std::fabs(iso.q.value) > 359.9999) {
            fail("thread", KERF_TR_NOOP("Q must be within +-359.9999 degrees"));
            return false;
        }
    }
    double lead = iso.l.present ? length(iso.l.value) : m_thread.lead;
    if (!iso.l.present && m_thread.lead <= 0.0) {
        fail("thread", KERF_TR_NOOP("a thread needs its pitch L"));
        return false;
    }
    double change = variable && iso.k.present ? length(iso.k.value) : 0.0;
    if (variable && chained) {
        if (m_thread.previousWasVariable) {
            if (lead != 0.0 || change != 0.0) {
                fail("thread", KERF_TR_NOOP("two variable-pitch threads cannot be joined; end one "
                                            "with G34 L0 K0"));
                return false;
            }
            lead = m_thread.endLead;  // G34 L0 K0: keep the pitch reached
        } else if (std::fabs(lead - m_thread.lead) > 1e-9) {
            fail("thread", KERF_TR_NOOP("G34 joined to G33 must start with the pitch of the G33"));
            return false;
        }
    } else if (!variable && chained && m_thread.previousWasVariable) {
        fail("thread", KERF_TR_NOOP("after G34 a constant pitch is programmed with G34 L0 K0"));
        return false;
    }
    if (lead <= 0.0) {
        fail("thread", KERF_TR_NOOP("the thread pitch must be greater than 0"));
        return false;
    }
    out.lead = lead;
    out.leadChange = change;
    out.startAngle = iso.q.present ? iso.q.value : 0.0;
    // The pitch reached at the end: s = L n + K n^2 / 2 over the n revolutions of the path.
    const double s = element.planarLength();
    double endLead = lead;
    if (change != 0.0) {
        const double disc = lead * lead + 2.0 * change * s;
        if (disc < 0.0) {
            fail("thread", KERF_TR_NOOP("the variable pitch reaches zero before the end point"));
            return false;
        }
        const double n = (-lead + std::sqrt(disc)) / change;
        endLead = lead + change * n;
    }
    if (iso.l.present) m_thread.lead = length(iso.l.value);
    m_thread.endLead = endLead;
    m_thread.previousWasVariable = variable;
    return true;
}

bool FagorInterpreter::submit(const ContourElement& programmed, MoveKind kind, const IsoBlock& iso,
                              const OwnMoveData* own) {
    ContourElement element = programmed;
    element.start = m_position;
    element.end = toStream(programmed.end);
    if (programmed.kind == ContourElement::Kind::Arc) {
        Pose centre = programmed.start;
        programmed.setInPlane(centre, programmed.center);
        const Pose c = toStream(centre);
        element.center = element.inPlane(c);
        element.sweep = transformFlipsSense() ? -programmed.sweep : programmed.sweep;
    }
    Move move;
    move.geometry = element;
    move.kind = kind;
    move.location = m_at;
    move.location.column = 1;
    move.request = m_functions.request;
    const bool flip = transformFlipsSense() != m_modal.plane.reversed;
    move.side =
        flip ? static_cast<interp::CompSide>(-static_cast<int>(m_modal.side)) : m_modal.side;
    move.collisionWindow = m_modal.collisionBlocks;
    if (kind == MoveKind::Thread) {
        if (own != nullptr) {
            move.thread = own->thread;
        } else if (!threadData(iso, element, move.thread)) {
            return false;
        }
    } else if (own != nullptr && kind == MoveKind::Feed && own->feed > 0.0) {
        // A cycle's own feed (F, H) is in the active mode's unit, also when the feed at the
        // call was the maximum (no F or F0, per minute).
        ensureStreamFeedMode(m_modal.feed == FeedKind::PerRevolution
                                 ? canon::FeedMode::PerRevolution
                                 : canon::FeedMode::PerMinute);
        move.feed = own->feed;
    } else if (!feedFor(kind, element, iso, move.feed)) {
        return false;
    }
    if (!pathOk(m_shaper.add(move))) return false;
    if (kind == MoveKind::Feed) {
        for (size_t i = 0; i < m_lastDelta.values.size(); ++i) {
            m_lastDelta.values[i] = element.end.values[i] - element.start.values[i];
        }
    }
    m_position = element.end;
    return true;
}

bool FagorInterpreter::executeMotion(const IsoBlock& iso) {
    if (m_functions.probe != 0) return probeMove(iso);
    if (m_functions.machineCoordinates) return machineCoordinateMove(iso);
    if (m_functions.hardStop) return hardStopMove(iso);
    const int form = m_functions.arcForm != 0 ? m_functions.arcForm : m_modal.motion;
    const Pose start = programmedPosition();
    Pose target;
    bool polar = false;
    if (!targetOf(iso, target, polar)) return false;
    const PlaneFrame& plane = m_modal.plane;
    ContourElement element;
    MoveKind kind = MoveKind::Feed;
    if (form == 2 || form == 3 || form == 8 || form == 9) {
        if (!arcElement(iso, form, start, target, polar, element)) return false;
    } else {
        element = ContourElement::line(plane.plane, start, target);
        kind = form == 0 ? MoveKind::Rapid : form == 1 ? MoveKind::Feed : MoveKind::Thread;
    }
    if (!submit(element, kind, iso)) return false;
    m_thread.previousWasThread = kind == MoveKind::Thread;
    if (kind != MoveKind::Thread) m_thread.previousWasVariable = false;
    if (element.movesInPlane()) {
        // The end tangent in the program's frame, for G08.
        const Vec2 t = element.endTangent();
        m_lastTangent = plane.fromGeometry(t);
    }
    return true;
}

bool FagorInterpreter::machineCoordinateMove(const IsoBlock& iso) {
    // G53: the block's coordinates are the holder's machine coordinates (mm unless INCHES);
    // radius and length compensation are off for this block.
    if (!preparationStopFree()) return false;
    const int form = m_modal.motion;
    if (form != 0 && form != 1) {
        fail("geometry", KERF_TR_NOOP("G53 works with G00 and G01 moves only"));
        return false;
    }
    const Pose target = machineTarget(iso, m_position);
    Move move;
    move.geometry = ContourElement::line(m_modal.plane.plane, m_position, target);
    move.kind = form == 0 ? MoveKind::Rapid : MoveKind::Feed;
    move.location = m_at;
    move.location.column = 1;
    if (!feedFor(move.kind, move.geometry, iso, move.feed)) return false;
    if (!pathOk(m_shaper.add(move))) return false;
    m_position = target;
    m_lastTangent.reset();
    return pathOk(m_compensation.suspend());
}

Pose FagorInterpreter::machineTarget(const IsoBlock& iso, const Pose& from) const {
    Pose target = from;
    for (uint8_t i = 0; i < iso.axisCount; ++i) {
        const Axis axis = iso.axisOrder[i];
        double v = iso.axes[static_cast<size_t>(axisIndex(axis))].value;
        if (!rotary(axis)) v *= m_settings.inches ? 25.4 : 1.0;
        if (axis == Axis::X && m_modal.diameter) v /= 2.0;
        double tip = 0.0;
        if (axis == Axis::X) tip = m_tool.data.x + m_tool.data.wearX;
        if (axis == Axis::Z) tip = m_tool.data.z + m_tool.data.wearZ;
        target[axis] = v + tip - m_startOffset[axis];
    }
    return target;
}

bool FagorInterpreter::hardStopMove(const IsoBlock& iso) {
    // G52: towards the coordinate until the stop; where it stops is the machine's answer.
    if (iso.axisCount != 1) {
        fail("geometry", KERF_TR_NOOP("G52 moves one axis"));
        return false;
    }
    if (!preparationStopFree()) return false;
    Pose target;
    bool polar = false;
    if (!targetOf(iso, target, polar)) return false;
    const ContourElement element =
        ContourElement::line(m_modal.plane.plane, programmedPosition(), target);
    if (!submit(element, MoveKind::Feed, iso)) return false;
    emit(canon::SyncPoint{canon::SyncReason::ReadPosition});
    if (!pathOk(m_compensation.suspend())) return false;
    m_status = interp::RunStatus::NeedsSync;
    return true;
}

void FagorInterpreter::loadToolOffset() {
    const bool none = m_tool.tool == 0 || m_tool.offset == 0;
    if (none) {
        m_tool.data = ToolOffset{};
    } else if (m_toolOffsets) {
        m_tool.data = m_toolOffsets->get(m_tool.offset);
    } else {
        m_tool.data = ToolOffset{};
        m_tool.data.number = m_tool.offset;
        if (!m_warnedNoOffsets) {
            m_warnedNoOffsets = true;
            warn("tool",
                 KERF_TR_NOOP("no tool offset table: offset D{1} and the following ones "
                              "are all zero"),
                 {std::to_string(m_tool.offset)});
        }
    }
}

void FagorInterpreter::applyTool() {
    const TipDirection tip = tipDirection(m_tool.data.location);
    // The table's Z values go along the abscissa, its X values along the ordinate (PLACOMP).
    const Vec2 inFrame(tip.z, tip.x);
    m_compensation.setTool(m_tool.radius, m_modal.plane.toGeometry(inFrame));
}

}  // namespace kerf::fagor
