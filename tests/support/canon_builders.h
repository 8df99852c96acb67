// Small builders for tests that feed canonical commands straight to a consumer.
#pragma once

#include <cstdint>
#include <utility>

#include "core/canon/commands.h"
#include "core/geometry/axes.h"

namespace kerf::test {

// X, Y, Z; the other axes 0.
inline Pose pose(double x, double y, double z) {
    Pose p;
    p.values[0] = x;
    p.values[1] = y;
    p.values[2] = z;
    return p;
}

// A command as from the given program line.
inline canon::Command command(canon::CommandBody body, uint32_t line) {
    canon::Command c;
    c.location.line = line;
    c.body = std::move(body);
    return c;
}

}  // namespace kerf::test
