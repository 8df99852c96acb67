// Cycle 12 (PGM CALL) at the points of CYCL CALL PAT or of cycles 220/221. The tool is
// positioned over each point as for a machining cycle, then the program runs with the point as
// an additional datum shift (spec 1.9: "each point acts as an additional datum shift" for cycle
// 12), so a program written about X0 Y0 Z0 machines at every point. Program calls run as levels
// of the run loop: the next point follows when the called program returns.
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

void KlartextInterpreter::startProgramAtPoints(ProgramAtPoints run) {
    run.callerLevel = m_levels.size();
    run.at = m_at;
    run.program = m_cycle->program;
    run.outerShift = m_frame.pointShift();
    const size_t count = run.plan ? run.plan->points.size() : run.points.size();
    if (count == 0) {
        applyMFunctions(run.after, false);
        return;
    }
    m_pointRuns.push_back(std::move(run));
    callProgramAtNextPoint();
}

void KlartextInterpreter::setPointShift(const Pose& shift) {
    // A datum shift changes coordinates, not where the tool is.
    const Pose at = m_frame.toWorkpiece(m_programmed);
    m_frame.setPointShift(shift);
    m_programmed = m_frame.toProgram(at);
}

void KlartextInterpreter::callProgramAtNextPoint() {
    ProgramAtPoints& run = m_pointRuns.back();
    m_at = run.at;
    const PlaneAxes axes = planeAxes(workingPlane());
    const canon::FeedMode mode = m_feedMode;
    Vec3 datum;
    if (run.plan) {
        approachPatternPoint(*run.plan, run.next);
        const Vec2 p = run.plan->points[run.next].position;
        datum = {p.x(), p.y(), run.plan->surface};
    } else {
        const cycles::PatternPoint& point = run.points[run.next];
        Pose up = m_programmed;
        up[axes.normal] = run.height;
        moveProgrammed(up, run.rapid, run.feed);
        up[axes.first] = point.position.x();
        up[axes.second] = point.position.y();
        moveProgrammed(up, run.rapid, run.feed);
        // PATTERN DEF Z or the point table's tool-axis value shifts the tool axis too.
        datum = {point.position.x(), point.position.y(),
                 point.surface ? *point.surface : point.surfaceOffset};
    }
    restoreFeedMode(mode);
    if (m_status == interp::RunStatus::Failed) return;
    Pose shift = run.outerShift;
    shift[axes.first] += datum.x();
    shift[axes.second] += datum.y();
    shift[axes.normal] += datum.z();
    setPointShift(shift);
    callProgram(CallPgm{run.program});
}

void KlartextInterpreter::returnFromPointProgram() {
    ProgramAtPoints& run = m_pointRuns.back();
    m_at = run.at;
    setPointShift(run.outerShift);
    ++run.next;
    const size_t count = run.plan ? run.plan->points.size() : run.points.size();
    if (run.next < count) {
        callProgramAtNextPoint();
        return;
    }
    const MWords after = run.after;
    m_pointRuns.pop_back();
    applyMFunctions(after, false);
}

}  // namespace kerf::klartext
