#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_parameter.h"
#include "core/cycles/cycle_values.h"

// Touch-probe cycles (spec tnc-probing-cycles.md). A probing cycle moves the probe, touches,
// computes and moves again; it talks to the machine through ProbingMachine, in the local frame
// of the cycles (u main axis, v secondary axis, w tool axis; program coordinates). Positions are
// those of the ball centre: the interpreter converts them to tool-tip positions.
namespace kerf::cycles::probing {

// The active touch probe: tool-table R (ball radius) and the linked touch-probe table row.
struct ProbeData {
    int number = 1;                // NO: its row of the touch-probe table
    double ballRadius = 0.0;       // r_b
    double probingFeed = 0.0;      // F, mm/min
    double positioningFeed = 0.0;  // FMAX (F_PREPOS = FMAX_PROBE); 0: rapid traverse
    double maxPath = 0.0;          // DIST
    double setUp = 0.0;            // SET_UP
    bool track = false;            // TRACK ON or 441 Q399 = 1: orient the probe before each touch
    double length = 0.0;           // L_p: the probe's effective length (461 calibrates it)
    // CAL_OF1/CAL_OF2: the ball centre's offset from the spindle axis (main, secondary axis)
    // with the probe oriented at CAL_ANG; at another orientation it turns with the spindle.
    Vec2 centreOffset{0.0, 0.0};
    double calibrationAngleDeg = 0.0;  // CAL_ANG
    // The probe's TYPE allows a reversal (turned by half a turn): 460, 462 and 463 then also
    // measure the centre offset.
    bool reversible = true;
    // The machine's rotary table axes, nearest to the workpiece first ("CB" on a B/C trunnion
    // with C on B, "A" with one A table, empty without): 403 and 405 turn one of them.
    std::string tableAxes;
};

// What the control asks the operator to do at a stop of the semi-automatic mode.
struct OperatorPrompt {
    const char* messageTemplate = "";
    std::vector<std::string> args;
};

class ProbingMachine {
public:
    virtual ~ProbingMachine() = default;
    virtual Vec3 ballCentre() const = 0;
    // A positioning move of the ball centre at the probe's positioning feed.
    virtual void moveTo(const Vec3& ballCentre) = 0;
    // A touch from the current position along the unit vector `direction` at the probing feed:
    // the ball centre when the stylus triggered, nothing when it did not within `maxPath`. The
    // probe then returns to where the touch started.
    virtual std::optional<Vec3> touch(const Vec3& direction, double maxPath) = 0;
    // A touch like `touch` that stays where it ended, at the trigger or after `maxPath`
    // (cycles 3 and 4 retract by their own distance). This default goes back and forth.
    virtual std::optional<Vec3> touchAndStay(const Vec3& direction, double maxPath) {
        const Vec3 start = ballCentre();
        auto hit = touch(direction, maxPath);
        moveTo(hit ? *hit : Vec3(start + maxPath * direction));
        return hit;
    }
    // True when the stylus is deflected before a touch starts (PRB-002).
    virtual bool deflected() const { return false; }
    // Orients the spindle, and so the probe, to `angleDeg` in the plane (the calibration's
    // 180-degree reversal). The ball centre then lies where the new orientation puts it. A
    // machine whose probe cannot be oriented ignores it.
    virtual void orient(double angleDeg) { (void)angleDeg; }
    // What the control adds to the spindle position for the ball centre at the probe's current
    // orientation: CAL_OF1/CAL_OF2 turned with the spindle (main, secondary axis). Cycles 0, 1
    // and 3 report positions without it (spec 1.5).
    virtual Vec2 centreOffsetApplied() const { return {0.0, 0.0}; }
    // The semi-automatic mode (1416's "?"): the program stops with `prompt` and the operator
    // positions the probe near the touch point; after NC start ballCentre() is where it stands.
    // A machine no operator moves leaves it where it is.
    virtual void waitForOperator(const OperatorPrompt& prompt) { (void)prompt; }
};

// Where a datum cycle puts the datum: the measured feature (local program coordinates, per local
// axis u, v, w; unset axes are not measured) gets the nominal values (Q331, Q332, Q333 ...).
struct DatumResult {
    std::array<std::optional<double>, 3> measured;
    std::array<double, 3> nominal{0.0, 0.0, 0.0};
};

// Tool monitoring with Q330 (spec 1.14): what the measured deviation adds to the monitored
// tool's DR (or DL), and the size compared with its RBREAK.
struct ToolCorrection {
    bool length = false;        // DL (427 in the tool axis) instead of DR
    double delta = 0.0;         // added to DR or DL
    bool breakageOnly = false;  // 430: no correction, breakage monitoring only
};

// 403, 405: the rotary table axis turns by `turnDeg` (incremental) to cancel the measured
// misalignment; Q337 then zeroes its display (the preset's offset for that axis) or, for 405
// with Q337 > 0, adds the measured offset to that axis in row `datumRow` of the datum table.
struct RotaryCompensation {
    char axis = 'C';
    double turnDeg = 0.0;
    bool zeroDisplay = false;
    std::optional<int> datumRow;
};

// 441 FAST PROBING: what the following probing cycles of the program use instead of the probe
// table's FMAX and F_PREPOS, angle tracking, and whether Q281 = 2 may stop the program.
struct FastProbing {
    Feed positioning = Feed::perMinute(0.0);  // Q396 (FMAX: rapid traverse)
    bool machineRapid = false;                // Q397
    bool tracking = false;                    // Q399
    bool interrupt = true;                    // Q400
};

// 460-463: the probe's calibrated length and ball radius, for its row of the tool table, and
// its centre offset (CAL_OF1, CAL_OF2 at CAL_ANG) for its row of the touch-probe table.
struct ProbeCalibration {
    std::optional<double> length;
    std::optional<double> radius;
    std::optional<Vec2> centreOffset;
};

struct ProbingResults {
    std::vector<std::pair<uint16_t, double>> parameters;  // Q150..Q199 in mm and degrees
    std::optional<DatumResult> datum;                     // 408-419
    std::optional<double> basicRotationDeg;               // 400-402, 404, 414, 1416
    std::optional<RotaryCompensation> rotary;             // 403, 405
    int tableRow = 0;                                     // Q305 (404: -1 the active preset)
    int transfer = 0;                                     // Q303: -1, 0 datum table, 1 presets
    // Measuring log TCHPR<cycle>.TXT (Q281 = 1 or 2): the lines after the header.
    std::optional<std::vector<std::string>> protocol;
    bool protocolStop = false;                     // Q281 = 2: stop after writing the log
    std::optional<CycleError> toleranceStop;       // Q309 = 1 and a tolerance was exceeded
    std::optional<ToolCorrection> toolCorrection;  // applied when Q330 names a tool
    std::optional<FastProbing> fastProbing;        // 441
    std::optional<ProbeCalibration> calibration;   // 460-463

