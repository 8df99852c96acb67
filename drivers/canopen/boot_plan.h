#pragma once

#include <cstdint>
#include <vector>

#include "drivers/canopen/master_error.h"
#include "drivers/canopen/pdo.h"
#include "drivers/canopen/sdo_protocol.h"

// The SDO steps that configure one node at boot (CiA 402 A2.4 steps 2-8), built once in the
// configuration thread and then run by the master step by step. A step writes a value, reads one
// for the record, or reads one and compares it under a mask, failing the boot with its own
// reason on a mismatch.
namespace kerf::drivers::canopen {

enum class BootStepKind : uint8_t { Write, Read, Expect };

struct BootStep {
    BootStepKind kind = BootStepKind::Write;
    ObjectAddress address;
    uint32_t value = 0;  // Write: the value; Expect: the expected value under `mask`
    uint8_t size = 4;    // Write: bytes
    uint32_t mask = 0xFFFFFFFFu;
    MasterErrc mismatch = MasterErrc::ReadBackMismatch;
};

class BootPlan {
public:
    void write(ObjectAddress address, uint32_t value, uint8_t size) {
        m_steps.push_back({BootStepKind::Write, address, value, size});
    }
    void read(ObjectAddress address) { m_steps.push_back({BootStepKind::Read, address}); }
    void expect(ObjectAddress address, uint32_t value, uint32_t mask, MasterErrc mismatch) {
        m_steps.push_back({BootStepKind::Expect, address, value, 4, mask, mismatch});
    }
    // The remap procedure of CiA 301 for RPDO/TPDO `number` (1..4): invalidate the COB-ID, clear
    // the mapping, write the entries, set the count, the transmission type (TPDO: inhibit time and
    // event timer too), then validate the COB-ID.
    void configurePdo(bool transmit, int number, const PdoLayout& layout);
    // Marks RPDO/TPDO `number` as not existing (COB-ID bit 31).
    void disablePdo(bool transmit, int number, uint32_t cobId);

    const std::vector<BootStep>& steps() const noexcept { return m_steps; }

private:
    std::vector<BootStep> m_steps;
};

// Communication and mapping parameter indices of PDO `number` (1..4).
constexpr uint16_t pdoCommunicationIndex(bool transmit, int number) noexcept {
    return static_cast<uint16_t>((transmit ? 0x1800 : 0x1400) + number - 1);
}
constexpr uint16_t pdoMappingIndex(bool transmit, int number) noexcept {
    return static_cast<uint16_t>((transmit ? 0x1A00 : 0x1600) + number - 1);
}

}  // namespace kerf::drivers::canopen
