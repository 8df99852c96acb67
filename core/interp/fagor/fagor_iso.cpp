// ISO blocks: the G functions' modal state and the functions that are a block of their own.
#include <cmath>

#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"
#include "core/interp/fagor/g_functions.h"
#include "core/interp/fagor/g_rules.h"

namespace kerf::fagor {

namespace {

std::string gName(int n) {
    return "G" + std::string(n < 10 ? "0" : "") + std::to_string(n);
}

// G functions that make up their block (with their arguments).
bool isBlockFunction(int g, const IsoBlock& iso) {
    switch (g) {
        case 14:
        case 16:
        case 51:
        case 54:
        case 55:
        case 56:
        case 57:
        case 58:
        case 59:
        case 72:
        case 92:
        case 93:
        case 159:
        case 233:
        case 20:
        case 21:
        case 22:
        case 74:
            return true;
        case 4:
            return !iso.gK.present || !iso.gK.hasValue || iso.gK.value == 0.0;
        default:
            return false;
    }
}

}  // namespace

void FagorInterpreter::executeIso(const IsoBlock& iso, int repetition) {
    Problem problem;
    if (iso.gCount != 0 && !checkGFunctions(iso, problem)) {
        failAt(problem.offset, problem);
        return;
    }
    for (uint8_t i = 0; i < iso.axisCount; ++i) {
        const Axis axis = iso.axisOrder[i];
        const machine::AxisConfig* config =
            m_settings.machine != nullptr ? m_settings.machine->axis(axisLetter(axis)) : nullptr;
        if (config == nullptr || !config->enabled) {
            m_at.column = program::columnOf(m_line.text,
                                            iso.axes[static_cast<size_t>(axisIndex(axis))].offset);
            fail("axis", KERF_TR_NOOP("axis {1} is not available on this machine"),
                 {std::string(1, axisLetter(axis))});
            return;
        }
    }
    for (uint8_t i = 0; i < iso.gCount; ++i) {
        const int g = static_cast<int>(iso.g[i].value);
        if (isBlockFunction(g, iso)) {
            m_at.column = program::columnOf(m_line.text, iso.g[i].offset);
            executeAloneFunction(iso, g);
            return;
        }
    }
    m_functions = BlockFunctions{};
    if (iso.gCount != 0 && !applyModalFunctions(iso)) return;
    if (iso.cycle.g >= 0) {
        (void)executeCycle(iso);
        return;
    }
    if (iso.f.present && !setFeed(iso)) return;
    if ((iso.s.present || iso.hasG(96) || iso.hasG(97)) && !setSpindleSpeed(iso)) return;
    if ((iso.t.present || iso.d.present) && !selectTool(iso)) return;
    bool subroutine = false;
    if (iso.mCount != 0 && !mFunctions(iso, true, subroutine)) return;
    if (subroutine) return;
    const bool motion = hasMotion(iso) || m_functions.hardStop || m_functions.probe != 0;
    if (repetition >= 0 && !(motion && (m_modalSubroutine >= 0 || m_modalProgram >= 0))) {
        m_at.column = program::columnOf(m_line.text, m_block.repetitionOffset);
        fail("repetition",
             KERF_TR_NOOP("N{1}: only a motion block under a modal subroutine (MCALL, MEXEC) or a "
                          "canned cycle can be repeated"),
             {std::to_string(repetition)});
        return;
    }
    if (m_functions.machineCoordinates && !motion) {
        // G53 alone cancels the zero offset.
        m_selection = ZeroOffsetSelection{};
        applyZeroOffset();
    } else if (motion && !executeMotion(iso)) {
        return;
    } else if (!motion && m_modal.motion == 1 && (iso.hasG(41) || iso.hasG(42))) {
        // G01 G41/G42 without axes: compensation starts where the tool is; the first move in the
        // plane goes to its start's perpendicular first (spec part 1 §11.4).
        const Pose here = programmedPosition();
        if (!submit(ContourElement::line(m_modal.plane.plane, here, here), MoveKind::Feed, iso)) {
            return;
        }
    }
    if (iso.mCount != 0 && !mFunctions(iso, false, subroutine)) return;
    if (motion) runModalAfterMotion(repetition);
}

bool FagorInterpreter::applyModalFunctions(const IsoBlock& iso) {
    uint32_t entryColumn = 1;  // of G37, for the check against the motion mode
    for (uint8_t i = 0; i < iso.gCount; ++i) {
        const int n = static_cast<int>(iso.g[i].value);
        const GFunction* g = gFunction(n);
        m_at.column = program::columnOf(m_line.text, iso.g[i].offset);
        const bool lookAhead = m_modal.corner == CornerKind::LookAhead && !iso.hasG(5) &&
                               !iso.hasG(7) && !iso.hasG(50);
        if (lookAhead && (n == 33 || n == 34 || n == 52 || n == 95)) {
            fail("incompatible-g", KERF_TR_NOOP("incompatible G functions G51 and {1} (error 7)"),
                 {gName(n)});
            return false;
        }
        switch (g->group) {
            case GGroup::Motion:
                m_modal.motion = n;
                break;
            case GGroup::ArcForm:
                m_functions.arcForm = n;
                break;
            case GGroup::Plane:
                if (!setPlane(n, iso)) return false;
                break;
            case GGroup::Units:
                m_modal.inch = n == 70;
                break;
            case GGroup::Distance:
                m_modal.incremental = n == 91;
                break;
            case GGroup::XFormat:
                setDiameter(n == 151);
                break;
            case GGroup::FeedMode:
                m_modal.feed = n == 94   ? FeedKind::PerMinute
                               : n == 95 ? FeedKind::PerRevolution
                                         : FeedKind::InverseTime;
                break;
            case GGroup::SpindleMode:
                break;  // with S, in setSpindleSpeed()
            case GGroup::Corner:
                if (m_modal.corner == CornerKind::LookAhead) emit(canon::PathTolerance{0.0});
                m_modal.corner = n == 5   ? CornerKind::Round
                                 : n == 7 ? CornerKind::Sharp
                                          : CornerKind::Controlled;
                break;
            case GGroup::Mirror:
                if (!setMirror(iso)) return false;
                break;
            case GGroup::Compensation: {
                const int motion = iso.hasG(2) || iso.hasG(3) ? 2 : m_modal.motion;
                if (motion == 2 || motion == 3) {
                    fail("compensation",
                         KERF_TR_NOOP("G40, G41 and G42 need G00 or G01 active, not G02/G03"));
                    return false;
                }
                if (n != 40 && m_modal.plane.plane != Plane::ZX &&
                    !m_settings.compensationInAllPlanes) {
                    fail(
                        "compensation",
                        KERF_TR_NOOP("radius compensation works in the ZX plane only (PLACOMP 0)"));
                    return false;
                }
                m_modal.side = n == 40   ? interp::CompSide::None
                               : n == 41 ? interp::CompSide::Left
                                         : interp::CompSide::Right;
                const int blocks = iso.gN.present ? static_cast<int>(iso.gN.value) : 0;
                m_modal.collisionBlocks = n != 40 && blocks >= 3 ? blocks : 0;
                break;
            }
            case GGroup::ZeroOffset:
                m_functions.machineCoordinates = n == 53;
                break;
            case GGroup::CornerShape: {
                const double r = iso.cornerR.present ? iso.cornerR.value : 0.0;
                if (!(r > 0.0)) {
                    fail("geometry", KERF_TR_NOOP("{1} needs R greater than 0 right after it"),
                         {gName(n)});
                    return false;
                }
                m_functions.request.corner = n == 36   ? ContourRequest::Corner::Round
                                             : n == 38 ? ContourRequest::Corner::TangentExit
                                                       : ContourRequest::Corner::Chamfer;
                m_functions.request.cornerSize = length(r) * m_modal.scale;
                break;
            }
            case GGroup::WorkZone:
                break;  // block functions
            case GGroup::None:
                if (n == 6) m_functions.absoluteCentre = true;
                if (n == 52) m_functions.hardStop = true;
                if (n == 75 || n == 76) {
                    m_functions.probe = n;
                    m_functions.probeColumn = m_at.column;
                }
                if (n == 4 && !dwellOrStop(iso)) return false;
                if (n == 37) {
                    const double r = iso.cornerR.present ? iso.cornerR.value : 0.0;
                    if (!(r > 0.0)) {
                        fail("geometry", KERF_TR_NOOP("G37 needs R greater than 0 right after it"));
                        return false;
                    }
                    m_functions.request.entryRadius = length(r) * m_modal.scale;
                    entryColumn = m_at.column;
                }
                break;
        }
    }
    m_at.column = 1;
    const int motion = m_modal.motion;
    if (m_functions.request.entryRadius > 0.0 && motion != 0 && motion != 1) {
        m_at.column = entryColumn;
        fail("geometry", KERF_TR_NOOP("G37 needs a straight line (G00 or G01), not G02/G03"));
        return false;
    }
    if (m_functions.absoluteCentre && motion != 2 && motion != 3 && m_functions.arcForm == 0) {
        fail("geometry", KERF_TR_NOOP("G06 belongs in a circular interpolation block"));
        return false;
    }
    if (m_functions.hardStop || m_functions.probe != 0) {
        m_modal.motion = 1;  // G52, G75 and G76 leave G01 and G40
        m_modal.side = interp::CompSide::None;
    }
    return true;
}

void FagorInterpreter::setDiameter(bool diameter) {
    if (diameter == m_modal.diameter && diameter == m_streamDiameter) return;
    m_modal.diameter = diameter;
    if (diameter != m_streamDiameter) {
        m_streamDiameter = diameter;
        emit(canon::DiameterMode{diameter});
    }
}

bool FagorInterpreter::setPlane(int g, const IsoBlock& iso) {
    PlaneFrame frame;
    if (g == 16) {
        if (iso.axisCount != 2) {
            fail("syntax", KERF_TR_NOOP("G16 needs two axis letters: abscissa and ordinate"));
            return false;
        }
        const Axis a = iso.axisOrder[0];
        const Axis b = iso.axisOrder[1];
        auto plane = planeFromAxes(a, b);
        if (!plane) {
            fail(
                "not-supported",
                KERF_TR_NOOP("G16 {1}{2}: only planes of two of the axes X, Y and Z are supported"),
                {std::string(1, axisLetter(a)), std::string(1, axisLetter(b))});
            return false;
        }
        frame = PlaneFrame::standard(*plane);
        frame.abscissa = a;
        frame.ordinate = b;
        frame.reversed = a != planeAxes(*plane).first;
    } else {
        frame = PlaneFrame::standard(g == 17 ? Plane::XY : g == 18 ? Plane::ZX : Plane::YZ);
    }
    if (m_modal.side != interp::CompSide::None && frame.plane != m_modal.plane.plane) {
        fail("compensation", KERF_TR_NOOP("the plane cannot change under radius compensation"));
        return false;
    }
    m_modal.plane = frame;
    m_modal.planeG = g;
    m_polarOrigin = Vec2(0.0, 0.0);  // the origin of the new plane
    m_lastTangent.reset();
    applyTool();
    return true;
}

bool FagorInterpreter::setMirror(const IsoBlock& iso) {
    AxisMask mask = 0;
    for (uint8_t i = 0; i < iso.gCount; ++i) {
        const int n = static_cast<int>(iso.g[i].value);
        if (n == 10) {
            m_modal.mirror = 0;
            return true;
        }
        if (n == 11) mask |= axisBit(Axis::X);
        if (n == 12) mask |= axisBit(Axis::Y);
        if (n == 13) mask |= axisBit(Axis::Z);
        if (n == 14) {
            for (uint8_t a = 0; a < iso.axisCount; ++a)
                mask |= axisBit(iso.axisOrder[a]);
            m_modal.mirror = mask;
            return true;
        }
    }
    m_modal.mirror = static_cast<AxisMask>(m_modal.mirror | mask);
    return true;
}

bool FagorInterpreter::executeAloneFunction(const IsoBlock& iso, int g) {
    switch (g) {
        case 14:
            return setMirror(iso);
        case 16:
            return setPlane(16, iso);
        case 51:
            return setLookAhead(iso);
        case 72:
            return setScaling(iso);
        case 93:
            return setPolarOrigin(iso);
        case 233:
            return setThreadRetraction(iso);
        case 20:
        case 21:
        case 22:
            return defineWorkZone(g, iso);
        case 74:
            return homing(iso);
        case 4:
            return dwellOrStop(iso);
        default:
            return setZeroOffset(g, iso);
    }
}

bool FagorInterpreter::setLookAhead(const IsoBlock& iso) {
    if (!iso.e51.present || !iso.e51.hasValue) {
        fail("syntax", KERF_TR_NOOP("G51 needs E, the permitted contour error"));
        return false;
    }
    m_modal.corner = CornerKind::LookAhead;
    emit(canon::PathTolerance{length(iso.e51.value)});
    return true;
}

bool FagorInterpreter::setScaling(const IsoBlock& iso) {
    if (iso.s.present) {
        if (!(iso.s.value > 0.0)) {
            fail("geometry", KERF_TR_NOOP("G72 S: the scale factor must be greater than 0"));
            return false;
        }
        m_modal.scale = iso.s.value;
        return true;
    }
    if (iso.axisCount == 0) {
        fail("syntax", KERF_TR_NOOP("G72 needs S or axis factors"));
        return false;
    }
    if (!preparationStopFree()) return false;
    for (uint8_t i = 0; i < iso.axisCount; ++i) {
        const Axis axis = iso.axisOrder[i];
        const double k = iso.axes[static_cast<size_t>(axisIndex(axis))].value;
        if (!(k > 0.0)) {
            fail("geometry", KERF_TR_NOOP("G72: the scale factor of {1} must be greater than 0"),
                 {std::string(1, axisLetter(axis))});
            return false;
        }
        m_modal.axisScale[static_cast<size_t>(axisIndex(axis))] = k;
        m_output.setAxisScale(axis, k);
    }
    return true;
}

bool FagorInterpreter::setPolarOrigin(const IsoBlock& iso) {
    m_polarOrigin = polarOriginOf(iso, m_modal.plane.point(programmedPosition()));
    return true;
}

Vec2 FagorInterpreter::polarOriginOf(const IsoBlock& iso, const Vec2& current) const {
    const PlaneFrame& plane = m_modal.plane;
    if (!iso.i1.present && !iso.j.present) return current;
    // I names the plane axis that comes first in the order X Y Z U V W A B C, J the other (the
    // manual's example: G93 I90 J60 is X90 Z60 in the ZX plane).
    const bool abscissaFirst = axisIndex(plane.abscissa) < axisIndex(plane.ordinate) ||
                               (plane.abscissa == Axis::Z && plane.ordinate == Axis::A);
    const Axis first = abscissaFirst ? plane.abscissa : plane.ordinate;
    const Axis second = abscissaFirst ? plane.ordinate : plane.abscissa;
    Pose origin{};
    origin[first] = axisValue(first, iso.i1.value);
    origin[second] = axisValue(second, iso.j.value);
    return plane.point(origin);
}

bool FagorInterpreter::setThreadRetraction(const IsoBlock& iso) {
    Pose distance{};
    AxisMask axes = 0;
    for (uint8_t i = 0; i < iso.axisCount; ++i) {
        const Axis axis = iso.axisOrder[i];
        const double v = axisValue(axis, iso.axes[static_cast<size_t>(axisIndex(axis))].value);
        distance[axis] = v;
        if (v != 0.0) axes |= axisBit(axis);
    }
    m_modal.retraction = distance;
    m_modal.retractionAxes = axes;
    emit(canon::ThreadRetraction{distance, axes});
    return true;
}

bool FagorInterpreter::defineWorkZone(int g, const IsoBlock& iso) {
    if (!iso.gK.present || !iso.gK.hasValue) {
        fail("syntax", KERF_TR_NOOP("{1} needs K, the zone number 1-4"), {gName(g)});
        return false;
    }
    const int zone = static_cast<int>(iso.gK.value);
    if (g == 22) {
        const double s = iso.s.present ? iso.s.value : -1.0;
        if (s != 0.0 && s != 1.0 && s != 2.0) {
            fail("syntax", KERF_TR_NOOP("G22 needs S0 (off), S1 (no entry) or S2 (no exit)"));
            return false;
        }
        m_zones.setMode(zone, static_cast<WorkZones::Mode>(static_cast<int>(s)));
        return true;
    }
    // Limits from machine zero, in radius: X is not halved in diameter programming.
    for (uint8_t i = 0; i < iso.axisCount; ++i) {
        const Axis axis = iso.axisOrder[i];
        const double raw = iso.axes[static_cast<size_t>(axisIndex(axis))].value;
        const bool rotary = axis == Axis::A || axis == Axis::B || axis == Axis::C;
        const double v = rotary ? raw : length(raw);
        if (g == 20) {
            m_zones.setLower(zone, axis, v);
        } else {
            m_zones.setUpper(zone, axis, v);
        }
    }
    return true;
}

bool FagorInterpreter::dwellOrStop(const IsoBlock& iso) {
    // Every G04 stops block preparation: compensation is interrupted like by G00.
    preparationStop();
    if (m_status != interp::RunStatus::BudgetUsed) return false;
    if (iso.gK.present && iso.gK.hasValue && iso.gK.value > 0.0) {
        emit(canon::Dwell{iso.gK.value / 100.0});
        return true;
    }
    if (iso.gK.present) {
        // G04 K0: update the coordinates to the machine's actual position.
        emit(canon::SyncPoint{canon::SyncReason::ReadPosition});
        if (!pathOk(m_compensation.suspend())) return false;
        m_status = interp::RunStatus::NeedsSync;
    }
    return true;
}

void FagorInterpreter::preparationStop() {
    if (!pathOk(m_shaper.flush())) return;
    (void)pathOk(m_compensation.suspend());
}

bool FagorInterpreter::preparationStopFree() {
    preparationStop();
    return m_status == interp::RunStatus::BudgetUsed;
}

bool FagorInterpreter::homing(const IsoBlock& iso) {
    if (!preparationStopFree()) return false;
    if (m_modal.motion == 2 || m_modal.motion == 3) m_modal.motion = m_settings.imoveLinear ? 1 : 0;
    m_modal.side = interp::CompSide::None;
    if (iso.axisCount == 0) {
        if (m_settings.homingSubroutine <= 0) {
            fail("homing",
                 KERF_TR_NOOP("G74 alone runs the subroutine of REFPSUB, which is not set"));
            return false;
        }
        Problem problem;
        if (call(CallKind::Call, m_settings.homingSubroutine, LocalAssignments{}, problem)) {
            return true;
        }
        failAt(0, problem);
        return false;
    }
    // Axis by axis, in the order written, to the reference point (machine coordinates of the
    // holder, home position of the machine configuration).
    for (uint8_t i = 0; i < iso.axisCount; ++i) {
        const Axis axis = iso.axisOrder[i];
        const machine::AxisConfig* config = m_settings.machine->axis(axisLetter(axis));
        Pose target = m_position;
        double tip = 0.0;
        if (axis == Axis::X) tip = m_tool.data.x + m_tool.data.wearX;
        if (axis == Axis::Z) tip = m_tool.data.z + m_tool.data.wearZ;
        target[axis] = config->homePosition + tip - m_startOffset[axis];
        Move move;
        move.geometry = ContourElement::line(m_modal.plane.plane, m_position, target);
        move.kind = MoveKind::Rapid;
        move.location = m_at;
        if (!pathOk(m_shaper.add(move))) return false;
        m_position = target;
    }
    return true;
}

bool FagorInterpreter::setZeroOffset(int g, const IsoBlock& iso) {
    ZeroOffsetSelection s = m_selection;
    if (g >= 54 && g <= 57) {
        s = ZeroOffsetSelection{};
        s.absolute = g - 53;
    } else if (g == 58 || g == 59) {
        if (s.preset || s.byG159) s = ZeroOffsetSelection{};
        s.additive = g - 53;
    } else if (g == 159) {
        if (!iso.gN.present || !iso.gN.hasValue) {
            fail("syntax", KERF_TR_NOOP("G159 needs N1-N20"));
            return false;
        }
        s = ZeroOffsetSelection{};
        s.absolute = static_cast<int>(iso.gN.value);
        s.byG159 = true;
    } else if (g == 92) {
        if (iso.s.present) {
            m_spindle.limit = iso.s.value;
            if (m_spindle.direction != canon::SpindleDirection::Stopped) emitSpindle();
            return true;
        }
        // The named axes' present tip coordinates become the programmed values (not mirrored).
        const Pose plc = m_zeroOffsets ? m_zeroOffsets->plcOffset() : Pose{};
        Pose offset{};
        for (size_t i = 0; i < offset.values.size(); ++i)
            offset.values[i] = m_offset.values[i] - plc.values[i];
        for (uint8_t i = 0; i < iso.axisCount; ++i) {
            const Axis axis = iso.axisOrder[i];
            const double value =
                axisValue(axis, iso.axes[static_cast<size_t>(axisIndex(axis))].value);
            offset[axis] = m_position[axis] + m_startOffset[axis] - plc[axis] - value;
        }
        s = ZeroOffsetSelection{};
        s.preset = true;
        s.presetOffset = offset;
    }
    m_selection = s;
    applyZeroOffset();
    return true;
}

void FagorInterpreter::applyZeroOffset() {
    Pose offset{};
    if (m_selection.preset) {
        offset = m_selection.presetOffset;
    } else if (m_zeroOffsets) {
        offset = m_zeroOffsets->offset(m_selection.absolute);
        if (m_selection.additive != 0) {
            const Pose add = m_zeroOffsets->offset(m_selection.additive);
            for (size_t i = 0; i < offset.values.size(); ++i)
                offset.values[i] += add.values[i];
        }
    }
    const Pose plc = m_zeroOffsets ? m_zeroOffsets->plcOffset() : Pose{};
    for (size_t i = 0; i < offset.values.size(); ++i)
        offset.values[i] += plc.values[i];
    m_offset = offset;
    if (m_zeroOffsets) m_zeroOffsets->setSelection(m_selection);
}

}  // namespace kerf::fagor
