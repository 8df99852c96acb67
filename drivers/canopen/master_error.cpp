#include "drivers/canopen/master_error.h"

#include <string>

namespace kerf::drivers::canopen {

namespace {

class MasterCategory final : public std::error_category {
public:
    const char* name() const noexcept override { return "canopen.master"; }
    std::string message(int code) const override {
        switch (static_cast<MasterErrc>(code)) {
            case MasterErrc::BootUpTimeout:
                return "no boot-up message";
            case MasterErrc::DeviceTypeMismatch:
                return "device type (0x1000) is not the configured one";
            case MasterErrc::IdentityMismatch:
                return "identity (0x1018) is not the configured one";
            case MasterErrc::ModeNotSupported:
                return "drive does not support the mode of operation (0x6502)";
            case MasterErrc::ReadBackMismatch:
                return "value read back differs from the value written";
            case MasterErrc::NotOperational:
                return "node did not report Operational after the start command";
            case MasterErrc::HeartbeatLost:
                return "heartbeat lost";
            case MasterErrc::UnexpectedNmtState:
                return "unexpected NMT state";
            case MasterErrc::PdoMissing:
                return "TPDO missing";
        }
        return "unknown master error " + std::to_string(code);
    }
};

}  // namespace

const std::error_category& masterCategory() noexcept {
    static const MasterCategory category;
    return category;
}

std::error_code make_error_code(MasterErrc e) noexcept {
    return {static_cast<int>(e), masterCategory()};
}

}  // namespace kerf::drivers::canopen
