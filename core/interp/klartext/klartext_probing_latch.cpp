// Touches from the machine's latch (docs/probing.md, "How a cycle runs"): a probing block hands
// each touch to the machine as a probe move and a sync point, and runs again from its start when
// the latched position comes back, following its own positions quietly up to the last latched
// touch. The cycles are deterministic, so each pass repeats the one before up to there.
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

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
    TouchReplay& replay = *m_touchReplay;
    replay.latched.push_back({world.probeTriggered, world.probePosition});
    replay.waiting = false;
    // The probe stopped beyond the trigger (or at the end of DIST): the moves after the touch
    // start there.
    m_path.resetToMachine(world.position);
    m_programmed = programOfPath(m_path.toolPosition());
    m_cuts.setPosition(world.position.xyz());
    m_status = interp::RunStatus::BudgetUsed;
}

}  // namespace kerf::klartext
