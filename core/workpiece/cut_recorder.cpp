#include "core/workpiece/cut_recorder.h"

#include <algorithm>
#include <type_traits>

#include "core/workpiece/blank_solids.h"
#include "core/workpiece/simulated_part.h"

namespace kerf::workpiece {

namespace {

// [choice] A tool without a length in its table row (L = 0) cuts this high above its tip.
constexpr double kLengthWithoutTable = 1000.0;

// The part rides on the rotary tables: a cut made with a table turned would have to be turned
// back; the recorder keeps to moves with every rotary axis at 0.
bool rotaryAtZero(const Pose& pose) {
    return pose[Axis::A] == 0.0 && pose[Axis::B] == 0.0 && pose[Axis::C] == 0.0;
}

}  // namespace

void CutRecorder::activeToolIsProbe() {
    if (m_toolNumber >= 0) m_probeTools.insert(m_toolNumber);
    m_cutter = Cutter{};
}

void CutRecorder::setTool(const canon::ToolGeometry& geometry, Axis toolAxis) {
    m_cutter = Cutter{};
    m_tipOffset = Vec3::Zero();
    if (toolAxis != Axis::Z || m_probeTools.contains(m_toolNumber)) return;
    double radius = geometry.radiusMm;
    double length = geometry.lengthMm;
    if (auto real = m_realTools.find(m_toolNumber); real != m_realTools.end()) {
        radius = real->second.radius;
        length = real->second.length;
        m_tipOffset.z() = geometry.lengthMm - length;
    }
    m_cutter.radius = radius;
    m_cutter.cornerRadius = std::clamp(geometry.radius2Mm, 0.0, std::max(radius, 0.0));
    m_cutter.length = length > 0.0 ? length : kLengthWithoutTable;
}

void CutRecorder::moveTo(const Pose& target) {
    if (m_at && rotaryAtZero(target)) {
        m_removed->addLine(m_cutter, *m_at + m_tipOffset, target.xyz() + m_tipOffset);
    }
    m_at = target.xyz();
}

void CutRecorder::checkRapid(const canon::Command& command, const Pose& target) {
    if (!m_part || !m_at || !rotaryAtZero(target) || m_cutter.radius <= 0.0) return;
    if (!m_part->rapidTakesMaterial(m_cutter, *m_at + m_tipOffset, target.xyz() + m_tipOffset))
        return;
    const SourceLocation& at = command.location;
    const bool sameLine = !m_collisions.empty() && m_collisions.back().fileId == at.fileId &&
                          m_collisions.back().line == at.line;
    if (!sameLine) m_collisions.push_back(at);
}

void CutRecorder::consume(const canon::Command& command) {
    std::visit(
        [&](const auto& body) {
            using T = std::decay_t<decltype(body)>;
            if constexpr (std::is_same_v<T, canon::RapidMove>) {
                // [choice] A rapid cuts nothing: into material it is a collision (reported),
                // and a probe positioned into the part must stay deflected.
                checkRapid(command, body.target);
                m_at = body.target.xyz();
            } else if constexpr (std::is_same_v<T, canon::LinearMove> ||
                                 std::is_same_v<T, canon::SpindleSyncedMove>) {
                moveTo(body.target);
            } else if constexpr (std::is_same_v<T, canon::ArcMove>) {
                if (m_at && rotaryAtZero(body.target)) {
                    m_removed->addArc(m_cutter, *m_at + m_tipOffset,
                                      body.target.xyz() + m_tipOffset, body.center + m_tipOffset,
                                      body.plane, body.sweepRad);
                }
                m_at = body.target.xyz();
            } else if constexpr (std::is_same_v<T, canon::ProbeMove>) {
                m_at.reset();  // the machine decides where it ends
            } else if constexpr (std::is_same_v<T, canon::StockDefinition>) {
                m_part = simulatedPart(m_machine, blankSolids(body), Vec3::Zero());
                m_part->setRemoved(m_removed);
            } else if constexpr (std::is_same_v<T, canon::ToolChange>) {
                m_toolNumber = body.number;
                setTool(body.geometry, body.toolAxis);
            } else if constexpr (std::is_same_v<T, canon::ToolUpdate>) {
                setTool(body.geometry, body.toolAxis);
            }
        },
        command.body);
    if (m_target != nullptr) m_target->consume(command);
}

}  // namespace kerf::workpiece
