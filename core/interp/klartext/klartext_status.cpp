// The state the HMI status tabs show, copied out of the Klartext interpreter.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/cycles/cycle_registry.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/klartext/spatial_angles.h"

namespace kerf::klartext {
namespace {

// The name of the label whose body starts at `position`, as "LBL 5" or "LBL "NAME"".
std::string labelName(const ProgramFile& program, const LabelPosition& position) {
    for (const auto& [number, at] : program.numberedLabels) {
        if (at.offset == position.offset) return "LBL " + std::to_string(number);
    }
    for (const auto& [name, at] : program.namedLabels) {
        if (at.offset == position.offset) return "LBL \"" + name + "\"";
    }
    return "LBL";
}

void addParameters(const QParameters& q, interp::ProgramStatus& status) {
    using Scope = interp::ProgramStatus::ParameterScope;
    const struct {
        QKind kind;
        Scope scope;
    } families[] = {{QKind::Q, Scope::Global},
                    {QKind::QL, Scope::Local},
                    {QKind::QR, Scope::Remanent},
                    {QKind::QS, Scope::Text}};
    for (const auto& family : families) {
        for (int i = 0; i < qLimit(family.kind); ++i) {
            const QRef ref{family.kind, static_cast<uint16_t>(i)};
            if (!q.isSet(ref)) continue;
            interp::ProgramStatus::Parameter p;
            p.name = qPrefix(family.kind) + std::to_string(i);
            p.scope = family.scope;
            if (family.kind == QKind::QS) {
                p.text = q.getString(ref.index);
            } else {
                p.value = q.get(ref);
            }
            status.parameters.push_back(std::move(p));
        }
    }
}

}  // namespace

interp::ProgramStatus KlartextInterpreter::programStatus() const {
    interp::ProgramStatus status;
    if (!m_levels.empty()) {
        status.mainProgram = m_sources.displayName(m_levels.front().program->fileId);
        status.activeProgram = m_sources.displayName(m_levels.back().program->fileId);
        status.inch = m_levels.back().inch;
    }
    if (!m_frames.empty() && m_frames.back().level < m_levels.size()) {
        const LabelFrame& frame = m_frames.back();
        status.label = labelName(*m_levels[frame.level].program, frame.target);
    }
    if (m_lastCycleDefined >= 0) {
        const cycles::CycleDescriptor* d = cycles::findCycle(m_lastCycleDefined);
        status.cycle = interp::ProgramStatus::Cycle{m_lastCycleDefined,
                                                    d != nullptr && d->name ? d->name : ""};
    }
    status.probe = m_lastProbe;
    status.activeM.push_back(m_spindle == canon::SpindleDirection::Clockwise          ? 3
                             : m_spindle == canon::SpindleDirection::CounterClockwise ? 4
                                                                                      : 5);
    status.activeM.push_back(m_coolant ? 8 : 9);
    if (m_modalCycleCall) status.activeM.push_back(89);
    status.line = m_at.line;
    status.blockNumber = m_at.blockNumber;

    status.motion.spindleRpm = m_spindleSpeed;
    status.motion.feedMm = m_feed;
    status.motion.feedPerRevolution = m_feedMode == canon::FeedMode::PerRevolution;

    status.tool.number = m_tool.number;
    status.tool.name = m_tool.name;
    status.tool.lengthMm = m_tool.length;
    status.tool.radiusMm = m_tool.radius;
    status.tool.deltaLengthMm = m_tool.tableDl + m_tool.callDl;
    status.tool.deltaRadiusMm = m_tool.tableDr + m_tool.callDr;
    status.tool.axis = m_toolAxis;

    auto& t = status.transformations;
    t.datumShift = m_frame.shift();
    t.mirrored = m_frame.mirror();
    t.rotationDeg = m_frame.rotationDeg();
    for (int i = 0; i < kAxisCount; ++i) {
        const bool linear = cycles::isLinearAxis(static_cast<Axis>(i));
        t.scale[static_cast<size_t>(i)] =
            linear ? m_frame.scale() * m_frame.axisScale()[static_cast<size_t>(i)] : 1.0;
    }
    if (m_tilt.active) {
        interp::ProgramStatus::Transformations::WorkingPlane plane;
        plane.spatialDeg = spatialAnglesOf(m_tilt.rotation);
        plane.positionMm = {m_programmed[Axis::X], m_programmed[Axis::Y], m_programmed[Axis::Z]};
        if (m_kinematics) {
            auto solved = [&](char letter, double deg) {
                const Axis axis = *axisFromLetter(letter);
                plane.rotaryAxes |= axisBit(axis);
                plane.rotaryDeg[static_cast<size_t>(axisIndex(axis) - axisIndex(Axis::A))] = deg;
            };
            solved(m_kinematics->primary(), m_tiltAngles.primaryDeg);
            if (m_kinematics->twoAxes())
                solved(m_kinematics->secondary(), m_tiltAngles.secondaryDeg);
        }
        // The frame is affine in the linear axes: its origin and the images of the unit axes.
        Pose zero{};
        const Vec3 origin = m_frame.toProgram(zero).xyz();
        for (int column = 0; column < 3; ++column) {
            Pose unit{};
            unit.values[static_cast<size_t>(column)] = 1.0;
            const Vec3 image = m_frame.toProgram(unit).xyz() - origin;
            for (int row = 0; row < 3; ++row)
                plane.axesToProgram[static_cast<size_t>(3 * row + column)] = image[row];
        }
        plane.programAtAxesZeroMm = {origin.x(), origin.y(), origin.z()};
        if (m_tcpm && m_kinematics) {
            plane.tipFollowsTables = true;
            const Vec3 preset = tiltPreset();
            plane.presetInMachineMm = {preset.x(), preset.y(), preset.z()};
            for (size_t i = 0; i < 3; ++i)
                plane.rotaryPresetDeg[i] =
                    m_settings.presetInMachine.values[static_cast<size_t>(axisIndex(Axis::A)) + i];
            plane.toolLengthMm = m_tool.effectiveLength();
        }
        t.workingPlane = plane;
    }
    addParameters(m_q, status);
    return status;
}

}  // namespace kerf::klartext
