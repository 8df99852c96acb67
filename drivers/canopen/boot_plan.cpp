#include "drivers/canopen/boot_plan.h"

namespace kerf::drivers::canopen {

void BootPlan::configurePdo(bool transmit, int number, const PdoLayout& layout) {
    uint16_t comm = pdoCommunicationIndex(transmit, number);
    uint16_t mapping = pdoMappingIndex(transmit, number);
    write({comm, 1}, layout.cobId | kPdoInvalid, 4);
    write({mapping, 0}, 0, 1);
    for (uint8_t i = 0; i < layout.count; ++i)
        write({mapping, static_cast<uint8_t>(i + 1)}, layout.entries[i].value(), 4);
    write({mapping, 0}, layout.count, 1);
    write({comm, 2}, layout.transmissionType, 1);
    if (transmit) {
        write({comm, 3}, layout.inhibitTime100us, 2);
        write({comm, 5}, layout.eventTimerMs, 2);
    }
    write({comm, 1}, layout.cobId, 4);
}

void BootPlan::disablePdo(bool transmit, int number, uint32_t cobId) {
    write({pdoCommunicationIndex(transmit, number), 1}, cobId | kPdoInvalid, 4);
}

}  // namespace kerf::drivers::canopen
