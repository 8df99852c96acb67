// Parameters and internal variables (spec part 2 §5) as the simulated machine answers them.
#include <algorithm>
#include <cmath>
#include <ctime>

#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {

namespace {

std::string nameOf(const VariableRef& ref) {
    std::string name(ref.info->name);
    const VarShape shape = ref.info->shape;
    if (shape == VarShape::Axis || shape == VarShape::AxisTable || shape == VarShape::Gpos) {
        name += axisLetter(ref.axis);
    }
    if (shape == VarShape::Table || shape == VarShape::AxisTable) name += std::to_string(ref.index);
    return name;
}

bool notAvailable(const VariableRef& ref, Problem& problem) {
    return problemOf(problem, "not-available",
                     KERF_TR_NOOP("{1} is not available on the simulated machine"), {nameOf(ref)});
}

// Axis numbers of PLANE: X 1, Y 2, Z 3, U 4, V 5, W 6, A 7, B 8, C 9.
int planeNumber(Axis axis) {
    switch (axis) {
        case Axis::X:
            return 1;
        case Axis::Y:
            return 2;
        case Axis::Z:
            return 3;
        case Axis::U:
            return 4;
        case Axis::V:
            return 5;
        case Axis::W:
            return 6;
        case Axis::A:
            return 7;
        case Axis::B:
            return 8;
        default:
            return 9;
    }
}

int zeroOffsetIndex(int n) {
    if (n >= 54 && n <= 59) return n - 53;
    return n >= 1 && n <= ZeroOffsetTable::kCount ? n : 0;
}

}  // namespace

// ---- parameters ------------------------------------------------------------------------------

bool FagorInterpreter::parameter(int number, double& out, Problem& problem) {
    return m_parameters.get(number, out, problem);
}

bool FagorInterpreter::readParameter(int number, double& out, Problem& problem) {
    return m_parameters.get(number, out, problem);
}

bool FagorInterpreter::writeParameter(int number, double value, Problem& problem) {
    return m_parameters.set(number, value, problem);
}

// ---- helpers ---------------------------------------------------------------------------------

double FagorInterpreter::displayed(Axis axis, double radiusMm) const {
    if (axis == Axis::A || axis == Axis::B || axis == Axis::C) return radiusMm;
    const double v = units(radiusMm);
    return axis == Axis::X && m_modal.diameter ? 2.0 * v : v;
}

double FagorInterpreter::tipLength(Axis axis) const {
    if (axis == Axis::X) return m_tool.data.x + m_tool.data.wearX;
    if (axis == Axis::Z) return m_tool.data.z + m_tool.data.wearZ;
    return 0.0;
}

uint8_t FagorInterpreter::statementFlags(std::string_view text) const {
    uint8_t flags = 0;
    bool inString = false;
    size_t i = 0;
    while (i < text.size()) {
        if (text[i] == '"') inString = !inString;
        if (inString || !isUpper(text[i])) {
            ++i;
            continue;
        }
        const size_t start = i;
        while (i < text.size() && isUpper(text[i]))
            ++i;
        const std::string_view word = text.substr(start, i - start);
        const VariableInfo* v = findVariable(word, VarShape::Simple);
        if (v == nullptr) v = findVariable(word, VarShape::Table);
        if (v == nullptr && word.size() > 1 && axisFromLetter(word.back())) {
            v = findVariable(word.substr(0, word.size() - 1), VarShape::Axis);
        }
        if (v != nullptr)
            flags = static_cast<uint8_t>(flags | (v->flags & (kPrepStop | kMachineData)));
    }
    return flags;
}

