#include "drivers/can/can_error.h"

#include <string>

namespace kerf::drivers::can {

namespace {

class CanCategory final : public std::error_category {
public:
    const char* name() const noexcept override { return "can"; }
    std::string message(int code) const override {
        switch (static_cast<CanErrc>(code)) {
            case CanErrc::NotCanInterface:
                return "not a CAN interface";
            case CanErrc::MalformedReply:
                return "malformed netlink reply";
            case CanErrc::BitrateMismatch:
                return "interface bit rate differs from drives.bitrate";
        }
        return "unknown CAN error " + std::to_string(code);
    }
};

}  // namespace

const std::error_category& canCategory() noexcept {
    static const CanCategory category;
    return category;
}

std::error_code make_error_code(CanErrc e) noexcept {
    return {static_cast<int>(e), canCategory()};
}

}  // namespace kerf::drivers::can
