#pragma once

#include <array>
#include <bitset>
#include <cstdint>

#include "core/interp/fagor/problem.h"
#include "core/interp/fagor/statement_runner.h"

namespace kerf::fagor {

// The arithmetic parameters (spec part 2 §5.3): locals P0-P25 per local level (the main program
// and up to 6 nested PCALL/MCALL levels), globals P100-P299, manufacturer P1000-P1255 and OEM
// P2000-P2255 (only in programs with the O attribute). Unset parameters read as 0.
class Parameters {
public:
    static constexpr int kMaxLocalLevels = 6;

    bool get(int number, double& out, Problem& problem) const;
    bool set(int number, double value, Problem& problem);
    // Whether the run gave the parameter a value (locals: of the current level, including those
    // the call assigned). Only locals and globals are tracked.
    bool isSet(int number) const;

    // A new local level for PCALL/MCALL; false when 6 are already nested.
    bool pushLocalLevel(const LocalAssignments& locals);
    void popLocalLevel();
    int localLevel() const { return m_level; }
    // CALLP: which locals the call that opened this level defined.
    uint32_t definedLocals() const { return m_defined[static_cast<size_t>(m_level)]; }

    // A canned cycle works in local level 6 and P299 (spec part 2 §1.5): they are overwritten
    // (cleared) by every cycle.
    void clobberForCycle();

    // Interrupt subroutines may only use globals; OEM parameters need an OEM program.
    void setLocalsAllowed(bool allowed) { m_localsAllowed = allowed; }
    void setOemAllowed(bool allowed) { m_oemAllowed = allowed; }

private:
    template <typename Self>
    static auto slotOf(Self& self, int number, Problem& problem) -> decltype(&self.m_globals[0]);

    std::array<std::array<double, 26>, kMaxLocalLevels + 1> m_locals{};
    std::array<uint32_t, kMaxLocalLevels + 1> m_defined{};
    int m_level = 0;
    std::array<double, 200> m_globals{};
    std::array<uint32_t, kMaxLocalLevels + 1> m_localSet{};
    std::bitset<200> m_globalSet;
    std::array<double, 256> m_manufacturer{};
    std::array<double, 256> m_oem{};
    bool m_localsAllowed = true;
    bool m_oemAllowed = false;
};

}  // namespace kerf::fagor