bool FagorInterpreter::gActive(int n) const {
    const ModalState& m = m_modal;
    switch (n) {
        case 0:
        case 1:
        case 2:
        case 3:
        case 33:
        case 34:
            return m.motion == n;
        case 5:
            return m.corner == CornerKind::Round;
        case 7:
            return m.corner == CornerKind::Sharp;
        case 50:
            return m.corner == CornerKind::Controlled;
        case 51:
            return m.corner == CornerKind::LookAhead;
        case 10:
            return m.mirror == 0;
        case 11:
            return (m.mirror & axisBit(Axis::X)) != 0;
        case 12:
            return (m.mirror & axisBit(Axis::Y)) != 0;
        case 13:
            return (m.mirror & axisBit(Axis::Z)) != 0;
        case 16:
        case 17:
        case 18:
        case 19:
            return m.planeG == n;
        case 32:
            return m.feed == FeedKind::InverseTime;
        case 94:
            return m.feed == FeedKind::PerMinute;
        case 95:
            return m.feed == FeedKind::PerRevolution;
        case 40:
            return m.side == interp::CompSide::None;
        case 41:
            return m.side == interp::CompSide::Left;
        case 42:
            return m.side == interp::CompSide::Right;
        case 54:
        case 55:
        case 56:
        case 57:
            return !m_selection.byG159 && !m_selection.preset && m_selection.absolute == n - 53;
        case 58:
        case 59:
            return m_selection.additive == n - 53;
        case 159:
            return m_selection.byG159;
        case 70:
            return m.inch;
        case 71:
            return !m.inch;
        case 72:
            return m.scale != 1.0;
        case 90:
            return !m.incremental;
        case 91:
            return m.incremental;
        case 96:
            return m.constantSurfaceSpeed;
        case 97:
            return !m.constantSurfaceSpeed;
        case 151:
            return m.diameter;
        case 152:
            return !m.diameter;
        case 233:
            return m.retractionAxes != 0;
        default:
            return false;
    }
}

// ---- reading ---------------------------------------------------------------------------------

bool FagorInterpreter::readVariable(const VariableRef& ref, double& out, Problem& problem) {
    const VariableInfo& v = *ref.info;
    if ((v.flags & kRead) == 0) {
        return problemOf(problem, "variable",
                         KERF_TR_NOOP("{1} cannot be read from a part program (PLC or DNC only)"),
                         {nameOf(ref)});
    }
    switch (v.family) {
        case VarFamily::Tool:
            return readToolVariable(ref, out, problem);
        case VarFamily::ZeroOffset:
            return readZeroOffsetVariable(ref, out, problem);
        case VarFamily::WorkZone: {
            const int offset = static_cast<int>(v.id) - static_cast<int>(VarId::Zone1);
            const int zone = offset / 3 + 1;
            const int kind = offset % 3;
            if (kind == 0) {
                out = static_cast<double>(static_cast<int>(m_zones.mode(zone)));
            } else {
                auto limit =
                    kind == 1 ? m_zones.lower(zone, ref.axis) : m_zones.upper(zone, ref.axis);
                const bool rotary =
                    ref.axis == Axis::A || ref.axis == Axis::B || ref.axis == Axis::C;
                out = limit ? (rotary ? *limit : units(*limit)) : 0.0;
            }
            return true;
        }
        case VarFamily::Feed:
            return readFeedVariable(ref, out);
        case VarFamily::Position:
            return readPositionVariable(ref, out, problem);
        case VarFamily::Spindle:
            return readSpindleVariable(ref, out);
        case VarFamily::Parameters:
            out = static_cast<double>(m_parameters.definedLocals());
            return true;
        case VarFamily::OperatingMode:
            out = m_settings.operatingMode;
            return true;
        case VarFamily::Other:
            return readOtherVariable(ref, out, problem);
        case VarFamily::MachineParameter:
        case VarFamily::Handwheel:
        case VarFamily::Measurement:
        case VarFamily::Plc:
            break;
    }
    return notAvailable(ref, problem);
}

