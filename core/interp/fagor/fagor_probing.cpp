// Probing moves G75 (until the probe touches) and G76 (until it stops touching), spec part 2 §3:
// a G01 move towards the programmed point that the machine ends; the program continues from where
// the axes really stopped.
#include <string>

#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {

bool FagorInterpreter::probeMove(const IsoBlock& iso) {
    const int g = m_functions.probe;
    const std::string name = "G" + std::to_string(g);
    m_at.column = m_functions.probeColumn;
    if (iso.axisCount == 0 && !iso.r.present && !iso.q.present) {
        fail("probe", KERF_TR_NOOP("{1} needs the coordinates of its end point"), {name});
        return false;
    }
    const ContourRequest& request = m_functions.request;
    if (m_functions.arcForm != 0 || m_functions.absoluteCentre || m_functions.machineCoordinates ||
        request.corner != ContourRequest::Corner::None || request.entryRadius > 0.0) {
        fail("probe",
             KERF_TR_NOOP("{1} is a straight probing move in workpiece coordinates: not with G06, "
                          "G08, G09, G36-G39 or G53"),
             {name});
        return false;
    }
    if (!m_feedSet || m_feed <= 0.0) {
        // A G01 without F runs at the maximum feed: no probe survives that.
        fail("probe", KERF_TR_NOOP("{1} needs a programmed feed F greater than 0"), {name});
        return false;
    }
    // The machine decides where the move ends: nothing may be prepared beyond it.
    if (!preparationStopFree()) return false;
    Pose target;
    bool polar = false;
    if (!targetOf(iso, target, polar)) return false;
    const ContourElement element =
        ContourElement::line(m_modal.plane.plane, programmedPosition(), target);
    const MoveKind kind = g == 75 ? MoveKind::ProbeTouch : MoveKind::ProbeRelease;
    if (!submit(element, kind, iso)) return false;
    m_lastTangent.reset();
    emit(canon::SyncPoint{canon::SyncReason::ProbeResult});
    if (!pathOk(m_compensation.suspend())) return false;
    m_pendingProbe = PendingProbe{g, m_at};
    m_at.column = 1;
    m_status = interp::RunStatus::NeedsSync;
    return true;
}

void FagorInterpreter::probeResult(const interp::WorldSnapshot& world) {
    const PendingProbe probe = *m_pendingProbe;
    m_pendingProbe.reset();
    m_lastProbe = interp::ProgramStatus::Probe{world.probeTriggered, world.probePosition};
    // PROBERR with PRBMOD 0: reaching the programmed point without the probe event is an error.
    if (world.probeTriggered || !m_settings.probeError || m_probeMode != 0) return;
    m_at = probe.at;
    fail("probe", probe.g == 75
                      ? KERF_TR_NOOP("G75 reached its end point without the probe touching")
                      : KERF_TR_NOOP("G76 reached its end point with the probe still touching"));
}

}  // namespace kerf::fagor
