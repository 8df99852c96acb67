#include "core/task/program_run.h"

#include <gtest/gtest.h>

#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::task {
namespace {

// A motion stand-in with a bounded queue that executes one command per pump() and can be told
// to hold, stop or fault.
class FakeMotion final : public MotionPort {
public:
    bool submit(const canon::Command& command) override {
        if (refuse) return false;
        queue.push_back(command);
        return true;
    }
    bool hasRoom() const override { return queue.size() < capacity; }
    void flush() override { ++flushes; }
    void pump() override {
        if (state != State::Idle && state != State::Running) return;
        if (queue.empty()) {
            state = State::Idle;
            return;
        }
        state = State::Running;
        const canon::Command c = queue.front();
        queue.erase(queue.begin());
        block = c.location;
        if (const auto* r = std::get_if<canon::RapidMove>(&c.body)) position = r->target;
        if (const auto* l = std::get_if<canon::LinearMove>(&c.body)) position = l->target;
        if (const auto* stop = std::get_if<canon::ProgramStop>(&c.body);
            stop && stop->kind != canon::StopKind::End) {
            state = State::Stopped;
        }
        if (std::holds_alternative<canon::SyncPoint>(c.body)) position[Axis::X] += jogAtSync;
        executed.push_back(c);
    }
    bool drained() const override { return queue.empty() && state != State::Stopped; }
    interp::WorldSnapshot world() const override {
        interp::WorldSnapshot w;
        w.position = position;
        return w;
    }
    Progress progress() const override { return {state, block, fault}; }
    void cycleStart() override {
        if (state == State::Held || state == State::Stopped) state = State::Running;
    }
    void feedHold() override { state = State::Held; }
    void quickStop() override {
        queue.clear();
        state = State::Idle;
    }
    void setSingleBlock(bool) override {}

    std::vector<canon::Command> queue;
    std::vector<canon::Command> executed;
    size_t capacity = 4;
    State state = State::Idle;
    SourceLocation block;
    Pose position{};
    std::string fault;
    bool refuse = false;
    int flushes = 0;
    double jogAtSync = 0.0;  // the operator moves X by this much while the machine waits
};

class ProgramRunTest : public testing::Test {
protected:
    std::unique_ptr<interp::Interpreter> load(const std::string& text) {
        klartext::KlartextSettings settings;
        settings.machine = &mill;
        auto k = std::make_unique<klartext::KlartextInterpreter>(sources, settings);
        EXPECT_TRUE(k->loadText(text, "P.H"));
        return k;
    }
    void serviceUntilDone(ProgramRun& run, int limit = 1000) {
        for (int i = 0; i < limit && run.state() != RunState::Finished &&
                        run.state() != RunState::Failed && run.state() != RunState::Stopped;
             ++i) {
            run.service();
        }
    }
    std::vector<double> xs(const FakeMotion& m) {
        std::vector<double> out;
        for (const auto& c : m.executed) {
            if (const auto* r = std::get_if<canon::RapidMove>(&c.body))
                out.push_back(r->target[Axis::X]);
            if (const auto* l = std::get_if<canon::LinearMove>(&c.body))
                out.push_back(l->target[Axis::X]);
        }
        return out;
    }

