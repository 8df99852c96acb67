#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <system_error>

#include "drivers/can/can_channel.h"
#include "drivers/can/fixed_queue.h"

// A CAN bus between processes on one host: every sent frame goes as one cannelloni v2 datagram to
// each peer on the loopback interface. Peers are given at open() or learned from the first
// datagram a new sender sends, so a drive simulator only needs to know the master's port. No bit
// timing and no arbitration: frames arrive in the order the kernel delivers them. open()/close()
// in a normal thread; send/receive/state in the cycle's thread (non-blocking, no allocation).
namespace kerf::drivers::can {

class UdpChannel final : public CanChannel {
public:
    static constexpr size_t kMaxPeers = 8;

    UdpChannel() = default;
    ~UdpChannel() override;
    UdpChannel(const UdpChannel&) = delete;
    UdpChannel& operator=(const UdpChannel&) = delete;

    // Binds 127.0.0.1:localPort (0: any free port, see localPort()).
    std::error_code open(uint16_t localPort, std::span<const uint16_t> peerPorts = {});
    void close() noexcept;
    uint16_t localPort() const noexcept { return m_port; }
    size_t peerCount() const noexcept { return m_peerCount; }

    std::error_code send(const CanFrame& frame) noexcept override;
    bool receive(CanFrame& frame) noexcept override;
    ControllerState state() const noexcept override;

private:
    void addPeer(uint16_t port) noexcept;
    void readDatagrams() noexcept;

    int m_fd = -1;
    uint16_t m_port = 0;
    std::array<uint16_t, kMaxPeers> m_peers{};
    size_t m_peerCount = 0;
    uint8_t m_sequence = 0;
    FixedQueue<CanFrame, 64> m_received;
};

}  // namespace kerf::drivers::can
