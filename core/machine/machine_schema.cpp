#include "core/machine/machine_schema.h"

#include <algorithm>

#include "core/machine/detail/field_binding.h"

namespace kerf::machine {

namespace {

using detail::bindField;
using detail::FieldBinding;

constexpr auto kMachine = ParameterScope::Machine;
constexpr auto kAxis = ParameterScope::Axis;

const std::vector<FieldBinding<MachineConfig>>& machineBindings() {
    static const std::vector<FieldBinding<MachineConfig>> table{
        bindField<&MachineConfig::name>(
            kMachine, {.key = "name", .description = KERF_TR_NOOP("Name shown to the operator")}),
        bindField<&MachineConfig::kind>(
            kMachine, {.key = "kind",
                       .description = KERF_TR_NOOP(
                           "Machine kind; selects the program dialects and lathe conventions")}),
        bindField<&MachineConfig::toolAxis>(
            kMachine, {.key = "tool_axis",
                       .description = KERF_TR_NOOP(
                           "Axis the tool points along; tool length compensation acts on it")}),
        bindField<&MachineConfig::rapidVelocityMmPerS>(
            kMachine, {.key = "rapid_velocity",
                       .unit = "mm/s",
                       .minimum = 0.1,
                       .maximum = 5000.0,
                       .description = KERF_TR_NOOP("Path velocity of rapid moves")}),
        bindField<&MachineConfig::maxFeedMmPerS>(
            kMachine, {.key = "max_feed",
                       .unit = "mm/s",
                       .minimum = 0.1,
                       .maximum = 5000.0,
                       .description = KERF_TR_NOOP("Highest programmable feed rate")}),
        bindField<&MachineConfig::servoPeriodMs>(
            kMachine, {.key = "servo_period",
                       .unit = "ms",
                       .minimum = 0.1,
                       .maximum = 100.0,
                       .description = KERF_TR_NOOP("Period of the servo cycle")}),
        bindField<&MachineConfig::pathToleranceMm>(
            kMachine,
            {.key = "path_tolerance",
             .unit = "mm",
             .minimum = 0.0,
             .maximum = 10.0,
             .description = KERF_TR_NOOP(
                 "Default path deviation allowed when blending corners; 0 stops exactly")}),
        bindField<&MachineConfig::referenceRequired>(
            kMachine, {.key = "reference_required",
                       .description = KERF_TR_NOOP(
                           "Programs and MDI run only after the axes are homed (Home all); false "
                           "lets a machine without reference switches run from power-on")}),
        bindField<&MachineConfig::slReturnToStart>(
            kMachine, {.key = "sl_return_to_start",
                       .description = KERF_TR_NOOP(
                           "SL cycles (21-25, 275, 276) end back at the position before the "
                           "cycle (the TNC's posAfterContPocket = PosBeforeMachining); false: at "
                           "the clearance height Q7, the tool axis only (ToolAxClearanceHeight)")}),
        bindField<&MachineConfig::parameterCode>(
            kMachine, {.key = "parameter_code",
                       .unit = "code",
                       .minimum = 0.0,
                       .maximum = 99999999.0,
                       .description = KERF_TR_NOOP(
                           "Code number asked before machine parameters may be edited")}),
        bindField<&MachineConfig::spindle, &SpindleConfig::minRpm>(
            kMachine, {.key = "spindle.min_rpm",
                       .unit = "rpm",
                       .minimum = 0.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP("Lowest spindle speed")}),
        bindField<&MachineConfig::spindle, &SpindleConfig::maxRpm>(
            kMachine, {.key = "spindle.max_rpm",
                       .unit = "rpm",
                       .minimum = 0.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP("Highest spindle speed")}),
        bindField<&MachineConfig::spindle, &SpindleConfig::driveNode>(
            kMachine, {.key = "spindle.drive_node",
                       .unit = "node-ID",
                       .minimum = 0.0,
                       .maximum = 127.0,
                       .description = KERF_TR_NOOP(
                           "CANopen node-ID of the spindle drive; 0: the spindle has none")}),
        bindField<&MachineConfig::spindle, &SpindleConfig::driveCountsPerDeg>(
            kMachine, {.key = "spindle.drive_scale",
                       .unit = "counts/deg",
                       .minimum = 0.001,
                       .maximum = 1.0e9,
                       .description = KERF_TR_NOOP("Spindle drive position units per degree")}),
        bindField<&MachineConfig::spindle, &SpindleConfig::driveMode>(
            kMachine, {.key = "spindle.drive_mode",
                       .description = KERF_TR_NOOP(
                           "CiA 402 mode of the spindle drive: cyclic synchronous or profile "
                           "velocity")}),
        bindField<&MachineConfig::kinematics, &KinematicsConfig::type>(
            kMachine, {.key = "kinematics.type",
                       .description = KERF_TR_NOOP(
                           "How the rotary axes are built: none, one rotary table, a table on a "
                           "tilting table, a swivel head and a table, or a fork head")}),
        bindField<&MachineConfig::kinematics, &KinematicsConfig::primary>(
            kMachine,
            {.key = "kinematics.primary",
             .description = KERF_TR_NOOP("The tilting rotary axis (SEQ+/SEQ- choose its sign)")}),
        bindField<&MachineConfig::kinematics, &KinematicsConfig::secondary>(
            kMachine, {.key = "kinematics.secondary",
                       .description = KERF_TR_NOOP(
                           "The second rotary axis: the table on the tilting table, the table "
                           "of a head-table machine, the head axis carrying the fork")}),
        bindField<&MachineConfig::kinematics, &KinematicsConfig::pivotXMm>(
            kMachine, {.key = "kinematics.pivot.x",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP(
                           "Machine X where the rotary axes meet; write pivot = [x, y, z]")}),
        bindField<&MachineConfig::kinematics, &KinematicsConfig::pivotYMm>(
            kMachine, {.key = "kinematics.pivot.y",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP(
                           "Machine Y where the rotary axes meet; write pivot = [x, y, z]")}),
        bindField<&MachineConfig::kinematics, &KinematicsConfig::pivotZMm>(
            kMachine, {.key = "kinematics.pivot.z",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP(
                           "Machine Z where the rotary axes meet; write pivot = [x, y, z]")}),
        bindField<&MachineConfig::kinematics, &KinematicsConfig::headPivotXMm>(
            kMachine, {.key = "kinematics.head_pivot.x",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP(
                           "Head: X of the head's pivot from the spindle nose, head at 0; write "
                           "head_pivot = [x, y, z]")}),
        bindField<&MachineConfig::kinematics, &KinematicsConfig::headPivotYMm>(
            kMachine, {.key = "kinematics.head_pivot.y",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP(
                           "Head: Y of the head's pivot from the spindle nose, head at 0; write "
                           "head_pivot = [x, y, z]")}),
        bindField<&MachineConfig::kinematics, &KinematicsConfig::headPivotZMm>(
            kMachine, {.key = "kinematics.head_pivot.z",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP(
                           "Head: Z of the head's pivot from the spindle nose, head at 0; write "
                           "head_pivot = [x, y, z]")}),
        bindField<&MachineConfig::bar, &BarConfig::diameterMm>(
            kMachine, {.key = "bar.diameter",
                       .unit = "mm",
                       .minimum = 0.0,
                       .maximum = 10000.0,
                       .description = KERF_TR_NOOP(
                           "Lathe: diameter of the bar simulated when the program defines no "
                           "blank; 0: none")}),
        bindField<&MachineConfig::bar, &BarConfig::lengthMm>(
            kMachine, {.key = "bar.length",
                       .unit = "mm",
                       .minimum = 0.1,
                       .maximum = 10000.0,
                       .description = KERF_TR_NOOP("Lathe: length of the simulated bar")}),
        bindField<&MachineConfig::bar, &BarConfig::faceZMm>(
            kMachine, {.key = "bar.face_z",
                       .unit = "mm",
                       .minimum = -10000.0,
                       .maximum = 10000.0,
                       .description = KERF_TR_NOOP(
                           "Lathe: workpiece Z of the bar's face; the bar reaches down to "
                           "face_z - length")}),
        bindField<&MachineConfig::bar, &BarConfig::boreDiameterMm>(
            kMachine,
            {.key = "bar.bore_diameter",
             .unit = "mm",
             .minimum = 0.0,
             .maximum = 10000.0,
             .description = KERF_TR_NOOP("Lathe: inner diameter of a tube; 0: a solid bar")}),
        bindField<&MachineConfig::probeWorkpiece, &ProbeWorkpieceConfig::enabled>(
            kMachine, {.key = "simulation.probe.enabled",
                       .description = KERF_TR_NOOP(
                           "Simulation: a box-shaped workpiece the touch probe touches (G75, "
                           "probing cycles); the bounds below, machine coordinates of the tool "
                           "tip")}),
        bindField<&MachineConfig::probeWorkpiece, &ProbeWorkpieceConfig::xMinMm>(
            kMachine,
            {.key = "simulation.probe.x_min",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated probe workpiece: lowest machine X of the tool tip inside it")}),
        bindField<&MachineConfig::probeWorkpiece, &ProbeWorkpieceConfig::xMaxMm>(
            kMachine,
            {.key = "simulation.probe.x_max",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated probe workpiece: highest machine X of the tool tip inside it")}),
        bindField<&MachineConfig::probeWorkpiece, &ProbeWorkpieceConfig::yMinMm>(
            kMachine,
            {.key = "simulation.probe.y_min",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated probe workpiece: lowest machine Y of the tool tip inside it")}),
        bindField<&MachineConfig::probeWorkpiece, &ProbeWorkpieceConfig::yMaxMm>(
            kMachine,
            {.key = "simulation.probe.y_max",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated probe workpiece: highest machine Y of the tool tip inside it")}),
        bindField<&MachineConfig::probeWorkpiece, &ProbeWorkpieceConfig::zMinMm>(
            kMachine,
            {.key = "simulation.probe.z_min",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated probe workpiece: lowest machine Z of the tool tip inside it")}),
        bindField<&MachineConfig::probeWorkpiece, &ProbeWorkpieceConfig::zMaxMm>(
            kMachine,
            {.key = "simulation.probe.z_max",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated probe workpiece: highest machine Z of the tool tip inside it")}),
        bindField<&MachineConfig::setupError, &SetupErrorConfig::shiftXMm>(
            kMachine,
            {.key = "simulation.setup.shift.x",
             .unit = "mm",
             .minimum = -1000.0,
             .maximum = 1000.0,
             .description = KERF_TR_NOOP(
                 "Simulation: how far the real blank lies from its programmed position in machine "
                 "X; write shift = [x, y, z]")}),
        bindField<&MachineConfig::setupError, &SetupErrorConfig::shiftYMm>(
            kMachine,
            {.key = "simulation.setup.shift.y",
             .unit = "mm",
             .minimum = -1000.0,
             .maximum = 1000.0,
             .description = KERF_TR_NOOP(
                 "Simulation: how far the real blank lies from its programmed position in machine "
                 "Y; write shift = [x, y, z]")}),
        bindField<&MachineConfig::setupError, &SetupErrorConfig::shiftZMm>(
            kMachine,
            {.key = "simulation.setup.shift.z",
             .unit = "mm",
             .minimum = -1000.0,
             .maximum = 1000.0,
             .description = KERF_TR_NOOP(
                 "Simulation: how far the real blank lies from its programmed position in machine "
                 "Z; write shift = [x, y, z]")}),
        bindField<&MachineConfig::setupError, &SetupErrorConfig::rotationDeg>(
            kMachine, {.key = "simulation.setup.rotation",
                       .unit = "deg",
                       .minimum = -180.0,
                       .maximum = 180.0,
                       .description = KERF_TR_NOOP(
                           "Simulation: how far the real blank is turned about the tool axis, "
                           "through its programmed origin")}),
        bindField<&MachineConfig::simulationBlank, &SimulationBlankConfig::minXMm>(
            kMachine,
            {.key = "simulation.blank.min.x",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated blank of a program without BLK FORM: its lowest X, "
                 "workpiece coordinates of the machine file's preset; write min = [x, y, z]")}),
        bindField<&MachineConfig::simulationBlank, &SimulationBlankConfig::minYMm>(
            kMachine,
            {.key = "simulation.blank.min.y",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated blank of a program without BLK FORM: its lowest Y, "
                 "workpiece coordinates of the machine file's preset; write min = [x, y, z]")}),
        bindField<&MachineConfig::simulationBlank, &SimulationBlankConfig::minZMm>(
            kMachine,
            {.key = "simulation.blank.min.z",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated blank of a program without BLK FORM: its lowest Z, "
                 "workpiece coordinates of the machine file's preset; write min = [x, y, z]")}),
        bindField<&MachineConfig::simulationBlank, &SimulationBlankConfig::maxXMm>(
            kMachine,
            {.key = "simulation.blank.max.x",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated blank of a program without BLK FORM: its highest X, "
                 "workpiece coordinates of the machine file's preset; write max = [x, y, z]")}),
        bindField<&MachineConfig::simulationBlank, &SimulationBlankConfig::maxYMm>(
            kMachine,
            {.key = "simulation.blank.max.y",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated blank of a program without BLK FORM: its highest Y, "
                 "workpiece coordinates of the machine file's preset; write max = [x, y, z]")}),
        bindField<&MachineConfig::simulationBlank, &SimulationBlankConfig::maxZMm>(
            kMachine,
            {.key = "simulation.blank.max.z",
             .unit = "mm",
             .minimum = -100000.0,
             .maximum = 100000.0,
             .description = KERF_TR_NOOP(
                 "Simulated blank of a program without BLK FORM: its highest Z, "
                 "workpiece coordinates of the machine file's preset; write max = [x, y, z]")}),
        bindField<&MachineConfig::calibrationSphere, &CalibrationSphereConfig::centreXMm>(
            kMachine, {.key = "simulation.calibration_sphere.centre.x",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP(
                           "Calibration sphere (cycle 460): X of its centre in the blank's "
                           "programmed frame; write centre = [x, y, z]")}),
        bindField<&MachineConfig::calibrationSphere, &CalibrationSphereConfig::centreYMm>(
            kMachine, {.key = "simulation.calibration_sphere.centre.y",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP(
                           "Calibration sphere (cycle 460): Y of its centre in the blank's "
                           "programmed frame; write centre = [x, y, z]")}),
        bindField<&MachineConfig::calibrationSphere, &CalibrationSphereConfig::centreZMm>(
            kMachine, {.key = "simulation.calibration_sphere.centre.z",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP(
                           "Calibration sphere (cycle 460): Z of its centre in the blank's "
                           "programmed frame; write centre = [x, y, z]")}),
        bindField<&MachineConfig::calibrationSphere, &CalibrationSphereConfig::radiusMm>(
            kMachine, {.key = "simulation.calibration_sphere.radius",
                       .unit = "mm",
                       .minimum = 0.0,
                       .maximum = 100.0,
                       .description = KERF_TR_NOOP(
                           "Calibration sphere (cycle 460): its exact radius; 0: none")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::enabled>(
            kMachine, {.key = "simulation.tool_probe.enabled",
                       .description = KERF_TR_NOOP(
                           "Simulation: the machine has a tool touch probe (TT) for the tool "
                           "measuring cycles 30-33 and 480-483")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::centreXMm>(
            kMachine, {.key = "simulation.tool_probe.centre.x",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP("TT: machine X of the centre of the measuring "
                                                   "surface; write centre = [x, y, z]")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::centreYMm>(
            kMachine, {.key = "simulation.tool_probe.centre.y",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP("TT: machine Y of the centre of the measuring "
                                                   "surface; write centre = [x, y, z]")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::centreZMm>(
            kMachine, {.key = "simulation.tool_probe.centre.z",
                       .unit = "mm",
                       .minimum = -100000.0,
                       .maximum = 100000.0,
                       .description = KERF_TR_NOOP("TT: machine Z of the centre of the measuring "
                                                   "surface; write centre = [x, y, z]")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::diameterMm>(
            kMachine, {.key = "simulation.tool_probe.diameter",
                       .unit = "mm",
                       .minimum = 1.0,
                       .maximum = 1000.0,
                       .description = KERF_TR_NOOP(
                           "TT: diameter of the disc stylus (side of a cube stylus)")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::shape>(
            kMachine, {.key = "simulation.tool_probe.type",
                       .description = KERF_TR_NOOP("TT: stylus shape, a disc or a cube")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::offsetToolAxisMm>(
            kMachine,
            {.key = "simulation.tool_probe.offset_tool_axis",
             .unit = "mm",
             .minimum = 0.0,
             .maximum = 100.0,
             .description = KERF_TR_NOOP("TT: how far below the top of the stylus the end face of "
                                         "the tool sits when its radius is measured")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::safetyDistanceMm>(
            kMachine, {.key = "simulation.tool_probe.safety_distance",
                       .unit = "mm",
                       .minimum = 0.1,
                       .maximum = 100.0,
                       .description = KERF_TR_NOOP("TT: safety zone above the stylus, and how far "
                                                   "before the stylus each touch starts")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::maxPeripheralSpeedMPerMin>(
            kMachine,
            {.key = "simulation.tool_probe.max_peripheral_speed",
             .unit = "m/min",
             .minimum = 1.0,
             .maximum = 1000.0,
             .description = KERF_TR_NOOP(
                 "TT: highest cutting-edge speed of a rotating tool; sets the measuring speed")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::measureToleranceMm>(
            kMachine, {.key = "simulation.tool_probe.measure_tolerance",
                       .unit = "mm",
                       .minimum = 0.0001,
                       .maximum = 1.0,
                       .description = KERF_TR_NOOP("TT: measuring error allowed with a rotating "
                                                   "tool; probing feed = tolerance x speed")}),
        bindField<&MachineConfig::toolProbe, &ToolProbeConfig::probingFeedMmPerMin>(
            kMachine, {.key = "simulation.tool_probe.probing_feed",
                       .unit = "mm/min",
                       .minimum = 1.0,
                       .maximum = 10000.0,
                       .description = KERF_TR_NOOP("TT: probing feed with a stationary spindle")}),
        bindField<&MachineConfig::drives, &DrivesConfig::interface>(
            kMachine, {.key = "drives.interface",
                       .description = KERF_TR_NOOP("SocketCAN interface of the drive bus")}),
        bindField<&MachineConfig::drives, &DrivesConfig::bitrate>(
            kMachine, {.key = "drives.bitrate",
                       .unit = "bit/s",
                       .minimum = 10000.0,
                       .maximum = 1000000.0,
                       .description = KERF_TR_NOOP("Bit rate of the drive bus (a CiA 301 rate)")}),
        bindField<&MachineConfig::drives, &DrivesConfig::cyclePeriodMs>(
            kMachine, {.key = "drives.cycle_period",
                       .unit = "ms",
                       .minimum = 0.1,
                       .maximum = 100.0,
                       .description = KERF_TR_NOOP(
                           "SYNC period of the drive bus; a whole multiple of servo_period")}),
        bindField<&MachineConfig::drives, &DrivesConfig::heartbeatPeriodMs>(
            kMachine, {.key = "drives.heartbeat_period",
                       .unit = "ms",
                       .minimum = 1.0,
                       .maximum = 10000.0,
                       .description = KERF_TR_NOOP("Heartbeat period of every drive (0x1017)")}),
        bindField<&MachineConfig::drives, &DrivesConfig::heartbeatTimeoutMs>(
            kMachine, {.key = "drives.heartbeat_timeout",
                       .unit = "ms",
                       .minimum = 1.0,
                       .maximum = 65535.0,
                       .description = KERF_TR_NOOP(
                           "A drive whose heartbeat is missing this long is lost; above "
                           "heartbeat_period")}),
        bindField<&MachineConfig::drives, &DrivesConfig::pdoLossCycles>(
            kMachine, {.key = "drives.pdo_loss_cycles",
                       .unit = "cycles",
                       .minimum = 1.0,
                       .maximum = 100.0,
                       .description = KERF_TR_NOOP(
                           "A drive whose feedback PDO is missing this many cycles is lost")}),
        bindField<&MachineConfig::drives, &DrivesConfig::masterNode>(
            kMachine, {.key = "drives.master_node",
                       .unit = "node-ID",
                       .minimum = 1.0,
                       .maximum = 127.0,
                       .description = KERF_TR_NOOP(
                           "CANopen node-ID of the control's heartbeat, watched by the drives")}),
        bindField<&MachineConfig::drives, &DrivesConfig::vendorId>(
            kMachine, {.key = "drives.vendor_id",
                       .description = KERF_TR_NOOP(
                           "Vendor-ID every drive must report (0x1018 sub 1), hexadecimal like "
                           "0x0000029C; empty: not checked")}),
        bindField<&MachineConfig::drives, &DrivesConfig::productCode>(
            kMachine, {.key = "drives.product_code",
                       .description = KERF_TR_NOOP(
                           "Product code every drive must report (0x1018 sub 2); empty: not "
                           "checked")}),
    };
    return table;
}

const std::vector<FieldBinding<AxisConfig>>& axisBindings() {
    static const std::vector<FieldBinding<AxisConfig>> table{
        bindField<&AxisConfig::type>(
            kAxis, {.key = "type",
                    .description = KERF_TR_NOOP("Linear or rotary; A, B and C default to rotary")}),
        bindField<&AxisConfig::minLimit>(
            kAxis, {.key = "min_limit",
                    .unit = "mm",
                    .rotaryUnit = "deg",
                    .minimum = -100000.0,
                    .maximum = 100000.0,
                    .description = KERF_TR_NOOP(
                        "Lower soft limit in machine coordinates (a radius on a lathe)")}),
        bindField<&AxisConfig::maxLimit>(
            kAxis, {.key = "max_limit",
                    .unit = "mm",
                    .rotaryUnit = "deg",
                    .minimum = -100000.0,
                    .maximum = 100000.0,
                    .description = KERF_TR_NOOP(
                        "Upper soft limit in machine coordinates (a radius on a lathe)")}),
        bindField<&AxisConfig::maxVelocityPerS>(
            kAxis, {.key = "max_velocity",
                    .unit = "mm/s",
                    .rotaryUnit = "deg/s",
                    .minimum = 0.1,
                    .maximum = 100000.0,
                    .description = KERF_TR_NOOP("Highest velocity of the axis")}),
        bindField<&AxisConfig::maxAccelerationPerS2>(
            kAxis, {.key = "max_acceleration",
                    .unit = "mm/s^2",
                    .rotaryUnit = "deg/s^2",
                    .minimum = 1.0,
                    .maximum = 100000.0,
                    .description = KERF_TR_NOOP("Highest acceleration of the axis")}),
        bindField<&AxisConfig::maxJerkPerS3>(
            kAxis, {.key = "max_jerk",
                    .unit = "mm/s^3",
                    .rotaryUnit = "deg/s^3",
                    .minimum = 1.0,
                    .maximum = 10000000.0,
                    .description = KERF_TR_NOOP("Highest jerk of the axis")}),
        bindField<&AxisConfig::homePosition>(
            kAxis, {.key = "home",
                    .unit = "mm",
                    .rotaryUnit = "deg",
                    .minimum = -100000.0,
                    .maximum = 100000.0,
                    .description = KERF_TR_NOOP(
                        "Machine position after homing; must lie within the soft limits")}),
        bindField<&AxisConfig::homeSequence>(
            kAxis, {.key = "home_sequence",
                    .unit = "order",
                    .rotaryUnit = "order",
                    .minimum = 1.0,
                    .maximum = 9.0,
                    .description = KERF_TR_NOOP(
                        "Order of the axis in Home all: lower numbers are homed first")}),
        bindField<&AxisConfig::presetPosition>(
            kAxis, {.key = "preset",
                    .unit = "mm",
                    .rotaryUnit = "deg",
                    .minimum = -100000.0,
                    .maximum = 100000.0,
                    .description = KERF_TR_NOOP(
                        "Machine coordinate of the workpiece origin (the default preset); kerf "
                        "run --work-offset overrides it")}),
        bindField<&AxisConfig::optional>(
            kAxis, {.key = "optional",
                    .description = KERF_TR_NOOP(
                        "The axis may be absent and is then switched off with enabled = false")}),
        bindField<&AxisConfig::enabled>(
            kAxis, {.key = "enabled",
                    .description =
                        KERF_TR_NOOP("The axis is present; only optional axes may be disabled")}),
        bindField<&AxisConfig::diameterMode>(
            kAxis, {.key = "diameter_mode",
                    .description =
                        KERF_TR_NOOP("Lathe: the axis is programmed and displayed as a diameter")}),
        bindField<&AxisConfig::endless>(
            kAxis, {.key = "endless",
                    .description = KERF_TR_NOOP(
                        "Rotary: turns without end; no soft limits, M126 takes the short way")}),
        bindField<&AxisConfig::driveNode>(
            kAxis, {.key = "drive_node",
                    .unit = "node-ID",
                    .rotaryUnit = "node-ID",
                    .minimum = 0.0,
                    .maximum = 127.0,
                    .description = KERF_TR_NOOP("CANopen node-ID of the axis drive; 0: none")}),
        bindField<&AxisConfig::driveCountsPerUnit>(
            kAxis, {.key = "drive_scale",
                    .unit = "counts/mm",
                    .rotaryUnit = "counts/deg",
                    .minimum = 0.001,
                    .maximum = 1.0e9,
                    .description = KERF_TR_NOOP("Drive position units per millimetre or degree")}),
        bindField<&AxisConfig::followingErrorWindow>(
            kAxis, {.key = "following_error_window",
                    .unit = "mm",
                    .rotaryUnit = "deg",
                    .minimum = 0.001,
                    .maximum = 1000.0,
                    .description = KERF_TR_NOOP(
                        "Following error the drive allows (0x6065) before it faults")}),
    };
    return table;
}

template <typename Owner>
std::vector<ParameterDescriptor> descriptorsOf(const std::vector<FieldBinding<Owner>>& bindings) {
    std::vector<ParameterDescriptor> list;
    list.reserve(bindings.size());
    for (const auto& b : bindings)
        list.push_back(b.descriptor);
    return list;
}

template <typename Owner>
const FieldBinding<Owner>* findBinding(const std::vector<FieldBinding<Owner>>& bindings,
                                       std::string_view key) {
    auto it = std::find_if(bindings.begin(), bindings.end(),
                           [key](const auto& b) { return b.descriptor.key == key; });
    return it == bindings.end() ? nullptr : &*it;
}

// Splits "axes.X.rest" into 'X' and "rest"; false when the key has another shape.
bool splitAxisKey(std::string_view fullKey, char& letter, std::string_view& rest) {
    constexpr std::string_view prefix = "axes.";
    if (fullKey.size() < prefix.size() + 3 || fullKey.substr(0, prefix.size()) != prefix ||
        fullKey[prefix.size() + 1] != '.') {
        return false;
    }
    letter = fullKey[prefix.size()];
    rest = fullKey.substr(prefix.size() + 2);
    return isAxisLetter(letter);
}

Diagnostic schemaError(std::string messageTemplate, std::string_view key) {
    return Diagnostic::make(Severity::Error, "config", "", 0, 0, std::move(messageTemplate),
                            std::string(key));
}

}  // namespace

const std::vector<ParameterDescriptor>& machineParameters() {
    static const std::vector<ParameterDescriptor> list = descriptorsOf(machineBindings());
    return list;
}

const std::vector<ParameterDescriptor>& axisParameters() {
    static const std::vector<ParameterDescriptor> list = descriptorsOf(axisBindings());
    return list;
}

std::string axisParameterKey(char letter, std::string_view axisKey) {
    std::string key = "axes.";
    key += letter;
    key += '.';
    key += axisKey;
    return key;
}

const ParameterDescriptor* findParameter(std::string_view fullKey, char* axisLetter) {
    char letter = 0;
    std::string_view rest;
    if (splitAxisKey(fullKey, letter, rest)) {
        const auto* binding = findBinding(axisBindings(), rest);
        if (binding && axisLetter) *axisLetter = letter;
        return binding ? &binding->descriptor : nullptr;
    }
    const auto* binding = findBinding(machineBindings(), fullKey);
    return binding ? &binding->descriptor : nullptr;
}

std::vector<std::string> parameterKeys(const MachineConfig& config) {
    std::vector<std::string> keys;
    for (const auto& d : machineParameters())
        keys.emplace_back(d.key);
    for (const AxisConfig& axis : config.axes) {
        for (const auto& d : axisParameters())
            keys.push_back(axisParameterKey(axis.letter, d.key));
    }
    return keys;
}

Expected<ParameterValue> getParameter(const MachineConfig& config, std::string_view fullKey) {
    char letter = 0;
    std::string_view rest;
    if (splitAxisKey(fullKey, letter, rest)) {
        const auto* binding = findBinding(axisBindings(), rest);
        if (!binding) return schemaError(KERF_TR_NOOP("unknown key {1}"), fullKey);
        const AxisConfig* axis = config.axis(letter);
        if (!axis) return schemaError(KERF_TR_NOOP("the machine has no axis for {1}"), fullKey);
        return binding->get(*axis);
    }
    const auto* binding = findBinding(machineBindings(), fullKey);
    if (!binding) return schemaError(KERF_TR_NOOP("unknown key {1}"), fullKey);
    return binding->get(config);
}

MaybeError setParameter(MachineConfig& config, std::string_view fullKey,
                        const ParameterValue& value) {
    char letter = 0;
    std::string_view rest;
    if (splitAxisKey(fullKey, letter, rest)) {
        const auto* binding = findBinding(axisBindings(), rest);
        if (!binding) return schemaError(KERF_TR_NOOP("unknown key {1}"), fullKey);
        AxisConfig* axis = config.axis(letter);
        if (!axis) return schemaError(KERF_TR_NOOP("the machine has no axis for {1}"), fullKey);
        if (auto error = checkParameterValue(binding->descriptor, fullKey, value, axis->type)) {
            return error;
        }
        binding->set(*axis, value);
        return std::nullopt;
    }
    const auto* binding = findBinding(machineBindings(), fullKey);
    if (!binding) return schemaError(KERF_TR_NOOP("unknown key {1}"), fullKey);
    if (auto error = checkParameterValue(binding->descriptor, fullKey, value)) return error;
    binding->set(config, value);
    return std::nullopt;
}

}  // namespace kerf::machine
