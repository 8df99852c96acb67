#pragma once

#include "core/cycles/lathe/lathe_path.h"

namespace kerf::cycles::lathe {

// G88 (plunges along X, steps along Z) and G89 (plunges along Z, steps along X): spec part 2 §2.
struct Groove {
    bool alongZ = false;   // G89
    Vec2 start{0.0, 0.0};  // (z, x radius): X Z
    Vec2 end{0.0, 0.0};    // Q R
    double maxStep = 0.0;  // C (0: the tool width)
    double safety = 0.0;   // D, radius
    double dwellSeconds = 0.0;
    double toolWidth = 0.0;  // NOSEW
    // Location code F of the active offset: which edge of the blade the programmed point is
    // (docs/fagor.md, G88/G89); -1, 0 and 9 say nothing: the width runs from it towards the end.
    int locationCode = -1;
};

bool expandGroove(const Groove& groove, const Vec2& call, LathePath& path, LatheError& error);

}  // namespace kerf::cycles::lathe
