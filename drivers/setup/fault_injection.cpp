#include "drivers/setup/fault_injection.h"

#include <array>
#include <charconv>
#include <string>

#include "core/base/translate.h"

namespace kerf::drivers {

namespace {

struct KindName {
    FaultKind kind;
    const char* name;
};

constexpr std::array<KindName, 11> kKinds{{
    {FaultKind::Heartbeat, "heartbeat"},
    {FaultKind::Emcy, "emcy"},
    {FaultKind::FollowingError, "following-error"},
    {FaultKind::Encoder, "encoder"},
    {FaultKind::Pdo, "pdo"},
    {FaultKind::Silent, "silent"},
    {FaultKind::SlowBoot, "slow-boot"},
    {FaultKind::Identity, "identity"},
    {FaultKind::SdoAbort, "sdo-abort"},
    {FaultKind::BusOff, "bus-off"},
    {FaultKind::ErrorPassive, "error-passive"},
}};

Diagnostic badSpec(std::string_view text) {
    std::string kinds;
    for (const KindName& k : kKinds) {
        if (!kinds.empty()) kinds += ", ";
        kinds += k.name;
    }
    Diagnostic d;
    d.code = "drives.fault-spec";
    d.messageTemplate = KERF_TR_NOOP(
        "--inject-fault {1}: expected NODE:KIND@SECONDS with a node-ID 0-127 (0: the master's "
        "controller) and KIND one of {2}");
    d.args = {std::string(text), kinds};
    return d;
}

}  // namespace

const char* faultKindName(FaultKind kind) noexcept {
    for (const KindName& k : kKinds) {
        if (k.kind == kind) return k.name;
    }
    return "?";
}

Expected<FaultInjection> parseFaultInjection(std::string_view text) {
    size_t colon = text.find(':');
    size_t at = text.find('@');
    if (colon == std::string_view::npos || at == std::string_view::npos || at < colon) {
        return badSpec(text);
    }
    FaultInjection f;
    std::string_view node = text.substr(0, colon);
    unsigned value = 0;
    auto [end, error] = std::from_chars(node.data(), node.data() + node.size(), value);
    if (error != std::errc() || end != node.data() + node.size() || value > 127)
        return badSpec(text);
    f.node = static_cast<uint8_t>(value);
    std::string_view kind = text.substr(colon + 1, at - colon - 1);
    bool found = false;
    for (const KindName& k : kKinds) {
        if (kind == k.name) {
            f.kind = k.kind;
            found = true;
        }
    }
    if (!found) return badSpec(text);
    bool masterFault = f.kind == FaultKind::BusOff || f.kind == FaultKind::ErrorPassive;
    if (f.node == 0 && !masterFault) return badSpec(text);
    std::string_view seconds = text.substr(at + 1);
    auto [last, bad] = std::from_chars(seconds.data(), seconds.data() + seconds.size(), f.timeS);
    if (seconds.empty() || bad != std::errc() || last != seconds.data() + seconds.size() ||
        !(f.timeS >= 0.0)) {
        return badSpec(text);
    }
    return f;
}

}  // namespace kerf::drivers
