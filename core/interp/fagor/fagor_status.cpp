// The state the HMI status tabs show, copied out of the FAGOR interpreter.
#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {
namespace {

// "G54", "G54 G58", "G159 N7", "G92"; empty without a zero offset.
std::string zeroOffsetName(const ZeroOffsetSelection& s) {
    if (s.preset) return "G92";
    std::string name;
    if (s.byG159) {
        name = "G159 N" + std::to_string(s.absolute);
    } else if (s.absolute != 0) {
        name = "G" + std::to_string(53 + s.absolute);
    }
    if (s.additive != 0) {
        if (!name.empty()) name += ' ';
        name += "G" + std::to_string(53 + s.additive);
    }
    return name;
}

// M functions that act once (stops, end, tool change) are not shown as active.
bool isOneShot(int m) {
    return m == 0 || m == 1 || m == 2 || m == 6 || m == 30;
}

// The canned cycles' names as the manual's headings give them (spec part 2 §2).
const char* cycleName(int g) {
    switch (g) {
        case 66:
            return KERF_TR_NOOP("Pattern repeat cycle");
        case 68:
            return KERF_TR_NOOP("Stock removal cycle along X");
        case 69:
            return KERF_TR_NOOP("Stock removal cycle along Z");
        case 81:
            return KERF_TR_NOOP("Turning cycle, straight sections");
        case 82:
            return KERF_TR_NOOP("Facing cycle, straight sections");
        case 83:
            return KERF_TR_NOOP("Axial drilling / tapping cycle");
        case 84:
            return KERF_TR_NOOP("Turning cycle, curved sections");
        case 85:
            return KERF_TR_NOOP("Facing cycle, curved sections");
        case 86:
            return KERF_TR_NOOP("Longitudinal threading cycle");
        case 87:
            return KERF_TR_NOOP("Face threading cycle");
        case 88:
            return KERF_TR_NOOP("Grooving cycle along X");
        case 89:
            return KERF_TR_NOOP("Grooving cycle along Z");
        default:
            return "";
    }
}

}  // namespace

interp::ProgramStatus FagorInterpreter::programStatus() const {
    interp::ProgramStatus status;
    if (!m_programs.empty()) status.mainProgram = m_sources.displayName(m_programs.front()->fileId);
    if (m_program != nullptr) status.activeProgram = m_sources.displayName(m_program->fileId);
    for (auto frame = m_frames.rbegin(); frame != m_frames.rend(); ++frame) {
        if (frame->subroutine >= 0) {
            status.label = "SUB " + std::to_string(frame->subroutine);
            break;
        }
    }
    for (size_t m = 0; m < m_mActive.size(); ++m) {
        if (m_mActive[m] && !isOneShot(static_cast<int>(m))) {
            status.activeM.push_back(static_cast<int>(m));
        }
    }
    if (m_lastCycle >= 0)
        status.cycle = interp::ProgramStatus::Cycle{m_lastCycle, cycleName(m_lastCycle)};
    status.line = m_at.line;
    status.blockNumber = m_at.blockNumber;
    status.inch = m_modal.inch;
    status.parameterLetter = 'P';

    status.motion.spindleRpm = m_spindle.rpm;
    if (m_modal.constantSurfaceSpeed && m_spindle.surfaceSet)
        status.motion.surfaceMPerMin = m_spindle.surface;
    status.motion.spindleLimitRpm = m_spindle.limit;
    status.motion.feedMm = m_feed;
    status.motion.feedPerRevolution = m_modal.feed == FeedKind::PerRevolution;

    status.tool.number = m_tool.tool > 0 ? m_tool.tool : -1;
    status.tool.radiusMm = m_tool.data.radius;
    status.tool.lathe = interp::ProgramStatus::Tool::LatheOffset{
        m_tool.offset,     m_tool.data.x,     m_tool.data.z,
        m_tool.data.wearX, m_tool.data.wearZ, m_tool.data.location};

    auto& t = status.transformations;
    t.datum = zeroOffsetName(m_selection);
    t.datumShift = m_offset;
    t.mirrored = m_modal.mirror;
    for (size_t i = 0; i < t.scale.size(); ++i) {
        t.scale[i] = m_modal.scale * m_modal.axisScale[i];
    }

    status.probe = m_lastProbe;

    using Scope = interp::ProgramStatus::ParameterScope;
    const auto addParameter = [&](int number, Scope scope) {
        if (!m_parameters.isSet(number)) return;
        double value = 0.0;
        Problem ignored;
        if (!m_parameters.get(number, value, ignored)) return;
        const int level = scope == Scope::Local ? m_parameters.localLevel() : 0;
        status.parameters.push_back({"P" + std::to_string(number), value, {}, scope, level});
    };
    for (int p = 0; p <= 25; ++p)
        addParameter(p, Scope::Local);
    for (int p = 100; p <= 299; ++p)
        addParameter(p, Scope::Global);
    return status;
}

}  // namespace kerf::fagor
