#include "drivers/canopen/emcy.h"

#include <cstddef>

#include "drivers/canopen/cob_id.h"

namespace kerf::drivers::canopen {

can::CanFrame emcyFrame(uint8_t node, const Emcy& emcy) noexcept {
    const auto& m = emcy.manufacturer;
    return can::makeFrame(kEmcyBase + node, {static_cast<uint8_t>(emcy.code & 0xFF),
                                             static_cast<uint8_t>(emcy.code >> 8),
                                             emcy.errorRegister, m[0], m[1], m[2], m[3], m[4]});
}

bool parseEmcy(const can::CanFrame& frame, uint8_t& node, Emcy& out) noexcept {
    if (frame.extended || frame.remote || functionCode(frame.id) != kEmcyBase ||
        nodeOf(frame.id) == 0 || frame.length != 8) {
        return false;
    }
    node = nodeOf(frame.id);
    out.code = static_cast<uint16_t>(frame.data[0] | frame.data[1] << 8);
    out.errorRegister = frame.data[2];
    for (std::size_t i = 0; i < out.manufacturer.size(); ++i)
        out.manufacturer[i] = frame.data[3 + i];
    return true;
}

const char* emcyClassName(uint16_t code) noexcept {
    if (code == 0x0000) return "error reset";
    switch (code >> 12) {
        case 0x1:
            return "generic error";
        case 0x2:
            return "current";
        case 0x3:
            return "voltage";
        case 0x4:
            return "temperature";
        case 0x5:
            return "device hardware";
        case 0x6:
            return "device software";
        case 0x7:
            return "additional modules";
        case 0x8:
            return (code >> 8) == 0x81 || (code >> 8) == 0x82 ? "communication" : "monitoring";
        case 0x9:
            return "external error";
        case 0xF:
            return (code >> 8) == 0xFF ? "device specific" : "additional functions";
        default:
            return "unknown class";
    }
}

const char* emcyCodeText(uint16_t code) noexcept {
    switch (code) {
        case 0x1000:
            return "generic error";
        case 0x2310:
            return "continuous over-current";
        case 0x3210:
            return "DC link over-voltage";
        case 0x3220:
            return "DC link under-voltage";
        case 0x4210:
            return "excess temperature device";
        case 0x4310:
            return "excess temperature drive";
        case 0x5530:
            return "EEPROM / data memory error";
        case 0x6010:
            return "software reset (watchdog)";
        case 0x7300:
            return "sensor error";
        case 0x7305:
            return "incremental sensor 1 fault (encoder)";
        case 0x8110:
            return "CAN overrun (objects lost)";
        case 0x8120:
            return "CAN in error passive mode";
        case 0x8130:
            return "life guard or heartbeat error";
        case 0x8140:
            return "recovered from bus off";
        case 0x8250:
            return "RPDO timeout";
        case 0x8400:
            return "velocity speed controller";
        case 0x8611:
            return "following error";
        case 0x8612:
            return "reference limit";
        default:
            return emcyClassName(code);
    }
}

uint8_t errorRegisterFor(uint16_t code) noexcept {
    if (code == 0) return 0;
    uint8_t reg = 0x01;
    switch (code >> 12) {
        case 0x2:
            reg |= 0x02;
            break;
        case 0x3:
            reg |= 0x04;
            break;
        case 0x4:
            reg |= 0x08;
            break;
        case 0x8:
            if ((code >> 8) == 0x81 || (code >> 8) == 0x82)
                reg |= 0x10;
            else
                reg |= 0x20;
            break;
        default:
            break;
    }
    return reg;
}

}  // namespace kerf::drivers::canopen
