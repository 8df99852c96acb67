#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/canon/commands.h"
#include "core/cycles/cycle_values.h"
#include "core/geometry/axes.h"
#include "core/geometry/offset_contour.h"

namespace kerf::cycles::contour {
class ClearingCache;
}

// What a cycle reads and how it emits its moves. Cycles work in a local frame of the working
// plane: u = main axis, v = secondary axis, w = tool axis (positive away from the workpiece), in
// program coordinates; the interpreter maps them to axes and applies the active coordinate
// transformations, so cycles and path functions are transformed alike.
namespace kerf::cycles {

struct ToolInfo {
    int number = 0;
    double radius = 0.0;  // R + DR (table) + DR (TOOL CALL)
    double length = 0.0;
    double radius2 = 0.0;
    double pointAngleDeg = 0.0;   // T-ANGLE
    double plungeAngleDeg = 0.0;  // ANGLE
    double cuttingLength = 0.0;   // LCUTS
    double pitch = 0.0;           // PITCH
    int cutterCount = 0;          // CUT
};

// A local date and time (cycle 225 %time).
struct DateTime {
    int year = 2000;
    int month = 1;
    int day = 1;
    int hour = 0;
    int minute = 0;
    int second = 0;
};

// One contour subprogram listed in cycle 14 (SL cycles), as programmed: its direction and its
// radius compensation tell a pocket (the tool inside) from an island (the tool outside).
struct SubContour {
    ClosedContour contour;
    bool island = false;
    int label = 0;
};

// The contour formula (spec §8) instead of cycle 14: subcontours (all pockets unless `island`,
// the simple formula's I<n>) and how they combine, in postfix order.
struct FormulaContour {
    ClosedContour contour;
    // How deep the area reaches below the surface (0: cycle 20's depth); for an island the depth
    // of its top below the surface (0: the island reaches up to the surface).
    double depth = 0.0;
    bool island = false;
};
struct FormulaStep {
    enum class Kind : uint8_t { Contour, Union, Intersection, Difference, SymmetricDifference };
    Kind kind = Kind::Contour;
    size_t contour = 0;  // index into `contours` for Kind::Contour
};
struct ContourFormula {
    std::vector<FormulaContour> contours;
    std::vector<FormulaStep> steps;
};

// Cycles 25, 275 and 276: the first contour subprogram of cycle 14 as a path, open or closed, as
// programmed (25: the contour to follow; 275: the slot's centre line).
struct ContourTrain {
    std::vector<PlanarSegment> segments;
    int side = 0;           // radius compensation of its first move: +1 RL, -1 RR, 0 R0
    bool closed = false;    // ends where it starts
    bool approach = false;  // begins with an APPR block (275: an open slot)
    // 276: the tool-axis coordinate at the start and end of each segment (empty: planar).
    std::vector<std::pair<double, double>> heights;
    size_t labelCount = 0;  // labels listed in cycle 14
    int label = 0;
};

struct CycleContext {
    Vec3 start{0.0, 0.0, 0.0};  // tool position when the cycle starts (hole centre in the plane)
    ToolInfo tool;
    canon::SpindleDirection spindle = canon::SpindleDirection::Stopped;
    double spindleRpm = 0.0;
    bool positiveDepthIsError = true;  // machine parameter displayDepthErr
    // Mirrored working-plane axes: 202/204 keep their disengaging direction unmirrored.
    bool mirroredMain = false;
    bool mirroredSecondary = false;
    DateTime now;                    // cycle 225 %time
    unsigned long long counter = 0;  // cycle 225 %count: the MOD counter (0 in test run)
    // SL cycles 21-24: the subcontours of cycle 14 (empty without it), the values of cycle 20
    // (null without it), the tools of the table by number (Q13, Q18; R without DR) and the
    // radius of the tool that last roughed this contour (cycle 22; 0: none).
    std::vector<SubContour> contours;
    std::optional<ContourFormula> formula;  // SEL CONTOUR or CONTOUR DEF instead of cycle 14
    const CycleValues* contourData = nullptr;
    std::function<std::optional<ToolInfo>(int)> toolByNumber;
    double roughingRadius = 0.0;
    // Clearing plans of earlier calls, kept by the caller across cycle calls (22 and 23 clear
    // the same region): null plans afresh every time.
    contour::ClearingCache* clearingCache = nullptr;
    // Machine parameter posAfterContPocket: the SL cycles (21-25, 275, 276) end back at `start`
    // (PosBeforeMachining) instead of at the clearance height in the tool axis only.
    bool slReturnToStart = false;
    // Cycles 25 and 275: the contour as a path; cycle 270's values (null without it).
    ContourTrain train;
    const CycleValues* trainData = nullptr;
};

// A problem that stops the cycle; the interpreter adds the location of the calling block.
struct CycleError {
    std::string code;
    std::string messageTemplate;  // English with {1}.. placeholders, marked with KERF_TR_NOOP
    std::vector<std::string> args;
};

// Receives the moves of an expanded cycle (local coordinates, see above).
// How far the straight pieces of an arc the stream cannot hold may stray from it (mm).
inline constexpr double kSpatialArcTolerance = 0.5e-3;

class CycleEmitter {
public:
    virtual ~CycleEmitter() = default;
    virtual void rapid(const Vec3& target) = 0;
    virtual void line(const Vec3& target, const Feed& feed) = 0;
    // Arc or helix about `center` (u, v) in the working plane; sweep signed, positive = DR+.
    virtual void arc(const Vec3& target, const Vec2& center, double sweepRad, const Feed& feed) = 0;
    // An arc of less than half a turn from `from` to `target` about `centre` (all u, v, w) in the
    // plane of the three points, which may hold the tool axis (cycle 23's approach). This one
    // writes straight pieces within kSpatialArcTolerance of it; an emitter that can write the
    // plane's arc does so instead.
    virtual void spatialArc(const Vec3& from, const Vec3& target, const Vec3& centre,
                            const Feed& feed);
    // Spindle-synchronised move (rigid tapping, thread cutting): `leadMm` per revolution, its
    // sign the hand of the thread (+ right-hand).
    virtual void threadMove(const Vec3& target, double leadMm, double startAngleDeg) = 0;
    virtual void dwell(double seconds) = 0;
    virtual void spindle(canon::SpindleDirection direction, double rpm) = 0;
    virtual void orientSpindle(double angleDeg) = 0;
    // A miscellaneous function the cycle switches (coolant M8/M9 of cycle 241 ...).
    virtual void miscFunction(int number) = 0;
};

}  // namespace kerf::cycles
