// F, S, T, D and M functions.
#include <algorithm>
#include <cmath>

#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {

bool FagorInterpreter::setFeed(const IsoBlock& iso) {
    // Feeds are kept in mm (per minute or per revolution); G32 F is 1/min.
    const double f = iso.f.value;
    m_feed = m_modal.feed == FeedKind::InverseTime ? f : length(f);
    m_feedSet = true;
    return true;
}

double FagorInterpreter::maxSpindleRpm() const {
    double limit = static_cast<double>(m_settings.machine->spindle.maxRpm);
    if (m_spindle.gear >= 1) {
        const double gear = m_settings.maxGearRpm[static_cast<size_t>(m_spindle.gear - 1)];
        if (gear > 0.0) limit = std::min(limit, gear);
    }
    if (m_spindle.limit > 0.0) limit = std::min(limit, m_spindle.limit);
    return limit;
}

void FagorInterpreter::emitSpindle() {
    canon::SpindleControl control;
    control.direction = m_spindle.direction;
    if (m_modal.constantSurfaceSpeed) {
        control.surfaceSpeedMPerMin = m_spindle.surface;
        control.maxRpm = maxSpindleRpm();
        // The speed at the tip's present diameter (part zero on the spindle axis).
        const double radius =
            std::fabs(m_position[Axis::X] - m_offset[Axis::X] + m_startOffset[Axis::X]);
        const double rpm =
            radius > 1e-9 ? 1000.0 * m_spindle.surface / (kPi * 2.0 * radius) : 1e300;
        control.speedRpm = std::min(rpm, control.maxRpm);
    } else {
        control.speedRpm = m_spindle.rpm;
        control.maxRpm = m_spindle.limit;
    }
    emit(control);
}

bool FagorInterpreter::setSpindleSpeed(const IsoBlock& iso) {
    const bool css = iso.hasG(96) || (!iso.hasG(97) && m_modal.constantSurfaceSpeed);
    if (css) {
        if (iso.s.present) {
            // m/min, or ft/min in inch programming.
            m_spindle.surface = m_modal.inch ? iso.s.value * 0.3048 : iso.s.value;
            m_spindle.surfaceSet = true;
        } else if (!m_spindle.surfaceSet) {
            fail("spindle", KERF_TR_NOOP("G96 needs S: no cutting speed was programmed before"));
            return false;
        }
        // The range may be selected in the G96 block itself (its M functions run after S).
        bool gearInBlock = false;
        for (uint8_t i = 0; i < iso.mCount; ++i)
            gearInBlock =
                gearInBlock || (iso.m[i].number.value >= 41 && iso.m[i].number.value <= 44);
        if (m_spindle.gear == 0 && !gearInBlock && !m_settings.autoGear) {
            fail("spindle", KERF_TR_NOOP("G96 needs a spindle gear range (M41-M44) first"));
            return false;
        }
        m_modal.constantSurfaceSpeed = true;
    } else {
        if (iso.s.present) {
            m_spindle.rpm = iso.s.value;
        } else if (m_modal.constantSurfaceSpeed) {
            // G97 without S: the speed the spindle turns at now becomes the programmed one.
            const double radius =
                std::fabs(m_position[Axis::X] - m_offset[Axis::X] + m_startOffset[Axis::X]);
            m_spindle.rpm = std::min(
                radius > 1e-9 ? 1000.0 * m_spindle.surface / (kPi * 2.0 * radius) : maxSpindleRpm(),
                maxSpindleRpm());
        }
        const double limit = maxSpindleRpm();
        if (m_spindle.rpm > limit + 1e-9) {
            fail("spindle", KERF_TR_NOOP("S{1} is above the spindle limit of {2} rpm"),
                 {formatTableNumber(m_spindle.rpm), formatTableNumber(limit)});
            return false;
        }
        m_modal.constantSurfaceSpeed = false;
    }
    // A new speed reaches a turning spindle now, unless the block's M3, M4, M5 or M19 acts
    // before its motion and sends the spindle's state itself (two SPINDLE lines otherwise).
    if (m_spindle.direction != canon::SpindleDirection::Stopped && !spindleMBeforeMotion(iso)) {
        emitSpindle();
    }
    return true;
}

