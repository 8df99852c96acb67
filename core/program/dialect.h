#pragma once

#include <optional>
#include <string_view>

namespace kerf::program {

enum class Dialect : uint8_t { Klartext, TncIso, Fagor };

const char* dialectName(Dialect dialect);
std::optional<Dialect> dialectFromName(std::string_view name);

// The dialect a file is written in: `.H` conversational, `.I` TNC ISO; anything else follows the
// machine (Fagor on a lathe, conversational on a mill). G numbers are never used to guess.
Dialect dialectForFile(std::string_view path, bool latheMachine);

}  // namespace kerf::program
