// Touches from the machine's latch (docs/probing.md, "How a cycle runs"): a probing block hands
// each touch to the machine as a probe move and a sync point, and runs again from its start when
// the latched position comes back, following its own positions quietly up to the last latched
// touch. The cycles are deterministic, so each pass repeats the one before up to there.
#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

namespace {

// [choice] How far the stylus of a touch probe can be deflected beyond the trigger before it is
// damaged (the HEIDENHAIN TS probes' stylus gives way by about 5 mm): the axes, braking from the
// probing feed after the trigger, must stop within it.
constexpr double kStylusOvertravelMm = 5.0;

}  // namespace

void KlartextInterpreter::runTouching(std::function<void()> block) {
    if (!m_settings.touchesFromMachine) {
        block();
        return;
    }
    m_touchReplay = TouchReplay{std::move(block), m_programmed, {}, 0, false};
    passTouching();
}

void KlartextInterpreter::passTouching() {
    TouchReplay& replay = *m_touchReplay;
    replay.next = 0;
    m_programmed = replay.start;
    replay.block();
    if (m_status != interp::RunStatus::Failed && touchHandedToMachine()) {
        m_status = interp::RunStatus::NeedsSync;
        return;
    }
    m_touchReplay.reset();
}

void KlartextInterpreter::resumeTouch(const interp::WorldSnapshot& world) {
    const double beyond = (world.position.xyz() - world.probePosition.xyz()).norm();
    const bool placed = m_touchReplay->placing;
    if (!placed && world.probeTriggered && beyond > kStylusOvertravelMm) {
        m_touchReplay.reset();
        fail("PRB-025",
             KERF_TR_NOOP("the probe stopped {1} mm beyond its touch point, more than its stylus "
                          "can be deflected ({2} mm): lower the probing feed F in tchprobe.tp"),
             {formatFixed(beyond, 3), formatFixed(kStylusOvertravelMm, 1)});
        return;
    }
    TouchReplay& replay = *m_touchReplay;
    // A stop of the semi-automatic mode: where the operator left the probe.
    replay.latched.push_back(placed ? LatchedTouch{false, world.position}
                                    : LatchedTouch{world.probeTriggered, world.probePosition});
    replay.waiting = replay.placing = false;
    // The probe stopped beyond the trigger (or at the end of DIST): the moves after the touch
    // start there.
    m_path.resetToMachine(world.position);
    m_programmed = programOfPath(m_path.toolPosition());
    m_cuts.setPosition(world.position.xyz());
    m_status = interp::RunStatus::BudgetUsed;
}

const KlartextInterpreter::LatchedTouch* KlartextInterpreter::nextLatchedTouch(
    const Pose& farEnd, double feed,
    const std::function<std::shared_ptr<const canon::ProbeSurface>()>& surface) {
    TouchReplay& replay = *m_touchReplay;
    if (replay.waiting) return nullptr;
    const size_t touch = replay.next++;
    if (touch == replay.latched.size()) {
        // The probe move starts where the moves before it end, and the sync point must reach
        // the machine now.
        if (!checkPathError(m_path.flush())) return nullptr;
        emit(canon::ProbeMove{m_frame.toWorkpiece(farEnd), feed, false, surface()});
        emit(canon::SyncPoint{canon::SyncReason::ProbeResult});
        replay.waiting = true;
        return nullptr;
    }
    const LatchedTouch& latch = replay.latched[touch];
    m_lastProbe = interp::ProgramStatus::Probe{latch.triggered, latch.tip};
    return &latch;
}

void KlartextInterpreter::followLatchedTouch(const Pose& end) {
    // The last latched touch: the moves after it start where the machine stopped.
    m_programmed = m_touchReplay->quiet() ? end : programOfPath(m_path.toolPosition());
}

}  // namespace kerf::klartext