bool FagorInterpreter::spindleMBeforeMotion(const IsoBlock& iso) const {
    for (uint8_t i = 0; i < iso.mCount; ++i) {
        const int number = static_cast<int>(iso.m[i].number.value);
        if (number != 3 && number != 4 && number != 5 && number != 19) continue;
        const MFunctionEntry* entry = findMFunction(m_settings.mFunctions, number);
        if (entry == nullptr || entry->beforeMotion) return true;
    }
    return false;
}

void FagorInterpreter::emitToolData(bool change) {
    canon::ToolGeometry g;
    g.radiusMm = m_tool.radius;
    g.tipXMm = m_tool.data.x + m_tool.data.wearX;
    g.tipZMm = m_tool.data.z + m_tool.data.wearZ;
    g.offsetNumber = m_tool.offset;
    g.locationCode = m_tool.data.location;
    if (m_toolTable) {
        const ToolEntry entry = m_toolTable->get(m_tool.tool);
        g.cuttingWidthMm = entry.noseWidth;
        g.noseAngleDeg = entry.noseAngle;
    }
    if (change) {
        emit(canon::ToolChange{m_tool.tool, {}, g, Axis::Z});
    } else {
        emit(canon::ToolUpdate{g, Axis::Z});
    }
}

void FagorInterpreter::changeToPreselectedTool() {
    if (!m_settings.toolChangeByM06 || m_tool.nextTool < 0) return;
    const bool change = m_tool.nextTool != m_tool.tool;
    m_tool.tool = m_tool.nextTool;
    m_tool.offset = m_tool.nextOffset;
    m_tool.nextTool = m_tool.nextOffset = -1;
    loadToolOffset();
    m_tool.radius = m_tool.data.radius;
    applyTool();
    emitToolData(change);
}

bool FagorInterpreter::selectTool(const IsoBlock& iso) {
    if (iso.t.present) {
        const int tool = static_cast<int>(iso.t.value);
        int offset = tool;
        if (m_toolTable) offset = m_toolTable->get(tool).offset;
        if (iso.d.present) offset = static_cast<int>(iso.d.value);
        if (m_settings.toolChangeByM06) {
            // The tool waits in the changer for M06.
            m_tool.nextTool = tool;
            m_tool.nextOffset = offset;
            return true;
        }
        const bool change = tool != m_tool.tool;
        m_tool.tool = tool;
        m_tool.offset = offset;
        loadToolOffset();
        m_tool.radius = m_tool.data.radius;  // HTOR takes the table value again
        applyTool();
        emitToolData(change);
        return true;
    }
    m_tool.offset = static_cast<int>(iso.d.value);
    loadToolOffset();
    m_tool.radius = m_tool.data.radius;
    applyTool();
    emitToolData(false);
    return true;
}

bool FagorInterpreter::mFunctions(const IsoBlock& iso, bool beforeMotion, bool& calledSubroutine) {
    for (uint8_t i = 0; i < iso.mCount; ++i) {
        const MWord& m = iso.m[i];
        const int number = static_cast<int>(m.number.value);
        const MFunctionEntry* entry = findMFunction(m_settings.mFunctions, number);
        // An M the table does not know acts at the start of its block.
        const bool before = entry == nullptr || entry->beforeMotion;
        if (before != beforeMotion) continue;
        m_at.column = program::columnOf(m_line.text, m.number.offset);
        const bool alone = iso.mCount == 1 && iso.gCount == 0 && iso.axisMask == 0 &&
                           !iso.f.present && !iso.s.present && !iso.t.present && !iso.d.present &&
                           !iso.r.present && !iso.q.present && !iso.l.present && !iso.i1.present &&
                           !iso.j.present && !iso.k.present;
        if (entry != nullptr && entry->subroutine > 0 && !alone) {
            fail("m-function", KERF_TR_NOOP("M{1} has a subroutine: it must be alone in its block"),
                 {std::to_string(number)});
            return false;
        }
        if (!mFunction(number, m, calledSubroutine)) return false;
        if (m_status != interp::RunStatus::BudgetUsed) return true;
    }
    m_at.column = 1;
    return true;
}

