#include "core/interp/path/value_guard.h"

#include <cmath>
#include <variant>

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

namespace {

// A straight move whose nine coordinates and feed are all in range: the command of nearly every
// block, passed without the general inspection (which would find nothing either).
bool straightMoveInRange(const canon::CommandBody& body) {
    const Pose* target = nullptr;
    double feed = 0.0;
    if (const auto* line = std::get_if<canon::LinearMove>(&body)) {
        target = &line->target;
        feed = line->feed;
    } else if (const auto* rapid = std::get_if<canon::RapidMove>(&body)) {
        target = &rapid->target;
    } else {
        return false;
    }
    bool safe = std::fabs(feed) <= canon::kMaxStreamMagnitude;
    for (double value : target->values)
        safe &= std::fabs(value) <= canon::kMaxStreamMagnitude;
    return safe;
}

}  // namespace

void ValueGuard::consume(const canon::Command& command) {
    if (m_refused || m_target == nullptr) return;
    if (straightMoveInRange(command.body)) {
        m_target->consume(command);
        return;
    }
    if (auto error = unsafeValueError(command)) {
        m_error = std::move(error);
        m_refused = true;
        return;
    }
    m_target->consume(command);
}

std::optional<PathError> ValueGuard::takeError() {
    if (!m_error) return std::nullopt;  // asked after every block
    auto error = std::move(m_error);
    m_error.reset();
    return error;
}

}  // namespace kerf::interp
