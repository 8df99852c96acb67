#include "core/interp/path/value_guard.h"

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/canon/value_limits.h"

namespace kerf::interp {

std::optional<PathError> unsafeValueError(const canon::Command& command) {
    const auto unsafe = canon::findUnsafeValue(command.body);
    if (!unsafe) return std::nullopt;
    return PathError{
        command.location,
        "range",
        KERF_TR_NOOP("{1} = {2} is outside the range of the control (at most {3})"),
        {unsafe->quantity, formatShort(unsafe->value), formatShort(canon::kMaxStreamMagnitude)}};
}

void ValueGuard::consume(const canon::Command& command) {
    if (m_refused || m_target == nullptr) return;
    if (auto error = unsafeValueError(command)) {
        m_error = std::move(error);
        m_refused = true;
        return;
    }
    m_target->consume(command);
}

std::optional<PathError> ValueGuard::takeError() {
    auto error = std::move(m_error);
    m_error.reset();
    return error;
}

}  // namespace kerf::interp
