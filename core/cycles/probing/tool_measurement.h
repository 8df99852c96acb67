#pragma once

#include <optional>

#include "core/canon/commands.h"
#include "core/cycles/cycle_context.h"

// Tool measurement with the tool touch probe TT (spec 7): cycles 30/480 CALIBRATE TT, 31/481
// TOOL LENGTH, 32/482 TOOL RADIUS, 33/483 MEASURE TOOL. A cycle moves the spindle's gauge point
// (machine coordinates, tool axis z), touches and computes; the tool tip lies the tool's length
// below the gauge point, so a length is where the gauge point triggers above the stylus top.
namespace kerf::cycles::probing {

// The TT as the control knows it: the machine file's values, or those of the last calibration.
struct ToolProbeData {
    Vec3 top{0.0, 0.0, 0.0};  // centre of the measuring surface
    double diameter = 0.0;    // a cube's side
    bool cube = false;
    double offsetToolAxis = 0.0;      // radius measurement: end face below the top
    double safetyDistance = 0.0;      // clearance above the stylus, start of a touch before it
    double maxPeripheralSpeed = 0.0;  // m/min
    double measureTolerance = 0.0;    // mm
    double probingFeed = 0.0;         // mm/min, stationary spindle
    double maxRpm = 0.0;              // of the machine's spindle
};

// The tool-table row of the tool in the spindle (TOOL.T columns of spec 7.1), in mm.
struct MeasuredToolData {
    double length = 0.0;                 // L
    double radius = 0.0;                 // R
    double deltaLength = 0.0;            // DL
    double deltaRadius = 0.0;            // DR
    int cutterCount = 0;                 // CUT; 0: measure the radius with a stationary spindle
    double lengthWear = 0.0;             // LTOL
    double radiusWear = 0.0;             // RTOL
    double lengthBreak = 0.0;            // LBREAK
    double radiusBreak = 0.0;            // RBREAK
    std::optional<double> radiusOffset;  // R-OFFS; empty: the tool radius
    double lengthOffset = 0.0;           // L-OFFS
    double cuttingDirection = -1.0;      // DIRECT: negative cuts with M3
};

class ToolProbingMachine {
public:
    virtual ~ToolProbingMachine() = default;
    virtual Vec3 gauge() const = 0;
    // A positioning move of the gauge point (rapid traverse).
    virtual void moveTo(const Vec3& gauge) = 0;
    virtual void spindle(canon::SpindleDirection direction, double rpm) = 0;
    virtual void orientSpindle(double angleDeg) = 0;
    // A touch from the current position along the unit `direction` at `feed`: the gauge point
    // when the TT triggered, nothing when it did not within `maxPath`. The tool then returns to
    // where the touch started.
    virtual std::optional<Vec3> touch(const Vec3& direction, double maxPath, double feed) = 0;
    virtual bool deflected() const = 0;
};

struct ToolMeasurementRequest {
    bool length = false;
    bool radius = false;
    int mode = 0;             // Q340: 0 write L/R, 1 compare and write DL/DR, 2 compare only
    double clearanceZ = 0.0;  // Q260 as a tool-tip height in machine coordinates
    bool teeth = false;       // Q341: individual-tooth measurement
};

struct ToolMeasurementResult {
    std::optional<double> length;  // measured L, R
    std::optional<double> radius;
    double lengthDeviation = 0.0;  // Q115: measured - L (modes 1 and 2)
    double radiusDeviation = 0.0;  // Q116
    int status = 0;                // Q199: 0 in tolerance, 1 worn, 2 broken
    // What the tool table gets (nothing in mode 2).
    std::optional<double> newLength, newRadius, newDeltaLength, newDeltaRadius;
    bool lock = false;  // TL = L
};

// Cycles 31-33 / 481-483: measures `request` and evaluates it against the tool table row.
std::optional<CycleError> measureTool(int cycle, const ToolMeasurementRequest& request,
                                      const ToolProbeData& tt, const MeasuredToolData& tool,
                                      ToolProbingMachine& machine, ToolMeasurementResult& result);

// Cycle 30 / 480 with a calibration tool whose L and R are exact: where the TT really is.
std::optional<CycleError> calibrateToolProbe(int cycle, double clearanceZ, const ToolProbeData& tt,
                                             const MeasuredToolData& tool,
                                             ToolProbingMachine& machine,
                                             ToolProbeData& calibrated);

}  // namespace kerf::cycles::probing
