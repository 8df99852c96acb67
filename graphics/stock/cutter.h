#pragma once

#include <cstdint>
#include <vector>

#include "core/canon/commands.h"

namespace kerf::graphics {

enum class CutterKind : uint8_t { Flat, Ball, BullNose, Drill };
const char* cutterKindName(CutterKind kind);

// A milling tool as a solid of revolution about the tool axis, the tip (the programmed point) at
// its lowest point. Built from the tool table: R and R2 give flat (R2 = 0), ball (R2 = R) and
// bull-nose (0 < R2 < R) end mills; a point angle (T-ANGLE, the full included angle) gives a
// drill, whose cone ends in the cylinder of radius R.
struct MillCutter {
    CutterKind kind = CutterKind::Flat;
    double radiusMm = 0.0;
    double cornerRadiusMm = 0.0;  // bull-nose and ball
    double pointAngleDeg = 0.0;   // drill
    double lengthMm = 0.0;        // shown length of the tool (0: a default from the radius)
    bool touchProbe = false;      // a touch probe's stylus: drawn as a ball, removes nothing

    static MillCutter fromGeometry(double radiusMm, double radius2Mm, double pointAngleDeg = 0.0);
    // A touch probe (a tool with TP_NO in the tool table): its ball of the tool's radius.
    static MillCutter touchProbeStylus(double ballRadiusMm);
    // Height of the cutting surface above the tip at a distance rho from the axis (rho <= R);
    // +infinity beyond the radius.
    double heightAt(double rhoMm) const;
    // Height of the cutting surface where it reaches the full radius (drill: the cone's length).
    double profileHeight() const;
    // Volume of the tool below height h above its tip, for checks: the analytic volume a plunge
    // of depth h removes.
    double volumeBelow(double heightMm) const;
    bool cuts() const { return radiusMm > 0.0 && !touchProbe; }
};

// What a lathe tool is, for the material it removes (docs/graphics.md, "Lathe tools").
enum class LatheToolKind : uint8_t { Turning, Grooving, Drill };

// A lathe insert in the XZ plane (X a radius): a nose circle and, optionally, the two cutting
// edges of a rhombic body behind it. The programmed point is the theoretical tip P, which the
// location code places relative to the nose centre C (codes 1-8 around the nose, 0 and 9 the
// centre itself). The code table is the provisional variant "A" of shared/spec/fagor-8035t-part1.md
// §11.3 (X up, Z right, F3 the standard external turning tool), kept here until the Fagor tool
// offsets are wired in.
// A grooving tool is a blade of the cutting width and a drill a cylinder of that diameter ending
// in its point, the programmed point at the point's tip.
struct LatheInsert {
    LatheToolKind kind = LatheToolKind::Turning;
    double noseRadiusMm = 0.4;
    int locationCode = 3;
    double includedAngleDeg = 0.0;  // rhombic body angle; 0: the nose circle alone
    double edgeLengthMm = 0.0;      // body edge length; 0: the nose circle alone
    double widthMm = 0.0;           // grooving: the cutting edge's width; drill: the diameter
    double pointAngleDeg = 118.0;   // drill: the point's included angle (twist drill default)

    // The tool of a canonical lathe offset: a cutting width (NOSEW) makes a centre code (F0, F9:
    // the programmed point on the tool's axis) a drill of that diameter and a corner or face
    // code a grooving tool of that width; anything else is a turning insert of nose R. A drill's
    // point is the tool's nose angle (NOSEA), the default point without one.
    static LatheInsert fromGeometry(const canon::ToolGeometry& geometry);

    // Unit tip-offset vector u = (uX, uZ) of a code: P = C + R * u.
    static std::pair<double, double> tipDirection(int locationCode);
    // Nose centre relative to the programmed point, (dX, dZ).
    std::pair<double, double> noseCentreOffset() const;
    // A grooving tool that plunges along Z (face codes 2 and 6) rather than along X.
    bool groovesAlongZ() const;
    // Outline of the tool relative to the programmed point as (X, Z) pairs, the nose arc with
    // `arcPoints` points. A drill's or grooving blade's body reaches `bodyMm` back from its
    // cutting edge (0: four times its width).
    std::vector<std::pair<double, double>> outline(int arcPoints = 16, double bodyMm = 0.0) const;
};

}  // namespace kerf::graphics
