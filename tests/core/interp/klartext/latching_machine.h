#pragma once

// A stand-in for a machine whose probe input latches (settings.touchesFromMachine, docs/probing.md
// "How a cycle runs"): it follows the tool tip through the stream, moves it along each probe move
// and finds by bisection where its surface is first touched, the surface the move carries or
// one a test moves elsewhere.
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/canon/commands.h"
#include "core/interp/interpreter.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

class LatchingMachine : public canon::Sink {
public:
    // What the drives' probe input sees for a tool tip, given the surface the move carries.
    using Surface = std::function<bool(const canon::ProbeSurface&, const Vec3& tip)>;
    static constexpr double kProbingFeed = 1000.0;  // F of a new touch-probe table row

    // `probingFeed`: the feed every probe move must have (0: any).
    explicit LatchingMachine(Surface surface, double braking = 0.05,
                             double probingFeed = kProbingFeed)
        : m_surface(std::move(surface)), m_braking(braking), m_probingFeed(probingFeed) {}

    void consume(const canon::Command& command) override {
        commands.push_back(command);
        const canon::CommandBody& body = command.body;
        if (const auto* rapid = std::get_if<canon::RapidMove>(&body)) m_tip = rapid->target;
        if (const auto* line = std::get_if<canon::LinearMove>(&body)) {
            m_tip = line->target;
            if (m_probingFeed > 0.0 && line->feed == m_probingFeed) ++probingFeedMoves;
        }
        if (const auto* arc = std::get_if<canon::ArcMove>(&body)) m_tip = arc->target;
        if (const auto* message = std::get_if<canon::Message>(&body))
            messages.push_back(message->text);
        if (const auto* stop = std::get_if<canon::ProgramStop>(&body))
            stops += stop->kind == canon::StopKind::Program ? 1 : 0;
        if (const auto* sync = std::get_if<canon::SyncPoint>(&body))
            m_operatorStop = sync->reason == canon::SyncReason::Operator;
        if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) {
            ++probeMoves;
            if (m_probingFeed > 0.0) {
                EXPECT_NEAR(probe->feed, m_probingFeed, 1e-9);
            }
            EXPECT_FALSE(probe->untilRelease);
            m_probe = *probe;
        }
    }

    // The probe move's end: the first touch along it, found to far below a nanometre; the axes
    // then stop `braking` further on. Without a touch they stop at its end point.
    interp::WorldSnapshot latch() {
        interp::WorldSnapshot world;
        if (m_operatorStop) {
            // A stop for the operator: "the operator" jogs the tool tip to the next place.
            m_operatorStop = false;
            EXPECT_LT(placed, places.size());
            if (placed < places.size()) m_tip.setXyz(places[placed++]);
            world.position = m_tip;
            return world;
        }
        EXPECT_TRUE(m_probe.has_value());
        if (!m_probe) return world;
        const canon::ProbeMove probe = *m_probe;
        m_probe.reset();
        EXPECT_NE(probe.surface, nullptr);
        const Vec3 from = m_tip.xyz();
        const Vec3 to = probe.target.xyz();
        auto touching = [&](double t) { return m_surface(*probe.surface, from + t * (to - from)); };
        const double length = (to - from).norm();
        const int steps = static_cast<int>(std::ceil(length / 0.01));
        world.position = probe.target;
        for (int i = 1; i <= steps; ++i) {
            double hi = static_cast<double>(i) / steps;
            if (!touching(hi)) continue;
            double lo = static_cast<double>(i - 1) / steps;
            for (int k = 0; k < 60; ++k)
                (touching((lo + hi) / 2.0) ? hi : lo) = (lo + hi) / 2.0;
            world.probeTriggered = true;
            world.probePosition = probe.target;
            world.probePosition.setXyz(from + hi * (to - from));
            world.position = world.probePosition;
            world.position.setXyz(world.probePosition.xyz() + m_braking * (to - from) / length);
            break;
        }
        m_tip = world.position;
        return world;
    }

    void setTip(const Pose& tip) { m_tip = tip; }

    std::vector<canon::Command> commands;  // everything the interpreter sent
    int probeMoves = 0;
    int probingFeedMoves = 0;  // feed moves of the interpreter's own at the probing feed
    std::vector<Vec3> places;  // where the operator puts the tool tip at each stop
    size_t placed = 0;
    int stops = 0;
    std::vector<std::string> messages;

private:
    bool m_operatorStop = false;
    Surface m_surface;
    double m_braking;
    double m_probingFeed;
    Pose m_tip;
    std::optional<canon::ProbeMove> m_probe;
};

// Runs `interpreter` to its end, `machine` answering each sync point; `atSync` is called before
// each answer.
inline interp::RunStatus runLatched(KlartextInterpreter& interpreter, LatchingMachine& machine,
                                    const std::function<void()>& atSync = {}) {
    machine.setTip(interpreter.nominalPosition());
    for (;;) {
        const interp::RunStatus status = interpreter.run(machine, 1000);
        if (status == interp::RunStatus::NeedsSync) {
            if (atSync) atSync();
            interpreter.resume(machine.latch());
            continue;
        }
        if (status != interp::RunStatus::BudgetUsed) return status;
    }
}

}  // namespace kerf::klartext