bool FagorInterpreter::readToolVariable(const VariableRef& ref, double& out, Problem& problem) {
    const VarId id = ref.info->id;
    switch (id) {
        case VarId::Tool:
            out = m_tool.tool;
            return true;
        case VarId::Tod:
            out = m_tool.offset;
            return true;
        case VarId::NxTool:
            out = m_tool.nextTool >= 0 ? m_tool.nextTool : 0;
            return true;
        case VarId::NxTod:
            out = m_tool.nextOffset >= 0 ? m_tool.nextOffset : 0;
            return true;
        case VarId::Htor:
            out = units(m_tool.radius);
            return true;
        case VarId::Tmzp:
        case VarId::Tmzt:
            return problemOf(problem, "not-available",
                             KERF_TR_NOOP("{1}: the simulated machine has no tool magazine"),
                             {nameOf(ref)});
        default:
            break;
    }
    const bool offsetVariable = id == VarId::Tox || id == VarId::Toz || id == VarId::Tof ||
                                id == VarId::Tor || id == VarId::Toi || id == VarId::Tok;
    if (offsetVariable) {
        if (ref.index < 0 || ref.index > ToolOffsetTable::kMaxOffset) {
            return problemOf(problem, "variable", KERF_TR_NOOP("{1}: offsets are numbered 0-255"),
                             {nameOf(ref)});
        }
        const ToolOffset o = m_toolOffsets ? m_toolOffsets->get(ref.index) : ToolOffset{};
        switch (id) {
            case VarId::Tox:
                out = units(o.x);
                break;
            case VarId::Toz:
                out = units(o.z);
                break;
            case VarId::Tof:
                out = o.location;
                break;
            case VarId::Tor:
                out = units(o.radius);
                break;
            case VarId::Toi:
                out = units(o.wearX);
                break;
            default:
                out = units(o.wearZ);
                break;
        }
        return true;
    }
    const ToolEntry t = m_toolTable ? m_toolTable->get(ref.index) : ToolEntry{ref.index, ref.index};
    switch (id) {
        case VarId::Tlfd:
            out = t.offset;
            break;
        case VarId::Tlff:
            out = t.family;
            break;
        case VarId::Tlfn:
            out = t.nominalLife;
            break;
        case VarId::Tlfr:
            out = t.realLife;
            break;
        case VarId::NoseA:
            out = t.noseAngle;
            break;
        case VarId::NoseW:
            out = units(t.noseWidth);
            break;
        default:
            out = t.cuttingAngle;
            break;
    }
    return true;
}

bool FagorInterpreter::readZeroOffsetVariable(const VariableRef& ref, double& out,
                                              Problem& problem) {
    const bool rotary = ref.axis == Axis::A || ref.axis == Axis::B || ref.axis == Axis::C;
    auto value = [&](double mm) { return rotary ? mm : units(mm); };
    const Pose plc = m_zeroOffsets ? m_zeroOffsets->plcOffset() : Pose{};
    switch (ref.info->id) {
        case VarId::Org:
            out = value(m_offset[ref.axis] - plc[ref.axis]);
            return true;
        case VarId::PorgF:
        case VarId::PorgS: {
            const PlaneFrame& plane = m_modal.plane;
            const bool abscissa = ref.info->id == VarId::PorgF;
            const Axis axis = abscissa ? plane.abscissa : plane.ordinate;
            out = displayed(axis, abscissa ? m_polarOrigin.x() : m_polarOrigin.y());
            return true;
        }
        case VarId::OrgTable: {
            const int index = zeroOffsetIndex(ref.index);
            if (index == 0) {
                return problemOf(problem, "variable",
                                 KERF_TR_NOOP("{1}: zero offsets are 54-59 and 1-20"),
                                 {nameOf(ref)});
            }
            out = value(m_zeroOffsets ? m_zeroOffsets->offset(index)[ref.axis] : 0.0);
            return true;
        }
        case VarId::PlcOf:
            out = value(plc[ref.axis]);
            return true;
        default:  // ADIOF: no additive handwheel
            out = 0.0;
            return true;
    }
}

