#include "core/interp/fagor/parameters.h"

#include <cmath>
#include <string>

#include "core/base/translate.h"

namespace kerf::fagor {

template <typename Self>
auto Parameters::slotOf(Self& self, int number, Problem& problem) -> decltype(&self.m_globals[0]) {
    auto fail = [&](const char* text) -> decltype(&self.m_globals[0]) {
        problem.code = "parameter";
        problem.messageTemplate = text;
        problem.args = {std::to_string(number)};
        return nullptr;
    };
    if (number >= 0 && number <= 25) {
        if (!self.m_localsAllowed) {
            return fail(
                KERF_TR_NOOP("P{1}: an interrupt subroutine may only use global parameters"));
        }
        return &self.m_locals[static_cast<size_t>(self.m_level)][static_cast<size_t>(number)];
    }
    if (number >= 100 && number <= 299) return &self.m_globals[static_cast<size_t>(number - 100)];
    if (number >= 1000 && number <= 1255) {
        return &self.m_manufacturer[static_cast<size_t>(number - 1000)];
    }
    if (number >= 2000 && number <= 2255) {
        if (!self.m_oemAllowed) {
            return fail(
                KERF_TR_NOOP("P{1}: OEM parameters are only for programs with the O attribute"));
        }
        return &self.m_oem[static_cast<size_t>(number - 2000)];
    }
    return fail(KERF_TR_NOOP("P{1} does not exist (P0-P25, P100-P299, P1000-P1255, P2000-P2255)"));
}

bool Parameters::get(int number, double& out, Problem& problem) const {
    const double* p = slotOf(*this, number, problem);
    if (p == nullptr) return false;
    out = *p;
    return true;
}

bool Parameters::set(int number, double value, Problem& problem) {
    double* p = slotOf(*this, number, problem);
    if (p == nullptr) return false;
    if (!std::isfinite(value)) {  // every value the language computes is finite: keep it so
        problem.code = "overflow";
        problem.messageTemplate = KERF_TR_NOOP("P{1}: the value is too large (overflow)");
        problem.args = {std::to_string(number)};
        return false;
    }
    *p = value;
    if (number >= 0 && number <= 25) {
        m_localSet[static_cast<size_t>(m_level)] |= 1u << number;
    } else if (number >= 100 && number <= 299) {
        m_globalSet.set(static_cast<size_t>(number - 100));
    }
    return true;
}

bool Parameters::isSet(int number) const {
    if (number >= 0 && number <= 25) {
        return ((m_localSet[static_cast<size_t>(m_level)] >> number) & 1u) != 0;
    }
    if (number >= 100 && number <= 299) return m_globalSet.test(static_cast<size_t>(number - 100));
    return false;
}

bool Parameters::pushLocalLevel(const LocalAssignments& locals) {
    if (m_level >= kMaxLocalLevels) return false;
    ++m_level;
    m_locals[static_cast<size_t>(m_level)] = locals.values;
    m_defined[static_cast<size_t>(m_level)] = locals.defined;
    m_localSet[static_cast<size_t>(m_level)] = locals.defined;
    return true;
}

void Parameters::popLocalLevel() {
    if (m_level > 0) --m_level;
}

void Parameters::clobberForCycle() {
    m_locals[kMaxLocalLevels].fill(0.0);
    m_localSet[kMaxLocalLevels] = 0;
    m_defined[kMaxLocalLevels] = 0;
    m_globals[299 - 100] = 0.0;
    m_globalSet.reset(299 - 100);
}

}  // namespace kerf::fagor