    void set(uint16_t q, double value) { parameters.emplace_back(q, value); }
};

using ProbingFunction = std::optional<CycleError> (*)(const CycleValues&, const ProbeData&,
                                                      ProbingMachine&, ProbingResults&);

// The TT cycles (tool_measurement.h) run through their own interface; `run` is unset for them.
enum class ToolMeasurementKind : uint8_t { None, Calibrate, Length, Radius, LengthAndRadius };

struct ProbingCycleDescriptor {
    int number = 0;
    const char* name = nullptr;  // English, KERF_TR_NOOP
    std::span<const ParameterDescriptor> parameters;
    ProbingFunction run = nullptr;
    std::span<const uint16_t> results;  // set to 0 before the cycle runs (spec 1.11)
    ToolMeasurementKind toolMeasurement = ToolMeasurementKind::None;
};

// The implemented probing cycles (TCH PROBE n); their numbers are independent of CYCL DEF's.
std::span<const ProbingCycleDescriptor* const> allProbingCycles();
const ProbingCycleDescriptor* findProbingCycle(int number);
// The old-format TT cycles 30-33 (sub-blocks 30.0 ... 33.3): the new cycle they run as (480-483),
// or nullptr.
const ProbingCycleDescriptor* findOldToolProbeCycle(int number);

}  // namespace kerf::cycles::probing
