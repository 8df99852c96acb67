#include "drivers/can/can_link_info.h"

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include <linux/can/netlink.h>
#include <linux/if_link.h>
#include <linux/netlink.h>
#include <linux/rtnetlink.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

#include "drivers/can/can_error.h"

namespace kerf::drivers::can {

namespace {

// Netlink attributes are 4-byte aligned {length, type, payload} records.
struct Attribute {
    uint16_t type = 0;
    std::span<const uint8_t> payload;
};

size_t align4(size_t n) noexcept {
    return (n + 3u) & ~size_t{3};
}

// Calls `visit` for each attribute in `data`; false on a malformed record.
template <typename Visit>
bool forEachAttribute(std::span<const uint8_t> data, Visit&& visit) noexcept {
    size_t pos = 0;
    while (pos + sizeof(struct rtattr) <= data.size()) {
        struct rtattr header;
        std::memcpy(&header, data.data() + pos, sizeof header);
        if (header.rta_len < sizeof header || pos + header.rta_len > data.size()) return false;
        visit(Attribute{static_cast<uint16_t>(header.rta_type & NLA_TYPE_MASK),
                        data.subspan(pos + sizeof header, header.rta_len - sizeof header)});
        pos += align4(header.rta_len);
    }
    return true;
}

ControllerState fromKernelState(uint32_t state) noexcept {
    switch (state) {
        case CAN_STATE_ERROR_ACTIVE:
            return ControllerState::ErrorActive;
        case CAN_STATE_ERROR_WARNING:
            return ControllerState::ErrorWarning;
        case CAN_STATE_ERROR_PASSIVE:
            return ControllerState::ErrorPassive;
        case CAN_STATE_BUS_OFF:
            return ControllerState::BusOff;
        default:
            return ControllerState::Stopped;
    }
}

}  // namespace

std::error_code parseCanLinkMessage(std::span<const uint8_t> message, CanLinkInfo& out) noexcept {
    struct nlmsghdr header;
    if (message.size() < sizeof header) return CanErrc::MalformedReply;
    std::memcpy(&header, message.data(), sizeof header);
    if (header.nlmsg_len > message.size() || header.nlmsg_len < sizeof header) {
        return CanErrc::MalformedReply;
    }
    if (header.nlmsg_type == NLMSG_ERROR) {
        struct nlmsgerr error;
        if (header.nlmsg_len < NLMSG_LENGTH(sizeof error)) return CanErrc::MalformedReply;
        std::memcpy(&error, message.data() + NLMSG_HDRLEN, sizeof error);
        return {-error.error, std::generic_category()};
    }
    if (header.nlmsg_type != RTM_NEWLINK) return CanErrc::MalformedReply;
    size_t attributes = NLMSG_HDRLEN + NLMSG_ALIGN(sizeof(struct ifinfomsg));
    if (header.nlmsg_len < attributes) return CanErrc::MalformedReply;
    bool isCan = false;
    bool haveState = false;
    CanLinkInfo info;
    auto visitData = [&](const Attribute& a) {
        if (a.type == IFLA_CAN_BITTIMING && a.payload.size() >= sizeof(struct can_bittiming)) {
            struct can_bittiming timing;
            std::memcpy(&timing, a.payload.data(), sizeof timing);
            info.bitrate = timing.bitrate;
        } else if (a.type == IFLA_CAN_STATE && a.payload.size() >= sizeof(uint32_t)) {
            uint32_t state = 0;
            std::memcpy(&state, a.payload.data(), sizeof state);
            info.state = fromKernelState(state);
            haveState = true;
        }
    };
    bool wellFormed = true;
    auto visitLinkInfo = [&](const Attribute& a) {
        if (a.type == IFLA_INFO_KIND) {
            std::string_view kind(reinterpret_cast<const char*>(a.payload.data()),
                                  a.payload.size());
            while (!kind.empty() && kind.back() == '\0')
                kind.remove_suffix(1);
            isCan = kind == "can";
        } else if (a.type == IFLA_INFO_DATA) {
            wellFormed = wellFormed && forEachAttribute(a.payload, visitData);
        }
    };
    auto visitLink = [&](const Attribute& a) {
        if (a.type == IFLA_LINKINFO)
            wellFormed = wellFormed && forEachAttribute(a.payload, visitLinkInfo);
    };
    if (!forEachAttribute(message.subspan(attributes, header.nlmsg_len - attributes), visitLink) ||
        !wellFormed) {
        return CanErrc::MalformedReply;
    }
    if (!isCan) return CanErrc::NotCanInterface;
    if (!haveState) info.state = ControllerState::ErrorActive;
    out = info;
    return {};
}

std::error_code readCanLinkInfo(std::string_view interface, CanLinkInfo& out) {
    std::string name(interface);
    unsigned index = ::if_nametoindex(name.c_str());
    if (index == 0) return std::make_error_code(std::errc::no_such_device);
    int fd = ::socket(AF_NETLINK, SOCK_RAW | SOCK_CLOEXEC, NETLINK_ROUTE);
    if (fd < 0) return {errno, std::generic_category()};
    struct {
        struct nlmsghdr header;
        struct ifinfomsg link;
    } request{};
    request.header.nlmsg_len = NLMSG_LENGTH(sizeof(struct ifinfomsg));
    request.header.nlmsg_type = RTM_GETLINK;
    request.header.nlmsg_flags = NLM_F_REQUEST;
    request.header.nlmsg_seq = 1;
    request.link.ifi_family = AF_UNSPEC;
    request.link.ifi_index = static_cast<int>(index);
    std::error_code result;
    if (::send(fd, &request, request.header.nlmsg_len, 0) < 0) {
        result = {errno, std::generic_category()};
    } else {
        std::vector<uint8_t> reply(32768);
        ssize_t n = ::recv(fd, reply.data(), reply.size(), 0);
        if (n < 0) {
            result = {errno, std::generic_category()};
        } else {
            result = parseCanLinkMessage({reply.data(), static_cast<size_t>(n)}, out);
        }
    }
    ::close(fd);
    return result;
}

}  // namespace kerf::drivers::can
