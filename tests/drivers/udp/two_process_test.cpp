// Master and drives in two processes over the UDP bus: this test is the master (the real
// CanDriveStack over a UdpChannel, on the wall clock) and kerf-drive-sim serves the mill's four
// drives. It boots, enables, moves X and checks the feedback; the timing of a shared machine is
// only reported, with limits loose enough for a loaded CI host.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include "core/machine/machine_loader.h"
#include "drivers/can/udp_channel.h"
#include "drivers/setup/can_drive_stack.h"
#include "motion/port/motion_status.h"

extern char** environ;

namespace kerf::drivers {
namespace {

using Clock = std::chrono::steady_clock;

class DriveSimProcess {
public:
    explicit DriveSimProcess(uint16_t masterPort) {
        std::string peer = std::to_string(masterPort);
        std::vector<std::string> args{KERF_DRIVE_SIM, "--machine", "mill", "--peer",
                                      peer,           "--seconds", "30"};
        std::vector<char*> argv;
        for (std::string& a : args)
            argv.push_back(a.data());
        argv.push_back(nullptr);
        m_error = posix_spawn(&m_pid, KERF_DRIVE_SIM, nullptr, nullptr, argv.data(), environ);
    }
    ~DriveSimProcess() {
        if (m_pid > 0 && !m_waited) {
            kill(m_pid, SIGKILL);
            waitpid(m_pid, nullptr, 0);
        }
    }
    bool started() const { return m_error == 0; }
    // SIGTERM and the exit status (0 for a clean stop).
    int stop() {
        kill(m_pid, SIGTERM);
        int status = 0;
        waitpid(m_pid, &status, 0);
        m_waited = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

private:
    pid_t m_pid = -1;
    int m_error = 0;
    bool m_waited = false;
};

TEST(TwoProcesses, MasterDrivesTheSimulatorOverUdp) {
    machine::MachineConfig config = machine::loadMachine("mill").value();
    config.servoPeriodMs = 5.0;  // a soft real-time loop on a shared host
    config.drives.cyclePeriodMs = 10.0;
    config.drives.heartbeatTimeoutMs = 2000;
    config.drives.pdoLossCycles = 50;
    CanBusConfig bus = makeCanBusConfig(config).value();
    bus.sdoTimeout = std::chrono::seconds(2);  // a loaded host may not run the simulator for 200 ms

    can::UdpChannel channel;
    ASSERT_FALSE(channel.open(0));
    DriveSimProcess sim(channel.localPort());
    ASSERT_TRUE(sim.started()) << "cannot start " << KERF_DRIVE_SIM;
    // The simulator's power-on boot-up messages tell the channel where the drives are.
    Clock::time_point deadline = Clock::now() + std::chrono::seconds(10);
    while (channel.peerCount() == 0 && Clock::now() < deadline) {
        can::CanFrame f;
        while (channel.receive(f)) {
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_EQ(channel.peerCount(), 1u) << "no frame from kerf-drive-sim";

    CanDriveStack stack(bus, channel);
    motion::DriveBus& drives = stack.bus();
    auto joints = static_cast<size_t>(drives.jointCount());
    std::array<motion::JointFeedback, motion::kMaxJoints> feedback{};
    std::array<motion::JointSetpoint, motion::kMaxJoints> setpoints{};
    Clock::time_point start = Clock::now();
    auto elapsed = [&start] {
        return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start);
    };
    std::vector<double> lateMs;
    auto period = std::chrono::milliseconds(5);
    Clock::time_point next = start;
    auto cycle = [&] {
        stack.clock().set(elapsed());
        drives.read({feedback.data(), joints});
        drives.write({setpoints.data(), joints});
        next += period;
        std::this_thread::sleep_until(next);
        lateMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - next).count());
    };
    stack.clock().set(elapsed());
    stack.start();
    drives.request(motion::DriveRequest::Enable);
    bool enabled = false;
    while (!enabled && elapsed() < std::chrono::seconds(10) && !stack.adapter().stopped()) {
        cycle();
        for (size_t j = 0; j < joints; ++j)
            setpoints[j].position = feedback[j].position;
        enabled = stack.adapter().allEnabled();
    }
    ASSERT_TRUE(enabled) << (stack.diagnostics().empty() ? "timeout"
                                                         : stack.diagnostics()[0].message());
    double x0 = feedback[0].position;
    for (int k = 1; k <= 200; ++k) {  // 2 mm in 1 s
        setpoints[0].position = x0 + 1.0 - std::cos(M_PI * k / 200.0);
        cycle();
    }
    for (int k = 0; k < 100; ++k)
        cycle();
    EXPECT_NEAR(feedback[0].position, x0 + 2.0, 1e-3);
    EXPECT_FALSE(stack.adapter().stopped())
        << (stack.diagnostics().empty() ? "" : stack.diagnostics()[0].message());
    EXPECT_EQ(sim.stop(), 0);

    std::sort(lateMs.begin(), lateMs.end());
    RecordProperty("cycle_late_p50_ms", std::to_string(lateMs[lateMs.size() / 2]));
    RecordProperty("cycle_late_max_ms", std::to_string(lateMs.back()));
    std::printf(
        "5 ms master loop over UDP: wake-up lateness median %.3f ms, p99 %.3f ms, max %.3f ms\n",
        lateMs[lateMs.size() / 2], lateMs[lateMs.size() * 99 / 100], lateMs.back());
}

}  // namespace
}  // namespace kerf::drivers