bool FagorInterpreter::readFeedVariable(const VariableRef& ref, double& out) {
    const FeedKind mode = m_modal.feed;
    const double feed = mode == FeedKind::InverseTime ? m_feed : units(m_feed);
    switch (ref.info->id) {
        case VarId::FReal:
        case VarId::Feed:
        case VarId::PrgF:
            out = mode == FeedKind::PerMinute ? feed : 0.0;
            return true;
        case VarId::FPrev:
        case VarId::PrgFpr:
            out = mode == FeedKind::PerRevolution ? feed : 0.0;
            return true;
        case VarId::PrgFin:
            out = mode == FeedKind::InverseTime ? feed : 0.0;
            return true;
        case VarId::FRealAxis:
        case VarId::FTeoAxis: {
            // The axis's share of the last feed move.
            const double len = m_lastDelta.xyz().norm();
            out = len > 0.0 ? units(m_feed) * std::fabs(m_lastDelta[ref.axis]) / len : 0.0;
            return true;
        }
        case VarId::Fro:
            out = m_programFeedOverride > 0.0 ? m_programFeedOverride : 100.0;
            return true;
        case VarId::PrgFro:
            out = m_programFeedOverride;
            return true;
        case VarId::CncFro:
        case VarId::PlcCfr:
            out = 100.0;
            return true;
        default:  // selected by DNC or PLC: none
            out = 0.0;
            return true;
    }
}

bool FagorInterpreter::readPositionVariable(const VariableRef& ref, double& out, Problem& problem) {
    const Axis axis = ref.axis;
    const double shift = m_offset[axis] - m_startOffset[axis];
    switch (ref.info->id) {
        case VarId::PPos:
            out = displayed(axis, programmedPosition()[axis]);
            return true;
        case VarId::Dply:
            out = displayed(axis, m_position[axis] - shift);
            return true;
        case VarId::Pos:
        case VarId::TPos:
            // The tool base (holder) in machine coordinates.
            out = displayed(axis, m_world[axis] + m_startOffset[axis] - tipLength(axis));
            return true;
        case VarId::APos:
        case VarId::ATPos:
            out = displayed(axis, m_world[axis] - shift - tipLength(axis));
            return true;
        case VarId::Flwe:
            out = 0.0;
            return true;
        case VarId::GPos:
            return gpos(ref, out, problem);
        case VarId::Dist: {
            const bool rotary = axis == Axis::A || axis == Axis::B || axis == Axis::C;
            out = rotary ? m_output.distance(axis) : units(m_output.distance(axis));
            return true;
        }
        case VarId::LimPl:
            out = units(m_secondUpperLimit[static_cast<size_t>(axisIndex(axis))]);
            return true;
        default:
            out = units(m_secondLowerLimit[static_cast<size_t>(axisIndex(axis))]);
            return true;
    }
}

bool FagorInterpreter::readSpindleVariable(const VariableRef& ref, double& out) {
    const bool running = m_spindle.direction != canon::SpindleDirection::Stopped;
    double rpm = m_spindle.rpm;
    if (m_modal.constantSurfaceSpeed) {
        const double radius =
            std::fabs(m_position[Axis::X] - m_offset[Axis::X] + m_startOffset[Axis::X]);
        rpm = radius > 1e-9
                  ? std::min(1000.0 * m_spindle.surface / (kPi * 2.0 * radius), maxSpindleRpm())
                  : maxSpindleRpm();
    }
    const double surface = m_modal.inch ? m_spindle.surface / 0.3048 : m_spindle.surface;
    switch (ref.info->id) {
        case VarId::SReal:
        case VarId::FTeoS:
            out = running ? rpm : 0.0;
            return true;
        case VarId::Speed:
        case VarId::PrgS:
            out = m_spindle.rpm;
            return true;
        case VarId::Css:
        case VarId::PrgCss:
            out = m_modal.constantSurfaceSpeed ? surface : 0.0;
            return true;
        case VarId::Sso:
            out = m_programSpindleOverride > 0.0 ? m_programSpindleOverride : 100.0;
            return true;
        case VarId::PrgSso:
            out = m_programSpindleOverride;
            return true;
        case VarId::CncSso:
            out = 100.0;
            return true;
        case VarId::SLimit:
            out = maxSpindleRpm();
            return true;
        case VarId::PrgSl:
        case VarId::MdiSl:
            out = m_spindle.limit;
            return true;
        case VarId::PosS:
        case VarId::TPosS:
        case VarId::PrgSp:
            out = m_spindle.orientation;
            return true;
        case VarId::RPosS:
        case VarId::RTPosS:
            out = std::fmod(std::fmod(m_spindle.orientation, 360.0) + 360.0, 360.0);
            return true;
        default:  // selected by DNC or PLC (none), following error (none)
            out = 0.0;
            return true;
    }
}

