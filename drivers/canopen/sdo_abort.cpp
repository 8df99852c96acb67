#include "drivers/canopen/sdo_abort.h"

#include <cstdio>
#include <string>

namespace kerf::drivers::canopen {

namespace {

const char* abortText(uint32_t code) noexcept {
    switch (static_cast<SdoAbort>(code)) {
        case SdoAbort::ToggleBit:
            return "toggle bit not alternated";
        case SdoAbort::Timeout:
            return "SDO protocol timed out";
        case SdoAbort::UnknownCommand:
            return "client/server command specifier not valid or unknown";
        case SdoAbort::OutOfMemory:
            return "out of memory";
        case SdoAbort::UnsupportedAccess:
            return "unsupported access to an object";
        case SdoAbort::ReadOfWriteOnly:
            return "attempt to read a write only object";
        case SdoAbort::WriteOfReadOnly:
            return "attempt to write a read only object";
        case SdoAbort::NoObject:
            return "object does not exist in the object dictionary";
        case SdoAbort::NotMappable:
            return "object cannot be mapped to the PDO";
        case SdoAbort::MappingTooLong:
            return "the number and length of the objects to be mapped would exceed PDO length";
        case SdoAbort::ParameterIncompatible:
            return "general parameter incompatibility reason";
        case SdoAbort::DeviceIncompatible:
            return "general internal incompatibility in the device";
        case SdoAbort::HardwareError:
            return "access failed due to a hardware error";
        case SdoAbort::LengthMismatch:
            return "data type does not match, length of service parameter does not match";
        case SdoAbort::LengthTooHigh:
            return "data type does not match, length of service parameter too high";
        case SdoAbort::LengthTooLow:
            return "data type does not match, length of service parameter too low";
        case SdoAbort::NoSubIndex:
            return "sub-index does not exist";
        case SdoAbort::InvalidValue:
            return "invalid value for parameter";
        case SdoAbort::ValueTooHigh:
            return "value of parameter written too high";
        case SdoAbort::ValueTooLow:
            return "value of parameter written too low";
        case SdoAbort::General:
            return "general error";
        case SdoAbort::DataTransfer:
            return "data cannot be transferred or stored to the application";
        case SdoAbort::LocalControl:
            return "data cannot be transferred or stored to the application because of local "
                   "control";
        case SdoAbort::DeviceState:
            return "data cannot be transferred or stored to the application because of the present "
                   "device state";
        case SdoAbort::NoData:
            return "no data available";
    }
    return nullptr;
}

class SdoCategory final : public std::error_category {
public:
    const char* name() const noexcept override { return "canopen.sdo"; }
    std::string message(int value) const override {
        auto code = static_cast<uint32_t>(value);
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%08X", code);
        const char* text = abortText(code);
        return std::string("SDO abort ") + hex + ": " + (text ? text : "unknown abort code");
    }
};

}  // namespace

const std::error_category& sdoCategory() noexcept {
    static const SdoCategory category;
    return category;
}

std::error_code make_error_code(SdoAbort e) noexcept {
    return sdoError(static_cast<uint32_t>(e));
}

std::error_code sdoError(uint32_t abortCode) noexcept {
    return {static_cast<int>(abortCode), sdoCategory()};
}

uint32_t abortCodeOf(std::error_code error) noexcept {
    if (error.category() != sdoCategory()) return static_cast<uint32_t>(SdoAbort::General);
    return static_cast<uint32_t>(error.value());
}

}  // namespace kerf::drivers::canopen
