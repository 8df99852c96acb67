#pragma once

#include <array>
#include <cstdint>

#include "core/interp/fagor/plane_frame.h"
#include "core/interp/path/path_move.h"

namespace kerf::fagor {

enum class FeedKind : uint8_t { PerMinute, PerRevolution, InverseTime };  // G94 G95 G32
enum class CornerKind : uint8_t { Sharp, Round, Controlled, LookAhead };  // G07 G05 G50 G51

// The modal G functions (spec part 1 §5). The reset events (start, M02, M30) restore the machine
// parameters' values; zero offsets are not modal state (they survive).
struct ModalState {
    int motion = 0;  // 0 1 2 3 33 34
    PlaneFrame plane;
    int planeG = 18;           // 16 17 18 19
    bool inch = false;         // G70
    bool incremental = false;  // G91
    bool diameter = true;      // G151
    FeedKind feed = FeedKind::PerMinute;
    bool constantSurfaceSpeed = false;  // G96
    CornerKind corner = CornerKind::Sharp;
    AxisMask mirror = 0;                                                  // G11-G14
    interp::CompSide side = interp::CompSide::None;                       // G41 G42
    int collisionBlocks = 0;                                              // G41 N
    double scale = 1.0;                                                   // G72 S
    std::array<double, kAxisCount> axisScale{1, 1, 1, 1, 1, 1, 1, 1, 1};  // G72 X..C
    Pose retraction{};                                                    // G233
    AxisMask retractionAxes = 0;
};

}  // namespace kerf::fagor
