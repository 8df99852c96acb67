#include "motion/runtime/realtime_machine.h"

#include <cerrno>
#include <cstring>

#include <pthread.h>
#include <sys/mman.h>
#include <time.h>

#include "motion/sim/probe_workpiece.h"

namespace kerf::motion {

namespace {

int64_t nanos(const timespec& t) {
    return static_cast<int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec;
}

timespec fromNanos(int64_t ns) {
    timespec t;
    t.tv_sec = static_cast<time_t>(ns / 1000000000);
    t.tv_nsec = static_cast<long>(ns % 1000000000);
    return t;
}

}  // namespace

RealtimeMachine::RealtimeMachine(const machine::MachineConfig& config, RealtimeOptions options,
                                 DriveBus* bus)
    : m_model(makeMachineModel(config, options.motion)),
      m_options(options),
      m_simDrives(bus ? nullptr : std::make_unique<SimDriveSet>(m_model, options.drives)),
      m_bus(bus ? *bus : *m_simDrives),
      m_items(std::make_unique<ItemRing>()),
      m_servo(m_model, m_bus, *m_items, m_commands, m_events),
      m_planner(m_model) {
    if (m_simDrives) {
        std::array<double, kMaxJoints> joints{};
        for (int j = 0; j < m_model.jointCount; ++j) {
            int axis = m_model.jointAxis[static_cast<size_t>(j)];
            if (axis >= 0) {
                joints[static_cast<size_t>(j)] = jointFromAxis(
                    m_model, axis, options.startPosition[static_cast<size_t>(axis)], 0.0);
            }
        }
        m_simDrives->setTruePositions(joints);
        if (!m_options.probeSurface)
            m_options.probeSurface = probeWorkpiece(config, options.motion.workOffset);
        // Called in the servo thread: the surface tests and tipOf() do not allocate. The
        // surface the current probe move carries, else the machine file's box.
        m_simDrives->setProbeSurface([this](const std::array<double, kMaxJoints>& j) {
            const AxisVector tip = tipOf(j);
            if (const canon::ProbeSurface* target = m_probeTarget.load(std::memory_order_acquire))
                return target->touches(Vec3(tip[0], tip[1], tip[2]));
            return m_options.probeSurface && m_options.probeSurface(tip);
        });
    }
    m_planner.setPosition(options.startPosition);
}

AxisVector RealtimeMachine::tipOf(const std::array<double, kMaxJoints>& joints) const {
    const double toolLength = m_toolLength.load(std::memory_order_relaxed);
    AxisVector tip{};
    for (int j = 0; j < m_model.jointCount; ++j) {
        const int axis = m_model.jointAxis[static_cast<size_t>(j)];
        if (axis >= 0) {
            tip[static_cast<size_t>(axis)] =
                axisFromJoint(m_model, axis, joints[static_cast<size_t>(j)], toolLength);
        }
    }
    return tip;
}

RealtimeMachine::~RealtimeMachine() {
    stop();
}

bool RealtimeMachine::start() {
    if (m_running) return true;
    m_servo.start();
    m_status.write(m_servo.status());
    if (m_options.lockMemory) {
        if (mlockall(MCL_CURRENT | MCL_FUTURE) == 0) {
            m_locked = true;
        } else {
            m_note += std::string("memory not locked: ") + std::strerror(errno) + "; ";
        }
    }
    m_stop = false;
    m_thread = std::thread([this] { run(); });
    sched_param param{};
    param.sched_priority = m_options.priority;
    int error = pthread_setschedparam(m_thread.native_handle(), SCHED_FIFO, &param);
    if (error == 0) {
        m_priority = true;
    } else {
        m_note += std::string("no SCHED_FIFO: ") + std::strerror(error) + "; ";
    }
    m_running = true;
    return true;
}

void RealtimeMachine::stop() {
    if (!m_running) return;
    m_stop = true;
    m_thread.join();
    m_running = false;
}

RealtimeReport RealtimeMachine::report() const {
    return {m_running.load(), m_priority.load(), m_locked.load(), m_note};
}

void RealtimeMachine::run() {
    const int64_t period = static_cast<int64_t>(m_model.periodS * 1e9);
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    int64_t deadline = nanos(now) + period;
    while (!m_stop.load(std::memory_order_relaxed)) {
        timespec wake = fromNanos(deadline);
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &wake, nullptr);
        timespec start{};
        clock_gettime(CLOCK_MONOTONIC, &start);
        bool late = nanos(start) - deadline > period;
        m_servo.cycle();
        if (m_simDrives) m_simDrives->advance(m_model.periodS);
        timespec end{};
        clock_gettime(CLOCK_MONOTONIC, &end);
        m_servo.noteTiming(late, static_cast<double>(nanos(end) - nanos(start)) * 1e-9);
        m_status.write(m_servo.status());
        deadline += period;
        // After a long stall, skip the missed periods instead of running them back to back.
        if (nanos(end) - deadline > 10 * period) deadline = nanos(end) + period;
    }
}

bool RealtimeMachine::submit(const canon::Command& command) {
    const auto* probe = std::get_if<canon::ProbeMove>(&command.body);
    if (probe != nullptr && probe->surface != m_probeTargetOwner) {
        // An interpreter waits for a probe move's result before it sends the next one, so the
        // servo thread no longer tests the surface replaced here; it stays alive one more
        // probe move all the same.
        m_retiredProbeTarget = std::move(m_probeTargetOwner);
        m_probeTargetOwner = probe->surface;
        m_probeTarget.store(m_probeTargetOwner.get(), std::memory_order_release);
    }
    bool accepted = m_planner.add(command);
    m_toolLength.store(m_planner.toolLength(), std::memory_order_relaxed);
    pump();
    return accepted;
}

void RealtimeMachine::flush() {
    m_planner.flush();
    pump();
}

void RealtimeMachine::pump() {
    for (;;) {
        if (!m_backlog) m_backlog = m_planner.next();
        if (!m_backlog || !m_items->push(*m_backlog)) return;
        m_backlog.reset();
    }
}

bool RealtimeMachine::drained() const {
    MotionStatus s = m_status.read();
    return !m_backlog && m_items->empty() && s.mode == MotionMode::Idle &&
           m_planner.pendingLength() == 0.0;
}

bool RealtimeMachine::setEmergencyStopButton(bool pressed) {
    if (!m_simDrives) return false;
    m_simDrives->setEmergencyStopPressed(pressed);
    return true;
}

bool RealtimeMachine::command(const OperatorCommand& command) {
    return m_commands.push(command);
}

std::optional<MotionEvent> RealtimeMachine::nextEvent() {
    if (m_events.empty()) return std::nullopt;
    MotionEvent event = m_events.front();
    m_events.pop();
    return event;
}

}  // namespace kerf::motion