bool FagorInterpreter::readOtherVariable(const VariableRef& ref, double& out, Problem& problem) {
    const auto seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_startTime);
    switch (ref.info->id) {
        case VarId::NbTool: {
            const bool inChange = std::any_of(m_frames.begin(), m_frames.end(), [](const Frame& f) {
                return f.kind == Frame::Kind::MFunction && f.mFunction == 6;
            });
            if (!inChange) {
                return problemOf(problem, "variable",
                                 KERF_TR_NOOP("NBTOOL can only be read in the tool change "
                                              "subroutine"));
            }
            out = m_tool.nextTool >= 0 ? m_tool.nextTool : m_tool.tool;
            return true;
        }
        case VarId::PrgN:
            out = m_programs.empty() ? -1 : m_programs.front()->number;
            return true;
        case VarId::BlkN:
            out = static_cast<double>(m_lastLabel);
            return true;
        case VarId::Gs:
            out = gActive(ref.index) ? 1.0 : 0.0;
            return true;
        case VarId::Ms: {
            static constexpr int kKnown[] = {0, 1, 2, 3, 4, 5, 6, 8, 9, 19, 30, 41, 42, 43, 44};
            if (std::find(std::begin(kKnown), std::end(kKnown), ref.index) == std::end(kKnown)) {
                return problemOf(problem, "variable",
                                 KERF_TR_NOOP("MS{1}: the state is kept for M00-M06, M08, M09, "
                                              "M19, M30 and M41-M44"),
                                 {std::to_string(ref.index)});
            }
            out = m_mActive[static_cast<size_t>(ref.index)] ? 1.0 : 0.0;
            return true;
        }
        case VarId::Plane:
            out = planeNumber(m_modal.plane.abscissa) * 16 + planeNumber(m_modal.plane.ordinate);
            return true;
        case VarId::LongAx:
            out = 3;
            return true;
        case VarId::Mirror: {
            int bits = 0;
            int bit = 0;
            for (char letter : m_settings.machine->enabledAxisLetters()) {
                if ((m_modal.mirror & axisBit(*axisFromLetter(letter))) != 0) bits |= 1 << bit;
                ++bit;
            }
            out = bits;
            return true;
        }
        case VarId::Scale:
            out = m_modal.scale;
            return true;
        case VarId::ScaleAxis:
            out = m_modal.axisScale[static_cast<size_t>(axisIndex(ref.axis))];
            return true;
        case VarId::Clock:
            out = std::floor(seconds.count());
            return true;
        case VarId::CyTime:
            out = std::floor(seconds.count() * 100.0);
            return true;
        case VarId::Time:
        case VarId::Date: {
            const std::time_t now = std::time(nullptr);
            std::tm local{};
            localtime_r(&now, &local);
            out = ref.info->id == VarId::Time
                      ? local.tm_hour * 10000 + local.tm_min * 100 + local.tm_sec
                      : (local.tm_year % 100) * 10000 + (local.tm_mon + 1) * 100 + local.tm_mday;
            return true;
        }
        case VarId::Timer:
            out = m_timer;
            return true;
        case VarId::PartC:
            out = m_partCounter;
            return true;
        case VarId::First:
            out = 1.0;
            return true;
        case VarId::KeySrc:
            out = m_keySource;
            return true;
        case VarId::Key:
            out = m_key;
            return true;
        case VarId::Ib:
            if (ref.index < 0 || ref.index >= UserScreen::kInputs) {
                return problemOf(problem, "variable", KERF_TR_NOOP("{1}: inputs are IB0-IB25"),
                                 {nameOf(ref)});
            }
            out = m_settings.userScreen != nullptr
                      ? m_settings.userScreen->input(ref.index)
                      : m_settings.inputValues[static_cast<size_t>(ref.index)];
            return true;
        case VarId::AnaO:
            if (ref.index < 1 || ref.index > 8) {
                return problemOf(problem, "variable", KERF_TR_NOOP("{1}: outputs 1-8"),
                                 {nameOf(ref)});
            }
            out = ref.index <= 4 ? m_analogOut[static_cast<size_t>(ref.index - 1)] : 0.0;
            return true;
        case VarId::AnaI:
            return notAvailable(ref, problem);
        case VarId::SelPro:
            out = m_probeInput;
            return true;
        case VarId::Diam:
            out = m_modal.diameter ? 1.0 : 0.0;
            return true;
        case VarId::PrbMod:
            out = m_probeMode;
            return true;
        case VarId::Rip:
            out = units(m_feed);
            return true;
        default:  // PRBST (not touching), TIMEG (no dwell), ORGROT
            out = 0.0;
            return true;
    }
}

