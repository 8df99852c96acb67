// Feeds, tools, the blank and miscellaneous functions.
#include <algorithm>
#include <cmath>

#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/workpiece/blank_solids.h"

namespace kerf::klartext {

bool KlartextInterpreter::resolveFeed(const FeedWord& word, bool& rapid, double& feed) {
    rapid = false;
    auto setMode = [&](canon::FeedMode mode) {
        if (mode != m_feedMode) {
            m_feedMode = mode;
            emit(canon::SetFeedMode{mode});
        }
    };
    switch (word.kind) {
        case FeedWord::Kind::None:
            break;
        case FeedWord::Kind::Max:
            rapid = true;  // FMAX acts in its own block only
            break;
        case FeedWord::Kind::Value:
            setMode(canon::FeedMode::PerMinute);
            m_feed = word.value * lengthScale();
            m_feedSet = true;
            break;
        case FeedWord::Kind::Auto:
            if (m_toolCallFeed <= 0.0) {
                fail("feed", KERF_TR_NOOP("FAUTO: the TOOL CALL block gave no feed rate F"));
                return false;
            }
            setMode(canon::FeedMode::PerMinute);
            m_feed = m_toolCallFeed;
            m_feedSet = true;
            break;
        case FeedWord::Kind::PerRevolution:
            setMode(canon::FeedMode::PerRevolution);
            m_feed = word.value * lengthScale();
            m_feedSet = true;
            break;
        case FeedWord::Kind::PerTooth:
            if (m_tool.cutterCount <= 0) {
                fail("feed", KERF_TR_NOOP("FZ needs the number of teeth (CUT) of the tool"));
                return false;
            }
            setMode(canon::FeedMode::PerRevolution);
            m_feed = word.value * lengthScale() * m_tool.cutterCount;
            m_feedSet = true;
            break;
    }
    if (!rapid && !m_feedSet) {
        fail("feed", KERF_TR_NOOP("feed rate is missing"));
        return false;
    }
    feed = m_feed;
    return true;
}

bool KlartextInterpreter::hasM(const MWords& m, int number) const {
    for (uint8_t i = 0; i < m.count; ++i) {
        if (m.list[i].number == number) return true;
    }
    return false;
}

void KlartextInterpreter::applyMFunctions(const MWords& m, bool atStart) {
    for (uint8_t i = 0; i < m.count && m_status != interp::RunStatus::Failed; ++i) {
        const MWord& word = m.list[i];
        const int n = word.number;
        // TNC: M3 M4 M8 M13 M14 M107 and M120 LA act at the start of the block, the others at
        // its end.
        const bool startFunction = n == 3 || n == 4 || n == 8 || n == 13 || n == 14 || n == 107 ||
                                   (n == 120 && word.parameter.has_value());
        if (startFunction != atStart) continue;
        switch (n) {
            case 3:
            case 4:
            case 13:
            case 14: {
                m_spindle = (n == 3 || n == 13) ? canon::SpindleDirection::Clockwise
                                                : canon::SpindleDirection::CounterClockwise;
                m_lastSpindleDirection = m_spindle;
                emit(canon::SpindleControl{m_spindle, m_spindleSpeed});
                if (n >= 13) {
                    m_coolant = true;
                    emit(canon::CoolantControl{true, false});
                }
                break;
            }
            case 8:
                m_coolant = true;
                emit(canon::CoolantControl{true, false});
                break;
            case 5:
                m_spindle = canon::SpindleDirection::Stopped;
                emit(canon::SpindleControl{m_spindle, m_spindleSpeed});
                break;
            case 9:
                m_coolant = false;
                emit(canon::CoolantControl{false, false});
                break;
            case 0:
                emit(canon::ProgramStop{canon::StopKind::Program, 0});
                break;
            case 1:
                emit(canon::ProgramStop{canon::StopKind::Optional, 1});
                break;
            case 2:
            case 30:
                finish(true, n);
                return;
            case 91:
            case 92:
                break;  // coordinates of this block, see targetOf()
            case 126:
            case 127:
                m_shortestRotary = n == 126;  // rotaryTarget(): the short way, from this block
                break;
            case 94:
                reduceRotaryDisplay(word.axes);
                break;
            case 107:
            case 108:
                // LN blocks with a tool larger than the CAM system's: permitted from M107 until
                // M108 (klartext_line_normal.cpp). M108's check of a replacement tool's radius
                // has nothing to check: Kerf does not replace tools (M101).
                m_permitOversize = n == 107;
                break;
            case 128:
            case 129:
                switchTcpm(TcpmBlock{n == 128});
                break;
            case 89:  // modal cycle call, from this block on
            case 99:  // cycle call in this block only
                m_modalCycleCall = n == 89;
                callCycleHere();
                break;
            case 19:
                // Oriented spindle stop to the angle of cycle 13; without it the machine's own.
                if (m_orientAngle) {
                    m_spindle = canon::SpindleDirection::Stopped;
                    emit(canon::SpindleOrient{*m_orientAngle});
                } else {
                    emit(canon::MachineFunction{n});
                }
                break;
            case 120:
                // Radius compensation calculated LA blocks ahead; M120 alone or LA0 ends it.
                if (!checkPathError(activePath().setLookAhead(
                        word.parameter ? static_cast<int>(*word.parameter) : 0))) {
                    return;
                }
                // M120 alone is passed on as before: some machines orient the spindle with it
                // (cycle 13).
                if (!word.parameter) emit(canon::MachineFunction{n});
                break;
            case 140: {
                // Retract along the tool axis: MB by a distance, MB MAX to the soft limit.
                if (!checkPathError(m_path.flush())) return;
                // The retraction is along the machine's tool axis, whatever transformation is on.
                Pose target = m_path.machinePosition();
                double& axisValue = target[m_toolAxis];
                if (word.maxParameter || !word.parameter) {
                    const machine::AxisConfig* axis =
                        m_settings.machine ? m_settings.machine->axis(axisLetter(m_toolAxis))
                                           : nullptr;
                    if (axis == nullptr) {
                        fail("machine", KERF_TR_NOOP("M140 MB MAX: the tool axis has no limit"));
                        return;
                    }
                    axisValue = axis->maxLimit - m_settings.presetInMachine[m_toolAxis] -
                                m_tool.effectiveLength();
                } else {
                    axisValue += *word.parameter * lengthScale();
                }
                m_path.addMachineLine(target, true, m_feed, m_at);
                m_programmed = programOfPath(m_path.toolPosition());
                break;
            }
            default:
                emit(canon::MachineFunction{n});
                break;
        }
    }
}

void KlartextInterpreter::reduceRotaryDisplay(AxisMask only) {
    if (!checkPathError(activePath().flush()) || m_settings.machine == nullptr) return;
    for (int i = 0; i < kAxisCount; ++i) {
        const Axis axis = static_cast<Axis>(i);
        if ((only & axisBit(axis)) == 0) continue;
        const machine::AxisConfig* config = m_settings.machine->axis(axisLetter(axis));
        if (config == nullptr || config->type != machine::AxisType::Rotary || !config->enabled) {
            fail("machine", KERF_TR_NOOP("M94 {1}: the machine has no rotary axis {1}"),
                 {std::string(1, axisLetter(axis))});
            return;
        }
    }
    // The axes stay where they are; their angles count from a whole turn nearer to 0, so that
    // the next absolute angle is reached the short way within the turn (TNC M94).
    for (const machine::AxisConfig& config : m_settings.machine->axes) {
        if (config.type != machine::AxisType::Rotary || !config.enabled) continue;
        const Axis axis = *axisFromLetter(config.letter);
        if (only != 0 && (only & axisBit(axis)) == 0) continue;
        const double shown = m_programmed[axis];
        const double reduced = std::fmod(shown, 360.0);
        m_frame.addTurns(axis, shown - reduced);
        m_programmed[axis] = reduced;
    }
    updatePathSpace();
}

void KlartextInterpreter::executeMOnly(const CommonWords& words) {
    m_currentM = words.m;
    if (words.feed.kind != FeedWord::Kind::None) {
        bool rapid = false;
        double feed = 0.0;
        if (!resolveFeed(words.feed, rapid, feed)) return;
    }
    applyMFunctions(words.m, true);
    if (m_status != interp::RunStatus::Failed) applyMFunctions(words.m, false);
}

void KlartextInterpreter::executeToolDef(const ToolDef& def) {
    if (!def.number) {
        m_preparedTool = -1;
        return;
    }
    m_preparedTool = *def.number;
    if (def.length || def.radius) {
        tables::ToolData data;
        data.number = *def.number;
        data.length = def.length.value_or(0.0) * lengthScale();
        data.radius = def.radius.value_or(0.0) * lengthScale();
        m_programTools[*def.number] = data;
    }
}

void KlartextInterpreter::executeToolCall(const ToolCall& call) {
    // A tool call ends the look-ahead of M120.
    if (!checkPathError(m_path.flush()) || !checkPathError(m_path.setLookAhead(0))) return;
    const double scale = lengthScale();
    bool changed = false;
    if (call.number || call.name) {
        const tables::ToolData* data = nullptr;
        std::string shown = call.number ? std::to_string(*call.number) : "\"" + *call.name + "\"";
        if (call.number) {
            auto own = m_programTools.find(*call.number);
            if (own != m_programTools.end()) data = &own->second;
        }
        if (data == nullptr && toolTable() != nullptr) {
            data =
                call.number ? toolTable()->byNumber(*call.number) : toolTable()->byName(*call.name);
        }
        tables::ToolData placeholder;
        if (data == nullptr) {
            if (m_settings.tools != nullptr && !(call.number && *call.number == 0)) {
                fail("tool", KERF_TR_NOOP("tool {1} is not in the tool table"), {shown});
                return;
            }
            if (m_settings.tools == nullptr && !m_warnedNoToolTable && call.number != 0) {
                warn("tool",
                     KERF_TR_NOOP("no tool table: tool {1} and the following tools are "
                                  "used with length 0 and radius 0"),
                     {shown});
                m_warnedNoToolTable = true;
            }
            placeholder.number = call.number.value_or(0);
            placeholder.name = call.name.value_or("");
            data = &placeholder;
        }
        if (data->locked) {
            fail("tool", KERF_TR_NOOP("tool {1} is locked (TL)"), {shown});
            return;
        }
        changed = data->number != m_tool.number || data->name != m_tool.name;
        m_tool.number = data->number;
        m_tool.name = data->name;
        m_tool.length = data->length;
        m_tool.radius = data->radius;
        m_tool.radius2 = data->radius2;
        m_tool.tableDl = data->deltaLength;
        m_tool.tableDr = data->deltaRadius;
        m_tool.tableDr2 = data->deltaRadius2;
        m_tool.cutterCount = data->cutterCount;
        m_tool.pointAngle = data->pointAngle;
        m_tool.plungeAngle = data->plungeAngle;
        m_tool.cuttingLength = data->cuttingLength;
        m_tool.pitch = data->pitch;
        m_tool.callDl = m_tool.callDr = m_tool.callDr2 = 0.0;
    }
    if (call.dl) m_tool.callDl = *call.dl * scale;
    if (call.dr) m_tool.callDr = *call.dr * scale;
    if (call.dr2) m_tool.callDr2 = *call.dr2 * scale;
    if (call.axis) m_toolAxis = *call.axis;
    if (call.feed) m_toolCallFeed = *call.feed * scale;
    if (changed) {
        if (isTouchProbe(m_tool.number)) m_cuts.addProbeTool(m_tool.number);
        if (toolTable() != nullptr) {
            if (const tables::ToolData* row = toolTable()->byNumber(m_tool.number))
                m_cuts.setRealTool(m_tool.number, realTool(*row));
        }
        emit(canon::ToolChange{m_tool.number, m_tool.name, m_tool.geometry(), m_toolAxis});
    } else {
        emit(canon::ToolUpdate{m_tool.geometry(), m_toolAxis});
    }
    m_path.setToolRadius(m_tool.effectiveRadius());
    if (m_kinematics && m_kinematics->hasHead() && m_tilt.active) {
        // A turned head holds the new tool's tip elsewhere: the tilted frame follows its length.
        const Pose at = m_frame.toWorkpiece(m_programmed);
        setTableFrame();
        m_programmed = m_frame.toProgram(at);
        updatePathSpace();
    }
    // Parameters the control sets on a tool call.
    m_q.set({QKind::Q, 108}, m_tool.effectiveRadius() / scale);
    m_q.set({QKind::Q, 114}, m_tool.effectiveLength() / scale);
    m_q.set({QKind::Q, 109}, m_toolAxis == Axis::X ? 0.0 : (m_toolAxis == Axis::Y ? 1.0 : 2.0));
    if (call.speed) {
        m_spindleSpeed = *call.speed;
        if (m_settings.machine && m_spindleSpeed > m_settings.machine->spindle.maxRpm) {
            fail("spindle", KERF_TR_NOOP("spindle speed {1} exceeds the machine's {2} rpm"),
                 {std::to_string(m_spindleSpeed),
                  std::to_string(m_settings.machine->spindle.maxRpm)});
            return;
        }
        if (m_spindle != canon::SpindleDirection::Stopped) {
            emit(canon::SpindleControl{m_spindle, m_spindleSpeed});
        }
    }
}

void KlartextInterpreter::executeBlkForm(const BlkForm& blk) {
    const double scale = lengthScale();
    if (blk.kind == BlkForm::Kind::Cylinder) {
        canon::StockCylinder cylinder;
        cylinder.axis = blk.toolAxis;
        cylinder.radiusMm = blk.radius * scale;
        cylinder.innerRadiusMm = blk.innerRadius * scale;
        cylinder.lengthMm = blk.length * scale;
        cylinder.distanceMm = blk.distance * scale;
        emit(canon::StockDefinition{cylinder});
        m_blank = workpiece::blankSolids(canon::StockDefinition{cylinder});
        return;
    }
    if (blk.kind == BlkForm::Kind::MinPoint) {
        Vec3 p(0.0, 0.0, 0.0);
        for (int i = 0; i < 3; ++i) {
            const AxisWord& w = blk.point.axes[static_cast<size_t>(i)];
            if (w.present) p[i] = w.value * scale;
        }
        m_blankMin = p;
        return;
    }
    if (!m_blankMin) {
        fail("blank", KERF_TR_NOOP("BLK FORM 0.2 needs BLK FORM 0.1 before it"));
        return;
    }
    Vec3 q = *m_blankMin;
    for (int i = 0; i < 3; ++i) {
        const AxisWord& w = blk.point.axes[static_cast<size_t>(i)];
        if (w.present) q[i] = w.incremental ? (*m_blankMin)[i] + w.value * scale : w.value * scale;
    }
    canon::StockBox box{m_blankMin->cwiseMin(q), m_blankMin->cwiseMax(q)};
    if ((box.max - box.min).minCoeff() <= 0.0) {
        fail("blank", KERF_TR_NOOP("the blank has no volume"));
        return;
    }
    emit(canon::StockDefinition{box});
    m_blank = workpiece::blankSolids(canon::StockDefinition{box});
}

}  // namespace kerf::klartext
