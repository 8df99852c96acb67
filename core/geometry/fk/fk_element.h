#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "core/geometry/axes.h"

// One block of HEIDENHAIN FK free contour programming (FL, FLT, FC, FCT) as the solver reads it:
// every datum the drawing gives, in the working plane, nothing computed yet.
namespace kerf::fk {

// A coordinate or angle as written: absolute, incremental from the element's start point
// (IX, IPA ...), or incremental from the end point of an earlier block (RX 13 with IX+20).
struct FkValue {
    double value = 0.0;
    bool incremental = false;
    std::optional<int64_t> reference;  // block number of R.. data
};

enum class FkKind : uint8_t { Line, TangentLine, Arc, TangentArc };
enum class FkRotation : uint8_t { None, Ccw, Cw };  // DR+ / DR-

struct FkElement {
    FkKind kind = FkKind::Line;
    int64_t blockNumber = -1;  // for R.. references of later blocks
    // End point: Cartesian X/Y, polar PR/PA about the FK pole.
    std::optional<FkValue> x, y, pr, pa;
    // Direction of a line / entry tangent of an arc (AN), length of a line / chord of an arc (LEN).
    std::optional<FkValue> an;
    std::optional<double> length;
    // Arc: rotation, radius, centre (Cartesian or polar), angle of the end point about the centre.
    FkRotation rotation = FkRotation::None;
    std::optional<double> radius;
    std::optional<FkValue> ccx, ccy, ccpr, ccpa;
    std::optional<double> endAngleAboutCentre;  // CCA
    // A point at distance D from the element (PDX/PDY/D) and up to three points on it (P1..P3).
    std::optional<FkValue> pdx, pdy;
    std::optional<double> distance;
    std::array<std::optional<Vec2>, 3> pointsOn{};
    bool closeStart = false;  // CLSD+
    bool closeEnd = false;    // CLSD-

    bool isArc() const { return kind == FkKind::Arc || kind == FkKind::TangentArc; }
    bool isTangent() const { return kind == FkKind::TangentLine || kind == FkKind::TangentArc; }
};

}  // namespace kerf::fk
