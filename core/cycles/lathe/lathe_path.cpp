#include "core/cycles/lathe/lathe_path.h"

#include "core/base/translate.h"

namespace kerf::cycles::lathe {

namespace {
constexpr double kSame = 1e-9;
}

void LathePath::move(LatheStep::Kind kind, const Vec2& to, double feed) {
    if ((to - m_at).norm() < kSame || full()) return;
    LatheStep step;
    step.kind = kind;
    step.to = to;
    step.feed = feed;
    m_steps.push_back(step);
    m_at = to;
}

void LathePath::arc(const Vec2& to, const Vec2& centre, bool ccw, double feed) {
    if ((to - m_at).norm() < kSame || full()) return;
    LatheStep step;
    step.kind = LatheStep::Kind::FeedArc;
    step.to = to;
    step.centre = centre;
    step.ccw = ccw;
    step.feed = feed;
    m_steps.push_back(step);
    m_at = to;
}

void LathePath::thread(const Vec2& to, double lead, double angleDeg, double leadChange) {
    if ((to - m_at).norm() < kSame || full()) return;
    LatheStep step;
    step.kind = LatheStep::Kind::Thread;
    step.to = to;
    step.lead = lead;
    step.leadChange = leadChange;
    step.angleDeg = angleDeg;
    m_steps.push_back(step);
    m_at = to;
}

void LathePath::dwell(double seconds) {
    if (seconds <= 0.0 || full()) return;
    LatheStep step;
    step.kind = LatheStep::Kind::Dwell;
    step.seconds = seconds;
    step.to = m_at;
    m_steps.push_back(step);
}

void LathePath::command(LatheStep::Kind kind, double angleDeg) {
    if (full()) return;
    LatheStep step;
    step.kind = kind;
    step.angleDeg = angleDeg;
    step.to = m_at;
    m_steps.push_back(step);
}

LatheError tooManySteps(char letter) {
    return {letter,
            "cycle-size",
            KERF_TR_NOOP("the cycle would need more than {1} moves: {2} is too small"),
            {std::to_string(LathePath::kStepLimit), std::string(1, letter)}};
}

}  // namespace kerf::cycles::lathe
