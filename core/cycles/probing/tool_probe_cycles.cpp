// The descriptors of the TT cycles 480-483 (spec 7); the old cycles 30-33 run as these.
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor kCheckMode =
    choice(340, KERF_TR_NOOP("Tool measurement: 0 write L/R, 1 compare and write DL/DR, 2 compare"),
           0, 2, 0);
constexpr ParameterDescriptor kProbeTeeth =
    choice(341, KERF_TR_NOOP("Probe each tooth: 0 no, 1 yes"), 0, 1, 0);

constexpr ParameterDescriptor kCalibrateParameters[] = {kClearanceHeight};
constexpr ParameterDescriptor kWirelessParameters[] = {choice(
    536, KERF_TR_NOOP("Stop before running: 0 stop to position the tool, 1 no stop"), 0, 1, 0)};
constexpr ParameterDescriptor kMeasureParameters[] = {kCheckMode, kClearanceHeight, kProbeTeeth};
constexpr uint16_t kLengthResults[] = {115, 199};
constexpr uint16_t kRadiusResults[] = {116, 199};
constexpr uint16_t kToolResults[] = {115, 116, 199};

}  // namespace

const ProbingCycleDescriptor kProbe480{.number = 480,
                                       .name = KERF_TR_NOOP("CALIBRATE TT"),
                                       .parameters = kCalibrateParameters,
                                       .run = nullptr,
                                       .results = {},
                                       .toolMeasurement = ToolMeasurementKind::Calibrate};
const ProbingCycleDescriptor kProbe481{.number = 481,
                                       .name = KERF_TR_NOOP("TOOL LENGTH"),
                                       .parameters = kMeasureParameters,
                                       .run = nullptr,
                                       .results = kLengthResults,
                                       .toolMeasurement = ToolMeasurementKind::Length};
const ProbingCycleDescriptor kProbe482{.number = 482,
                                       .name = KERF_TR_NOOP("TOOL RADIUS"),
                                       .parameters = kMeasureParameters,
                                       .run = nullptr,
                                       .results = kRadiusResults,
                                       .toolMeasurement = ToolMeasurementKind::Radius};
const ProbingCycleDescriptor kProbe483{.number = 483,
                                       .name = KERF_TR_NOOP("MEASURE TOOL"),
                                       .parameters = kMeasureParameters,
                                       .run = nullptr,
                                       .results = kToolResults,
                                       .toolMeasurement = ToolMeasurementKind::LengthAndRadius};

// 484 calibrates from where the operator put the calibration pin (the interpreter takes its
// height as the clearance height) after a stop with Q536 = 0.
const ProbingCycleDescriptor kProbe484{.number = 484,
                                       .name = KERF_TR_NOOP("CALIBRATE IR TT"),
                                       .parameters = kWirelessParameters,
                                       .run = nullptr,
                                       .results = {},
                                       .toolMeasurement = ToolMeasurementKind::Calibrate};

}  // namespace kerf::cycles::probing
