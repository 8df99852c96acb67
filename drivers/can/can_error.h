#pragma once

#include <system_error>

// Errors of the CAN back-ends that have no errno of their own.
namespace kerf::drivers::can {

enum class CanErrc {
    NotCanInterface = 1,  // the network interface exists but is no CAN controller
    MalformedReply,       // a netlink reply that cannot be parsed
    BitrateMismatch,      // the interface runs at another bit rate than the configuration's
};

const std::error_category& canCategory() noexcept;
std::error_code make_error_code(CanErrc e) noexcept;

}  // namespace kerf::drivers::can

template <>
struct std::is_error_code_enum<kerf::drivers::can::CanErrc> : std::true_type {};
