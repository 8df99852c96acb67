#include "drivers/can/socketcan_channel.h"

#include <cerrno>
#include <string>
#include <vector>

#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

#include "drivers/can/can_link_info.h"
#include "drivers/can/detail/socketcan_codec.h"

namespace kerf::drivers::can {

namespace {

std::error_code lastError() noexcept {
    return {errno, std::generic_category()};
}

}  // namespace

std::error_code probeSocketCan() noexcept {
    int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
    if (fd < 0) return lastError();
    ::close(fd);
    return {};
}

SocketCanChannel::~SocketCanChannel() {
    close();
}

std::error_code SocketCanChannel::open(std::string_view interface,
                                       std::span<const CanFilter> filters) {
    close();
    std::string name(interface);
    if (name.empty() || name.size() >= IFNAMSIZ)
        return std::make_error_code(std::errc::invalid_argument);
    int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
    if (fd < 0) return lastError();
    auto fail = [fd]() {
        std::error_code error = lastError();
        ::close(fd);
        return error;
    };
    unsigned index = ::if_nametoindex(name.c_str());
    if (index == 0) return fail();
    if (!filters.empty()) {
        std::vector<struct can_filter> kernel;
        kernel.reserve(filters.size());
        for (const CanFilter& f : filters)
            kernel.push_back(detail::toKernelFilter(f));
        if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_FILTER, kernel.data(),
                         static_cast<socklen_t>(kernel.size() * sizeof(struct can_filter))) != 0) {
            return fail();
        }
    }
    can_err_mask_t errors = CAN_ERR_CRTL | CAN_ERR_BUSOFF | CAN_ERR_RESTARTED;
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &errors, sizeof errors) != 0)
        return fail();
    int off = 0;
    if (::setsockopt(fd, SOL_CAN_RAW, CAN_RAW_RECV_OWN_MSGS, &off, sizeof off) != 0) return fail();
    struct sockaddr_can address {};
    address.can_family = AF_CAN;
    address.can_ifindex = static_cast<int>(index);
    if (::bind(fd, reinterpret_cast<const struct sockaddr*>(&address), sizeof address) != 0) {
        return fail();
    }
    m_fd = fd;
    // Virtual CAN (vcan) has no bit timing and no state: it counts as error active.
    CanLinkInfo link;
    m_state = readCanLinkInfo(interface, link) ? ControllerState::ErrorActive : link.state;
    return {};
}

void SocketCanChannel::close() noexcept {
    if (m_fd >= 0) ::close(m_fd);
    m_fd = -1;
    m_state = ControllerState::Stopped;
}

std::error_code SocketCanChannel::send(const CanFrame& frame) noexcept {
    if (m_fd < 0) return std::make_error_code(std::errc::not_connected);
    struct can_frame kernel = detail::toKernelFrame(frame);
    ssize_t written = ::write(m_fd, &kernel, sizeof kernel);
    if (written == static_cast<ssize_t>(sizeof kernel)) return {};
    if (written >= 0) return std::make_error_code(std::errc::io_error);
    if (errno == EAGAIN || errno == ENOBUFS)
        return std::make_error_code(std::errc::no_buffer_space);
    return lastError();
}

bool SocketCanChannel::receive(CanFrame& frame) noexcept {
    if (m_fd < 0) return false;
    for (;;) {
        struct can_frame kernel;
        ssize_t n = ::read(m_fd, &kernel, sizeof kernel);
        if (n != static_cast<ssize_t>(sizeof kernel)) return false;  // EAGAIN: nothing waiting
        if (detail::fromKernelFrame(kernel, frame)) return true;
        ++m_errorFrames;
        detail::ErrorFrameInfo info = detail::decodeErrorFrame(kernel, m_state);
        if (info.overflow) ++m_overflows;
        m_state = info.state;
    }
}

}  // namespace kerf::drivers::can