bool FagorInterpreter::mFunction(int number, const MWord& word, bool& calledSubroutine) {
    const MFunctionEntry* entry = findMFunction(m_settings.mFunctions, number);
    const bool recursive = std::any_of(m_frames.begin(), m_frames.end(), [&](const Frame& f) {
        return f.kind == Frame::Kind::MFunction && f.mFunction == number;
    });
    if (entry != nullptr && entry->subroutine > 0 && !recursive) {
        Frame frame;
        frame.kind = Frame::Kind::MFunction;
        frame.returnTo = nextBlock();
        frame.mFunction = number;
        frame.emitMAfter = entry->afterSubroutine;
        frame.callAt = m_at;
        Problem problem;
        if (!callSubroutine(frame, entry->subroutine, nullptr, problem)) {
            failAt(word.number.offset, problem);
            return false;
        }
        calledSubroutine = true;
        return true;
    }
    if (entry != nullptr && entry->stopsPreparation && !preparationStopFree()) return false;
    if (number >= 0 && number < static_cast<int>(m_mActive.size())) {
        m_mActive[static_cast<size_t>(number)] = true;
    }
    auto clear = [&](std::initializer_list<int> ms) {
        for (int m : ms)
            m_mActive[static_cast<size_t>(m)] = false;
    };
    switch (number) {
        case 0:
            emit(canon::ProgramStop{canon::StopKind::Program, 0});
            return true;
        case 1:
            emit(canon::ProgramStop{canon::StopKind::Optional, 1});
            return true;
        case 2:
        case 30:
            m_partCounter += 1.0;
            closeOpenProgram();
            if (std::any_of(m_frames.begin(), m_frames.end(),
                            [](const Frame& f) { return f.kind == Frame::Kind::Program; })) {
                // The end of a program run by EXEC: back to the caller, without a reset.
                while (m_frames.back().kind != Frame::Kind::Program) {
                    if (m_frames.back().newLocals) m_parameters.popLocalLevel();
                    m_frames.pop_back();
                }
                endOfText();
                return true;
            }
            finish(number);
            return true;
        case 3:
        case 4:
            clear({3, 4, 5, 19});
            m_mActive[static_cast<size_t>(number)] = true;
            m_spindle.direction = number == 3 ? canon::SpindleDirection::Clockwise
                                              : canon::SpindleDirection::CounterClockwise;
            emitSpindle();
            return true;
        case 5:
            clear({3, 4, 19});
            m_spindle.direction = canon::SpindleDirection::Stopped;
            emitSpindle();
            return true;
        case 6:
            changeToPreselectedTool();
            return true;
        case 19:
            // Closed loop: the spindle stops turning and goes to the angle.
            clear({3, 4, 5});
            m_spindle.direction = canon::SpindleDirection::Stopped;
            m_spindle.orientation = word.s.present ? word.s.value : 0.0;
            emit(canon::SpindleOrient{m_spindle.orientation});
            return true;
        case 41:
        case 42:
        case 43:
        case 44:
            clear({41, 42, 43, 44});
            m_mActive[static_cast<size_t>(number)] = true;
            m_spindle.gear = number - 40;
            emit(canon::MachineFunction{number});
            return true;
        case 8:  // coolant on (flood), as the machine's status and the drives see it
            clear({9});
            emit(canon::CoolantControl{true, false});
            return true;
        case 9:
            clear({8});
            emit(canon::CoolantControl{false, false});
            return true;
        default:
            emit(canon::MachineFunction{number});
            return true;
    }
}

}  // namespace kerf::fagor
