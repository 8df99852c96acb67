#pragma once

#include "core/task/motion_port.h"

namespace kerf::task {

// A MotionPort that "executes" every command at once by handing it to a sink: the test run of
// the programming station (graphics, machining time) and tests of the sequencer. It never holds.
class InstantMotion final : public MotionPort {
public:
    explicit InstantMotion(canon::Sink& sink) : m_sink(sink) {}

    bool submit(const canon::Command& command) override;
    bool hasRoom() const override { return true; }
    void flush() override {}
    void pump() override {}
    bool drained() const override { return true; }
    interp::WorldSnapshot world() const override;
    Progress progress() const override { return {State::Idle, m_block, {}}; }
    void cycleStart() override {}
    void feedHold() override {}
    void quickStop() override {}
    void setSingleBlock(bool) override {}

    void setPosition(const Pose& position) { m_position = position; }

private:
    canon::Sink& m_sink;
    Pose m_position{};
    SourceLocation m_block;
};

}  // namespace kerf::task
