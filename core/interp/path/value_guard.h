#pragma once

#include <optional>

#include "core/canon/commands.h"
#include "core/interp/path/path_move.h"

namespace kerf::interp {

// The error for a command with a number outside the canonical stream's range (not finite, or
// beyond canon::kMaxStreamMagnitude), at the command's block; nothing if all are in range.
std::optional<PathError> unsafeValueError(const canon::Command& command);

// The last stage of an interpreter's output: forwards commands whose numbers are all in range.
// The first command that is not is refused; it and everything after it are dropped, so the
// interpreter can report the error and stop.
class ValueGuard final : public canon::Sink {
public:
    void setTarget(canon::Sink* target) { m_target = target; }
    void consume(const canon::Command& command) override;
    // The refusal, once.
    std::optional<PathError> takeError();

private:
    canon::Sink* m_target = nullptr;
    std::optional<PathError> m_error;
    bool m_refused = false;
};

}  // namespace kerf::interp
