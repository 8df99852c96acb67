// TestRunController's part for Program run: the playback follows the machine instead of the
// clock. Kept apart from test_run_controller.cpp, which plays the test run.
#include <QTimer>
#include <algorithm>

#include "graphics/stock/progressive_stock.h"
#include "ui/testrun/test_run_controller.h"

namespace kerf::ui {

void TestRunController::follow(const QString& text, const std::filesystem::path& path,
                               program::Dialect dialect, const Pose& start) {
    m_timer->stop();
    m_playWhenReady = false;
    m_followingMachine = true;
    m_machinePlayback = true;
    m_waitingSamples.clear();
    m_endWhenReady.reset();
    m_actual.reset();
    m_toMachine.reset();
    m_lastOnPath = false;
    m_feedOverride = m_rapidOverride = 1.0;
    m_sampleClock.invalidate();
    const bool prepared = m_state != State::Interpreting && m_program && text == m_preparedText &&
                          path == m_preparedPath && start == m_preparedStart &&
                          currentOrigin().values == m_preparedOrigin.values;
    if (!prepared) return prepare(text, path, dialect, start);
    startFollowing();
}

void TestRunController::startFollowing() {
    m_follower.emplace(*m_program);
    m_timeS = 0.0;
    m_shownStatus = nullptr;
    newStock();
    setState(State::Following);
    emit progressChanged(m_timeS);
    for (const MachineSample& sample : m_waitingSamples)
        applySample(sample);
    m_waitingSamples.clear();
    if (m_endWhenReady) endFollowing(*m_endWhenReady);
}

void TestRunController::followMachine(const MachineSample& sample) {
    if (!m_followingMachine) return;
    if (m_sampleClock.isValid() && m_sampleClock.elapsed() < m_followIntervalMs) return;
    m_sampleClock.start();
    if (m_state == State::Interpreting) {
        constexpr size_t kMaxWaitingSamples = 100'000;  // about an hour at 25 looks a second
        if (m_waitingSamples.size() < kMaxWaitingSamples) m_waitingSamples.push_back(sample);
        return;
    }
    if (m_state != State::Following) return;
    applySample(sample);
}

void TestRunController::applySample(const MachineSample& sample) {
    if (!m_follower) return;
    const size_t pointsBefore = m_program->placeAt(m_follower->point()).pointsDone;
    const bool wasOnPath = m_lastOnPath && m_follower->startPoint().has_value();
    if (sample.onPath) m_follower->observe(sample.block, sample.nominal);
    m_lastOnPath = sample.onPath;
    m_feedOverride = sample.feedOverride;
    m_rapidOverride = sample.rapidOverride;
    // Tool changes and the blank of the blocks reached go to the stock before the cut.
    m_timeS = std::max(m_timeS, m_program->timeAt(m_follower->point()));
    pushUpTo(m_timeS);
    // Along the path the machine went by the program's points between the two looks (an arc
    // stays an arc); off it (held, jogged away, returning) straight to where the drives are.
    const size_t pointsAfter = m_program->placeAt(m_follower->point()).pointsDone;
    constexpr size_t kMaxPathPointsPerLook = 4096;
    const bool alongPath = wasOnPath && sample.onPath && pointsAfter >= pointsBefore &&
                           pointsAfter - pointsBefore <= kMaxPathPointsPerLook;
    cutTo(sample, alongPath ? pointsBefore : pointsAfter, pointsAfter);
    emit progressChanged(m_timeS);
    publishStatus();
}

void TestRunController::cutTo(const MachineSample& sample, size_t fromPoint, size_t toPoint) {
    // The tip moves without the axes when the tool length changes (a tool change): no cut.
    Pose toMachine;
    for (size_t i = 0; i < toMachine.values.size(); ++i)
        toMachine.values[i] = sample.machine.values[i] - sample.actual.values[i];
    const bool jumped =
        !m_actual || !m_toMachine || (toMachine.xyz() - m_toMachine->xyz()).norm() > 1e-6;
    m_actual = sample.actual;
    m_toMachine = toMachine;
    if (!m_stock) return;
    if (jumped) return m_stock->setStart(sample.actual);
    auto cut = [](const Pose& to, bool rapid) {
        canon::Command c;
        if (rapid) {
            c.body = canon::RapidMove{to};
        } else {
            c.body = canon::LinearMove{to, 1.0};  // any feed: the stock needs none
        }
        return c;
    };
    std::vector<canon::Command> cuts;
    const graphics::ToolpathData& path = *m_program->toolpath;
    for (size_t i = fromPoint; i < toPoint && i < path.pointCount(); ++i) {
        Pose to = sample.actual;
        to.setXyz(path.point(i));
        const std::optional<uint32_t> move = i > 0 ? path.moveOfSegment(i) : std::nullopt;
        cuts.push_back(cut(to, move && path.kinds[*move] == graphics::MoveKind::Rapid));
    }
    const size_t at = m_follower ? m_follower->point().command : 0;
    const bool rapid = at < m_program->commands.size() &&
                       std::holds_alternative<canon::RapidMove>(m_program->commands[at].body);
    cuts.push_back(cut(sample.actual, rapid));
    m_stock->push(std::move(cuts));
}

void TestRunController::endFollowing(bool completed) {
    if (!m_followingMachine) return;
    if (m_state == State::Interpreting) {
        m_endWhenReady = completed;
        return;
    }
    m_followingMachine = false;
    if (m_state != State::Following || !m_follower) return;
    if (completed) {
        m_follower->finish();
        m_timeS = m_program->machiningTimeS();
        pushUpTo(m_timeS);
    }
    m_stock->finish();
    emit progressChanged(m_timeS);
    publishStatus();
    setState(completed ? State::Finished : State::Stopped);
}

std::optional<TestRunController::Feed> TestRunController::followedFeed() const {
    if (!m_followingMachine || !m_follower || !m_follower->startPoint()) return std::nullopt;
    const size_t index = m_follower->point().command;
    if (index >= m_program->commands.size()) return std::nullopt;
    Feed feed;
    const canon::CommandBody& body = m_program->commands[index].body;
    if (const auto* line = std::get_if<canon::LinearMove>(&body)) feed.mm = line->feed;
    if (const auto* arc = std::get_if<canon::ArcMove>(&body)) feed.mm = arc->feed;
    if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) feed.mm = probe->feed;
    if (const auto* snapshot = m_program->statusOfCommand(index))
        feed.perRevolution = snapshot->status.motion.feedPerRevolution;
    return feed;
}

}  // namespace kerf::ui