// ---- writing ---------------------------------------------------------------------------------

bool FagorInterpreter::writeVariable(const VariableRef& ref, double value, Problem& problem) {
    const VariableInfo& v = *ref.info;
    if ((v.flags & kWrite) == 0) {
        return problemOf(problem, "variable", KERF_TR_NOOP("{1} is read-only in a part program"),
                         {nameOf(ref)});
    }
    const bool rotary = ref.axis == Axis::A || ref.axis == Axis::B || ref.axis == Axis::C;
    const double mm = m_modal.inch ? value * 25.4 : value;
    switch (v.family) {
        case VarFamily::Tool:
            return writeToolVariable(ref, value, problem);
        case VarFamily::ZeroOffset: {
            if (!m_zeroOffsets) m_zeroOffsets = ZeroOffsetTable::createDefault();
            const double written = rotary ? value : mm;
            if (v.id == VarId::PlcOf) {
                m_zeroOffsets->setPlcOffset(ref.axis, written);
            } else {
                const int index = zeroOffsetIndex(ref.index);
                if (index == 0) {
                    return problemOf(problem, "variable",
                                     KERF_TR_NOOP("{1}: zero offsets are 54-59 and 1-20"),
                                     {nameOf(ref)});
                }
                m_zeroOffsets->setOffset(index, ref.axis, written);
            }
            applyZeroOffset();
            return true;
        }
        case VarFamily::Feed:
            if (value < 0.0 || value > 255.0) {
                return problemOf(problem, "variable", KERF_TR_NOOP("PRGFRO: 0-255 %"));
            }
            m_programFeedOverride = value;
            return true;
        case VarFamily::Spindle:
            if (value < 0.0 || value > 255.0) {
                return problemOf(problem, "variable", KERF_TR_NOOP("PRGSSO: 0-255 %"));
            }
            m_programSpindleOverride = value;
            return true;
        case VarFamily::Position: {
            const auto i = static_cast<size_t>(axisIndex(ref.axis));
            const double written = rotary ? value : mm;
            if (v.id == VarId::Dist) {
                m_output.setDistance(ref.axis, written);
            } else if (v.id == VarId::LimPl) {
                m_secondUpperLimit[i] = written;
            } else {
                m_secondLowerLimit[i] = written;
            }
            return true;
        }
        case VarFamily::Other:
            return writeOtherVariable(ref, value, problem);
        default:
            return notAvailable(ref, problem);
    }
}

