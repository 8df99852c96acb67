#include "core/cycles/parameter_check.h"

#include <cmath>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"

namespace kerf::cycles {

std::string parameterName(const ParameterDescriptor& d) {
    return d.q != 0 ? "Q" + std::to_string(d.q) : std::string(d.word);
}

std::optional<CycleError> missingParameterError(const std::string& owner,
                                                const ParameterDescriptor& d) {
    if (d.optional) return std::nullopt;
    return CycleError{"cycle-parameter",
                      KERF_TR_NOOP("{1}: parameter {2} ({3}) is missing"),
                      {owner, parameterName(d), d.description}};
}

std::optional<CycleError> parameterValueError(const std::string& owner,
                                              const ParameterDescriptor& d, double value) {
    // The tolerance accepts values written with fewer decimals than the limit (99999.9999).
    const bool whole = !d.integer || std::fabs(value - std::round(value)) < 1e-9;
    if (value >= d.min - 1e-9 && value <= d.max + 1e-9 && whole) return std::nullopt;
    return CycleError{
        "cycle-range",
        d.integer ? KERF_TR_NOOP("{1}: parameter {2} ({3}) = {4} must be a whole number from {5} "
                                 "to {6}")
                  : KERF_TR_NOOP("{1}: parameter {2} ({3}) = {4} is outside {5} to {6}"),
        {owner, parameterName(d), d.description, formatForMessage(value, 4), formatFixed(d.min, 4),
         formatFixed(d.max, 4)}};
}

}  // namespace kerf::cycles
