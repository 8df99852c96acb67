#include "core/cycles/probing/probing_14xx.h"

#include "core/base/translate.h"
#include "core/cycles/parameter_check.h"

namespace kerf::cycles::probing {

namespace {

// The entries of a nominal position's actual value and of its "unknown" mark: apart from every
// Q number.
constexpr uint16_t kActualEntry = 40000;
constexpr uint16_t kUnknownEntry = 42000;

}  // namespace

bool takesActualPosition(int cycle, uint16_t q) {
    // Spec 8.8 rule 1: Q1100-Q1102, the nominal position in the main, secondary and tool axes.
    return cycle == 1416 && q >= 1100 && q <= 1102;
}

CycleError actualPositionError(const std::string& owner, const ParameterDescriptor& d) {
    return CycleError{"cycle-parameter",
                      KERF_TR_NOOP("{1}: parameter {2} ({3}) takes no actual position "
                                   "(nominal@actual is for the nominal positions of a 14xx "
                                   "cycle)"),
                      {owner, parameterName(d), d.description}};
}

void setActualPosition(CycleValues& values, uint16_t q, double actual) {
    values.set(static_cast<uint16_t>(q + kActualEntry), actual);
}

std::optional<double> actualPosition(const CycleValues& values, uint16_t q) {
    const auto entry = static_cast<uint16_t>(q + kActualEntry);
    if (!values.has(entry)) return std::nullopt;
    return values.number(entry);
}

CycleError unknownPositionError(const std::string& owner, const ParameterDescriptor& d) {
    return CycleError{"cycle-parameter",
                      KERF_TR_NOOP("{1}: parameter {2} ({3}) cannot be unknown ('?' is for the "
                                   "nominal positions of a 14xx cycle)"),
                      {owner, parameterName(d), d.description}};
}

void setUnknownPosition(CycleValues& values, uint16_t q) {
    values.set(static_cast<uint16_t>(q + kUnknownEntry), 1.0);
}

bool unknownPosition(const CycleValues& values, uint16_t q) {
    return values.has(static_cast<uint16_t>(q + kUnknownEntry));
}

}  // namespace kerf::cycles::probing