    machine::MachineConfig mill = *machine::loadMachine("mill");
    program::SourceRegistry sources;
    FakeMotion motion;
};

TEST_F(ProgramRunTest, RunsToTheEndThroughABoundedQueue) {
    ProgramRun run(motion);
    std::string program = "0 BEGIN PGM A MM\n";
    for (int i = 1; i <= 20; ++i)
        program += std::to_string(i) + " L X+" + std::to_string(i) + " Y+0 Z+0 R0 FMAX\n";
    program += "21 END PGM A MM\n";
    run.start(load(program));
    serviceUntilDone(run);
    EXPECT_EQ(run.state(), RunState::Finished);
    ASSERT_EQ(xs(motion).size(), 20u);
    EXPECT_DOUBLE_EQ(xs(motion).back(), 20);
}

TEST_F(ProgramRunTest, SyncReadsTheMachineAfterMotionDrained) {
    // The machine stands 0.25 mm further than programmed when the program reads it.
    ProgramRun run(motion);
    motion.jogAtSync = 0.25;
    run.start(
        load("0 BEGIN PGM A MM\n1 L X+10 Y+0 Z+0 R0 FMAX\n"
             "2 FN 18: SYSREAD Q1 = ID270 NR1 IDX1\n3 L X+Q1 Y+1 FMAX\n4 END PGM A MM\n"));
    serviceUntilDone(run);
    EXPECT_EQ(run.state(), RunState::Finished);
    EXPECT_DOUBLE_EQ(xs(motion).back(), 10.25);
}

TEST_F(ProgramRunTest, StopsAtM0AndContinuesOnCycleStart) {
    ProgramRun run(motion);
    run.start(
        load("0 BEGIN PGM A MM\n1 L X+1 Y+0 Z+0 R0 FMAX\n2 STOP\n3 L X+2 FMAX\n4 END PGM A MM\n"));
    serviceUntilDone(run);
    EXPECT_EQ(run.state(), RunState::Stopped);
    EXPECT_DOUBLE_EQ(xs(motion).back(), 1);
    run.cycleStart();
    serviceUntilDone(run);
    EXPECT_EQ(run.state(), RunState::Finished);
    EXPECT_DOUBLE_EQ(xs(motion).back(), 2);
}

TEST_F(ProgramRunTest, ASyncBehindAStopReadsWhereTheOperatorJoggedTheAxes) {
    // As 1416's semi-automatic mode: a stop, then a sync. Motion is not drained while stopped,
    // so the sync waits for NC start and reads the axes where the operator jogged them.
    ProgramRun run(motion);
    run.start(
        load("0 BEGIN PGM A MM\n1 L X+10 Y+0 Z+0 R0 FMAX\n2 STOP\n"
             "3 FN 18: SYSREAD Q1 = ID270 NR1 IDX1\n4 L X+Q1 Y+1 FMAX\n5 END PGM A MM\n"));
    serviceUntilDone(run);
    ASSERT_EQ(run.state(), RunState::Stopped);
    motion.position[Axis::X] = 13.0;
    run.service();
    run.cycleStart();
    serviceUntilDone(run);
    EXPECT_EQ(run.state(), RunState::Finished);
    EXPECT_DOUBLE_EQ(xs(motion).back(), 13.0);
}

TEST_F(ProgramRunTest, FeedHoldAndFaults) {
    ProgramRun run(motion);
    run.start(
        load("0 BEGIN PGM A MM\n1 L X+1 Y+0 Z+0 R0 FMAX\n2 L X+2 FMAX\n3 L X+3 FMAX\n"
             "4 END PGM A MM\n"));
    run.service();
    run.feedHold();
    EXPECT_EQ(run.state(), RunState::Held);
    run.service();
    EXPECT_EQ(run.state(), RunState::Held);
    motion.state = MotionPort::State::Faulted;
    motion.fault = "node 3: heartbeat lost";
    run.service();
    ASSERT_EQ(run.state(), RunState::Failed);
    EXPECT_EQ(run.diagnostics().back().message(), "motion stopped: node 3: heartbeat lost");
}

TEST_F(ProgramRunTest, AnErrorStopsAfterTheBlocksBeforeIt) {
    ProgramRun run(motion);
    run.start(
        load("0 BEGIN PGM A MM\n1 L X+1 Y+0 Z+0 R0 FMAX\n2 Q1 = 1 / Q2\n3 L X+2 FMAX\n"
             "4 END PGM A MM\n"));
    serviceUntilDone(run);
    ASSERT_EQ(run.state(), RunState::Failed);
    EXPECT_EQ(xs(motion), std::vector<double>{1});
    EXPECT_EQ(run.diagnostics().back().line, 3u);
}

TEST_F(ProgramRunTest, MidProgramStartRestoresToolSpindleAndPosition) {
    ProgramRun run(motion);
    motion.position[Axis::Z] = 100;  // the machine stands high above the part
    StartOptions options;
    options.startLine = 6;  // block 5: L X+30
    run.start(load("0 BEGIN PGM A MM\n1 TOOL CALL 1 Z S1000\n2 L X+10 Y+5 Z+2 R0 FMAX M3\n"
                   "3 L Z-1 F100\n4 L X+20\n5 L X+30\n6 END PGM A MM\n"),
              options);
    serviceUntilDone(run);
    EXPECT_EQ(run.state(), RunState::Finished);
    // Restored: tool, spindle on, then above (20,5) at Z100 and down to Z-1, then block 5.
    ASSERT_GE(motion.executed.size(), 5u);
    EXPECT_TRUE(std::holds_alternative<canon::ToolChange>(motion.executed[0].body));
    EXPECT_TRUE(std::holds_alternative<canon::SpindleControl>(motion.executed[1].body));
    const auto& over = std::get<canon::RapidMove>(motion.executed[2].body).target;
    EXPECT_DOUBLE_EQ(over[Axis::X], 20);
    EXPECT_DOUBLE_EQ(over[Axis::Z], 100);
    const auto& down = std::get<canon::RapidMove>(motion.executed[3].body).target;
    EXPECT_DOUBLE_EQ(down[Axis::Z], -1);
    EXPECT_DOUBLE_EQ(std::get<canon::LinearMove>(motion.executed[4].body).target[Axis::X], 30);
}

TEST_F(ProgramRunTest, RefusedBlocksAndAbort) {
    ProgramRun run(motion);
    run.start(load("0 BEGIN PGM A MM\n1 L X+1 Y+0 Z+0 R0 FMAX\n2 END PGM A MM\n"));
    motion.refuse = true;
    motion.fault = "X+1 beyond the soft limit";
    run.service();
    EXPECT_EQ(run.state(), RunState::Failed);
    // The message points at the refused block (line 2), not at what motion executes.
    ASSERT_FALSE(run.diagnostics().empty());
    EXPECT_EQ(run.diagnostics().back().line, 2u);
    ProgramRun second(motion);
    motion.refuse = false;
    second.start(load("0 BEGIN PGM A MM\n1 L X+1 Y+0 Z+0 R0 FMAX\n2 END PGM A MM\n"));
    second.abort();
    EXPECT_EQ(second.state(), RunState::Aborted);
}

}  // namespace
}  // namespace kerf::task