bool FagorInterpreter::writeToolVariable(const VariableRef& ref, double value, Problem& problem) {
    const VarId id = ref.info->id;
    const double mm = m_modal.inch ? value * 25.4 : value;
    if (id == VarId::Htor) {
        m_tool.radius = mm;
        applyTool();
        return true;
    }
    static constexpr std::pair<VarId, char> kOffsetFields[] = {
        {VarId::Tox, 'X'}, {VarId::Toz, 'Z'}, {VarId::Tof, 'F'},
        {VarId::Tor, 'R'}, {VarId::Toi, 'I'}, {VarId::Tok, 'K'}};
    for (const auto& [field, letter] : kOffsetFields) {
        if (field != id) continue;
        if (!m_toolOffsets) m_toolOffsets = ToolOffsetTable::createDefault();
        if (!m_toolOffsets->set(ref.index, letter, letter == 'F' ? value : mm)) {
            return problemOf(problem, "variable",
                             KERF_TR_NOOP("{1}: offsets are D1-D255 and F is 0-9"), {nameOf(ref)});
        }
        if (ref.index == m_tool.offset) {
            loadToolOffset();
            applyTool();
        }
        return true;
    }
    static constexpr std::pair<VarId, std::string_view> kToolFields[] = {
        {VarId::Tlfd, "D"},     {VarId::Tlff, "FAM"},    {VarId::Tlfn, "NLIFE"},
        {VarId::Tlfr, "RLIFE"}, {VarId::NoseA, "NOSEA"}, {VarId::NoseW, "NOSEW"},
        {VarId::CutA, "CUTA"}};
    for (const auto& [field, name] : kToolFields) {
        if (field != id) continue;
        if (!m_toolTable) m_toolTable = ToolTable::createDefault();
        if (!m_toolTable->set(ref.index, name, id == VarId::NoseW ? mm : value)) {
            return problemOf(problem, "variable", KERF_TR_NOOP("{1}: value out of range"),
                             {nameOf(ref)});
        }
        // The tool in use carries NOSEA and NOSEW in the stream: a new value goes out with it.
        const bool carried = id == VarId::NoseA || id == VarId::NoseW;
        if (carried && ref.index == m_tool.tool && m_tool.tool > 0) emitToolData(false);
        return true;
    }
    return notAvailable(ref, problem);
}

bool FagorInterpreter::writeOtherVariable(const VariableRef& ref, double value, Problem& problem) {
    auto flag = [&](int& into, double lo, double hi) {
        if (value != std::floor(value) || value < lo || value > hi) {
            return problemOf(problem, "variable", KERF_TR_NOOP("{1}: value out of range"),
                             {nameOf(ref)});
        }
        into = static_cast<int>(value);
        return true;
    };
    switch (ref.info->id) {
        case VarId::Timer:
            m_timer = value;
            return true;
        case VarId::PartC:
            m_partCounter = value;
            return true;
        case VarId::Key:
            if (m_settings.userScreen == nullptr) {
                return problemOf(
                    problem, "variable",
                    KERF_TR_NOOP("KEY can only be written in a customisation program"));
            }
            m_key = static_cast<int>(std::llround(value));
            return true;
        case VarId::KeySrc:
            if (m_keySource != 0) {
                return problemOf(problem, "variable",
                                 KERF_TR_NOOP("KEYSRC can only be changed while it is 0"));
            }
            if (!flag(m_keySource, 0, 2)) return false;
            if (m_settings.userScreen != nullptr) m_settings.userScreen->setKeySource(m_keySource);
            return true;
        case VarId::AnaO:
            if (ref.index < 1 || ref.index > 4 || std::fabs(value) > 10.0) {
                return problemOf(problem, "variable",
                                 KERF_TR_NOOP("{1}: free outputs 1-4, -10 to 10 V"), {nameOf(ref)});
            }
            m_analogOut[static_cast<size_t>(ref.index - 1)] = value;
            return true;
        case VarId::SelPro:
            return flag(m_probeInput, 1, 2);
        case VarId::PrbMod:
            return flag(m_probeMode, 0, 1);
        case VarId::Diam: {
            int diameter = 0;
            if (!flag(diameter, 0, 1)) return false;
            setDiameter(diameter == 1);
            return true;
        }
        default:
            return notAvailable(ref, problem);
    }
}

}  // namespace kerf::fagor
