#include "drivers/setup/socketcan_bus.h"

#include "drivers/can/can_error.h"
#include "drivers/can/can_link_info.h"
#include "drivers/canopen/cob_id.h"

namespace kerf::drivers {

std::vector<can::CanFilter> driveBusFilters(const CanBusConfig& config) {
    std::vector<can::CanFilter> filters;
    for (const CanJoint& j : config.joints) {
        if (j.node == 0) continue;
        for (uint32_t base : {canopen::kHeartbeatBase, canopen::kEmcyBase, canopen::kTpdo1Base,
                              canopen::kSdoResponseBase}) {
            filters.push_back({base + j.node, can::kStandardIdMask});
        }
    }
    return filters;
}

std::error_code openDriveBus(const CanBusConfig& config, can::SocketCanChannel& channel) {
    can::CanLinkInfo link;
    if (!can::readCanLinkInfo(config.interface, link) && link.bitrate != 0 &&
        link.bitrate != config.bitrate) {
        return can::CanErrc::BitrateMismatch;
    }
    std::vector<can::CanFilter> filters = driveBusFilters(config);
    return channel.open(config.interface, filters);
}

}  // namespace kerf::drivers
