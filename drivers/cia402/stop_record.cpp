#include "drivers/cia402/stop_record.h"

#include <cstdio>

#include "drivers/canopen/emcy.h"

namespace kerf::drivers::cia402 {

namespace {

std::string hex(unsigned value, int digits) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%0*X", digits, value);
    return text;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", value);
    return text;
}

std::string emcyText(const StopRecord& r) {
    return "EMCY " + hex(r.code, 4) + " " + canopen::emcyCodeText(r.code) + ", error register " +
           hex(r.errorRegister, 2);
}

}  // namespace

std::string describeStop(const StopRecord& r) {
    switch (r.reason) {
        case StopReason::DriveFault:
            return "drive fault" +
                   (r.code ? " " + hex(r.code, 4) + " " + canopen::emcyCodeText(r.code)
                           : std::string()) +
                   " (state " + stateName(r.state) + ")";
        case StopReason::Emergency:
            return emcyText(r);
        case StopReason::EmergencyWarning:
            return "warning: " + emcyText(r);
        case StopReason::HeartbeatLost:
            return "heartbeat lost: none within the consumer time";
        case StopReason::PdoMissing:
            return "TPDO missing in consecutive SYNC cycles";
        case StopReason::UnexpectedNmtState:
            return std::string("node reported ") + canopen::nmtStateName(r.nmtState) +
                   " while operational";
        case StopReason::BootFailed:
            if (r.object.index == 0) return "boot failed: " + r.error.message();
            return "boot failed at " + hex(r.object.index, 4) + ":" +
                   hex(r.object.subIndex, 2).substr(2) + ": " + r.error.message();
        case StopReason::EnableTimeout:
            return std::string("enable not confirmed within the step timeout (state ") +
                   stateName(r.state) + ")";
        case StopReason::UnexpectedState:
            return std::string("drive left operation enabled on its own (now ") +
                   stateName(r.state) + ")";
        case StopReason::TargetIgnored:
            return "drive stopped following the target (statusword bit 12)";
        case StopReason::FollowingError:
            return r.value > 0.0 ? "following error " + number(r.value) + " beyond twice the window"
                                 : "following error reported by the drive (statusword bit 13)";
        case StopReason::SetpointJump:
            return "first setpoint after enabling is " + number(r.value) +
                   " away from the actual position";
        case StopReason::BusOff:
            return "CAN controller is bus off";
        case StopReason::ErrorPassive:
            return "warning: CAN controller is error passive";
    }
    return "?";
}

}  // namespace kerf::drivers::cia402
