#pragma once

#include "ui/cycles/help_drawing.h"

namespace kerf::ui {

// The help picture of FAGOR canned cycle G<g> (G66-G89), in the 100 x 100 space of HelpDrawing:
// the lathe seen from the side (Z to the right, X up from the spindle axis). Dimensions are
// keyed by the parameter letters ("X", "C", "L", ...): the turning profile for G66, G68, G69
// and G81-G85 (start point, pass step, allowances, retract), the thread on the shaft for G86
// and on the face for G87 (depth, first pass, pitch, infeed angle), the groove for G88/G89 (step
// between plunges) and the hole for G83 (depth, peck).
HelpDrawing fagorHelpDrawing(int g);

}  // namespace kerf::ui
