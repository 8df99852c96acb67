#include "core/task/instant_motion.h"

namespace kerf::task {

bool InstantMotion::submit(const canon::Command& command) {
    m_block = command.location;
    const canon::CommandBody& body = command.body;
    if (const auto* rapid = std::get_if<canon::RapidMove>(&body)) m_position = rapid->target;
    if (const auto* line = std::get_if<canon::LinearMove>(&body)) m_position = line->target;
    if (const auto* arc = std::get_if<canon::ArcMove>(&body)) m_position = arc->target;
    if (const auto* synced = std::get_if<canon::SpindleSyncedMove>(&body))
        m_position = synced->target;
    if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) m_position = probe->target;
    m_sink.consume(command);
    return true;
}

interp::WorldSnapshot InstantMotion::world() const {
    interp::WorldSnapshot world;
    world.position = m_position;
    // Nothing moves: a probe move touches at its programmed end point.
    world.probeTriggered = true;
    world.probePosition = m_position;
    return world;
}

}  // namespace kerf::task
