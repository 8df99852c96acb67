#pragma once

namespace kerf::ui {

// What the position display shows, chosen with MOD (as the TNC's "position display" setting).
enum class PositionKind {
    Actual,            // ACTL: actual position, workpiece coordinates
    Nominal,           // NOML: commanded position, workpiece coordinates
    ReferenceActual,   // REF ACTL: actual position, machine coordinates
    ReferenceNominal,  // REF NOML: commanded position, machine coordinates
    Lag,               // LAG: following error
    DistanceToGo,      // DIST: remaining distance of the current move
};

// Display settings of the MOD functions, shared by the MOD page (writes) and the position and
// status displays (read).
struct DisplaySettings {
    PositionKind positionKind = PositionKind::Actual;
    bool inch = false;  // show lengths in inch
};

}  // namespace kerf::ui
