#pragma once

#include <cstdint>
#include <system_error>

// SDO abort codes of CiA 301 (section 7.2.4.3.17) as std::error_code values of the category
// "canopen.sdo": a failed transfer's error() compares equal to SdoAbort::NoObject and prints the
// standard's text. The values fit into int (all are below 0x80000000).
namespace kerf::drivers::canopen {

enum class SdoAbort : uint32_t {
    ToggleBit = 0x05030000,
    Timeout = 0x05040000,
    UnknownCommand = 0x05040001,
    OutOfMemory = 0x05040005,
    UnsupportedAccess = 0x06010000,
    ReadOfWriteOnly = 0x06010001,
    WriteOfReadOnly = 0x06010002,
    NoObject = 0x06020000,
    NotMappable = 0x06040041,
    MappingTooLong = 0x06040042,
    ParameterIncompatible = 0x06040043,
    DeviceIncompatible = 0x06040047,
    HardwareError = 0x06060000,
    LengthMismatch = 0x06070010,
    LengthTooHigh = 0x06070012,
    LengthTooLow = 0x06070013,
    NoSubIndex = 0x06090011,
    InvalidValue = 0x06090030,
    ValueTooHigh = 0x06090031,
    ValueTooLow = 0x06090032,
    General = 0x08000000,
    DataTransfer = 0x08000020,
    LocalControl = 0x08000021,
    DeviceState = 0x08000022,
    NoData = 0x08000024,
};

const std::error_category& sdoCategory() noexcept;
std::error_code make_error_code(SdoAbort e) noexcept;
// An abort code as received on the bus (also codes this list does not name).
std::error_code sdoError(uint32_t abortCode) noexcept;
// The abort code of an error of the SDO category; General (0x08000000) for any other error.
uint32_t abortCodeOf(std::error_code error) noexcept;

}  // namespace kerf::drivers::canopen

template <>
struct std::is_error_code_enum<kerf::drivers::canopen::SdoAbort> : std::true_type {};
