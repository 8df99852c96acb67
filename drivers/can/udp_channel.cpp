#include "drivers/can/udp_channel.h"

#include <cerrno>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include "drivers/can/cannelloni_codec.h"

namespace kerf::drivers::can {

namespace {

struct sockaddr_in loopback(uint16_t port) noexcept {
    struct sockaddr_in address {};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return address;
}

}  // namespace

UdpChannel::~UdpChannel() {
    close();
}

std::error_code UdpChannel::open(uint16_t localPort, std::span<const uint16_t> peerPorts) {
    close();
    int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd < 0) return {errno, std::generic_category()};
    struct sockaddr_in address = loopback(localPort);
    socklen_t size = sizeof address;
    if (::bind(fd, reinterpret_cast<const struct sockaddr*>(&address), size) != 0 ||
        ::getsockname(fd, reinterpret_cast<struct sockaddr*>(&address), &size) != 0) {
        std::error_code error{errno, std::generic_category()};
        ::close(fd);
        return error;
    }
    m_fd = fd;
    m_port = ntohs(address.sin_port);
    m_peerCount = 0;
    for (uint16_t peer : peerPorts)
        addPeer(peer);
    return {};
}

void UdpChannel::close() noexcept {
    if (m_fd >= 0) ::close(m_fd);
    m_fd = -1;
    m_port = 0;
    m_received.clear();
}

void UdpChannel::addPeer(uint16_t port) noexcept {
    if (port == m_port) return;
    for (size_t i = 0; i < m_peerCount; ++i) {
        if (m_peers[i] == port) return;
    }
    if (m_peerCount < kMaxPeers) m_peers[m_peerCount++] = port;
}

ControllerState UdpChannel::state() const noexcept {
    return m_fd >= 0 ? ControllerState::ErrorActive : ControllerState::Stopped;
}

std::error_code UdpChannel::send(const CanFrame& frame) noexcept {
    if (m_fd < 0) return std::make_error_code(std::errc::not_connected);
    std::array<uint8_t, kCannelloniHeaderSize + kCannelloniMaxFrameSize> datagram{};
    size_t size = encodeCannelloni(frame, m_sequence++, datagram);
    std::error_code result;
    for (size_t i = 0; i < m_peerCount; ++i) {
        struct sockaddr_in peer = loopback(m_peers[i]);
        if (::sendto(m_fd, datagram.data(), size, 0,
                     reinterpret_cast<const struct sockaddr*>(&peer), sizeof peer) < 0) {
            // A peer that is not (yet) listening refuses; the frame is lost for it, as on a bus.
            if (errno == EAGAIN || errno == ENOBUFS) {
                result = std::make_error_code(std::errc::no_buffer_space);
            }
        }
    }
    return result;
}

void UdpChannel::readDatagrams() noexcept {
    std::array<uint8_t, 1500> datagram{};
    std::array<CanFrame, 16> frames{};
    // Bounded: at most 64 datagrams per call, so an error that repeats cannot spin.
    for (int guard = 0; guard < 64 && m_received.size() + frames.size() <= m_received.capacity();
         ++guard) {
        struct sockaddr_in from {};
        socklen_t size = sizeof from;
        ssize_t n = ::recvfrom(m_fd, datagram.data(), datagram.size(), 0,
                               reinterpret_cast<struct sockaddr*>(&from), &size);
        if (n < 0) {
            if (errno == EAGAIN || errno == EWOULDBLOCK) return;
            continue;  // ECONNREFUSED from an earlier send to a peer that was gone
        }
        int count = decodeCannelloni({datagram.data(), static_cast<size_t>(n)}, frames);
        if (count < 0) continue;  // not cannelloni v2: ignored like noise
        addPeer(ntohs(from.sin_port));
        for (int i = 0; i < count; ++i)
            m_received.push(frames[static_cast<size_t>(i)]);
    }
}

bool UdpChannel::receive(CanFrame& frame) noexcept {
    if (m_fd < 0) return false;
    if (m_received.empty()) readDatagrams();
    if (m_received.empty()) return false;
    frame = m_received.front();
    m_received.pop();
    return true;
}

}  // namespace kerf::drivers::can
