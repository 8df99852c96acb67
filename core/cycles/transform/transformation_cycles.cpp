// Cycles 7, 8, 10, 11, 26 (spec §9): their sub-blocks applied to the coordinate frame, and their
// catalogue entries (with 247 PRESETTING and 19 WORKING PLANE).
#include "core/cycles/transform/transformation_cycles.h"

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/cycles/common_parameters.h"
#include "core/cycles/cycle_descriptor.h"
#include "core/cycles/detail/cycle_list.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr double kMinScale = 0.000001;
constexpr double kMaxScale = 99.999999;

CycleError badWord(int cycle, const CycleWord& word) {
    return {"cycle-syntax",
            KERF_TR_NOOP("cycle {1}: unexpected '{2}'"),
            {std::to_string(cycle), (word.incremental ? "I" : "") + word.key}};
}

CycleError missingValue(int cycle, const std::string& key) {
    return {
        "cycle-syntax", KERF_TR_NOOP("cycle {1}: {2} needs a value"), {std::to_string(cycle), key}};
}

std::optional<CycleError> checkScale(int cycle, const std::string& what, double value) {
    if (value >= kMinScale && value <= kMaxScale) return std::nullopt;
    return CycleError{"cycle-range",
                      KERF_TR_NOOP("cycle {1}: scaling factor {2} = {3} is outside 0.000001 to "
                                   "99.999999"),
                      {std::to_string(cycle), what, formatFixed(value, 6)}};
}

constexpr ParameterDescriptor kShift[] = {
    {.word = "X",
     .description = KERF_TR_NOOP("Datum shift per axis (IX: incremental), or #n: "
                                 "datum number of the datum table"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength}};
constexpr ParameterDescriptor kMirror[] = {
    {.word = "X", .description = KERF_TR_NOOP("Mirrored axes (none: mirroring off)")}};
constexpr ParameterDescriptor kRotation[] = {
    {.word = "ROT",
     .description = KERF_TR_NOOP("Angle of rotation (IROT: incremental)"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0}};
constexpr ParameterDescriptor kScaling[] = {{.word = "SCL",
                                             .description = KERF_TR_NOOP("Scaling factor"),
                                             .unit = Unit::Factor,
                                             .min = kMinScale,
                                             .max = kMaxScale,
                                             .defaultValue = 1.0}};
constexpr ParameterDescriptor kAxisScaling[] = {
    {.word = "X",
     .description = KERF_TR_NOOP("Scaling factor per axis"),
     .unit = Unit::Factor,
     .min = kMinScale,
     .max = kMaxScale,
     .defaultValue = 1.0},
    {.word = "CCX",
     .description = KERF_TR_NOOP("Centre of the scaling per axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength}};
constexpr ParameterDescriptor kPresetting[] = {
    {.q = 339,
     .description = KERF_TR_NOOP("Number of the preset to activate"),
     .min = 0.0,
     .max = 65535.0,
     .integer = true}};
constexpr ParameterDescriptor kWorkingPlane[] = {
    {.word = "A",
     .description = KERF_TR_NOOP("Tilt angles of the rotary axes"),
     .unit = Unit::Degrees,
     .min = -360.0,
     .max = 360.0},
    {.word = "F",
     .description = KERF_TR_NOOP("Feed rate for automatic positioning"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kFeed},
    {.word = "DIST",
     .description = KERF_TR_NOOP("Set-up clearance for automatic positioning"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength}};

}  // namespace

std::optional<Axis> wordAxis(const CycleWord& word, bool& incremental) {
    incremental = word.incremental;
    if (word.key.size() != 1) return std::nullopt;
    return axisFromLetter(word.key[0]);
}

std::optional<CycleError> applyDatumShift(CoordinateFrame& frame, const CycleWords& words) {
    for (const CycleWord& w : words) {
        bool incremental = false;
        auto axis = wordAxis(w, incremental);
        if (!axis) return badWord(7, w);
        if (!w.value) return missingValue(7, w.key);
        frame.setShift(*axis, *w.value, incremental);
    }
    return std::nullopt;
}

std::optional<CycleError> applyMirror(CoordinateFrame& frame, const CycleWords& words,
                                      Axis toolAxis, bool& toolAxisIgnored) {
    AxisMask mask = 0;
    toolAxisIgnored = false;
    for (const CycleWord& w : words) {
        bool incremental = false;
        auto axis = wordAxis(w, incremental);
        if (!axis || incremental || w.value) return badWord(8, w);
        if (*axis == toolAxis) {
            toolAxisIgnored = true;
            continue;
        }
        mask = static_cast<AxisMask>(mask | axisBit(*axis));
    }
    frame.setMirror(mask);
    return std::nullopt;
}

std::optional<CycleError> applyRotation(CoordinateFrame& frame, const CycleWords& words,
                                        Plane plane) {
    for (const CycleWord& w : words) {
        if (w.key != "ROT") return badWord(10, w);
        if (!w.value) return missingValue(10, "ROT");
        if (*w.value < -360.0 || *w.value > 360.0) {
            return CycleError{"cycle-range",
                              KERF_TR_NOOP("cycle {1}: angle of rotation ROT = {2} is outside "
                                           "-360 to 360"),
                              {"10", formatFixed(*w.value, 4)}};
        }
        frame.setRotation(*w.value, w.incremental, plane);
    }
    return std::nullopt;
}

std::optional<CycleError> applyScaling(CoordinateFrame& frame, const CycleWords& words) {
    for (const CycleWord& w : words) {
        if (w.key != "SCL" || w.incremental) return badWord(11, w);
        if (!w.value) return missingValue(11, "SCL");
        if (auto e = checkScale(11, "SCL", *w.value)) return e;
        frame.setScale(*w.value);
    }
    return std::nullopt;
}

std::optional<CycleError> applyAxisScaling(CoordinateFrame& frame, const CycleWords& words) {
    for (const CycleWord& w : words) {
        if (!w.value) return missingValue(26, w.key);
        if (w.key.size() == 3 && w.key.compare(0, 2, "CC") == 0) {
            auto axis = axisFromLetter(w.key[2]);
            if (!axis || w.incremental) return badWord(26, w);
            frame.setAxisScaleCentre(*axis, *w.value);
            continue;
        }
        bool incremental = false;
        auto axis = wordAxis(w, incremental);
        if (!axis || incremental || !isLinearAxis(*axis)) return badWord(26, w);
        if (auto e = checkScale(26, w.key, *w.value)) return e;
        frame.setAxisScale(*axis, *w.value);
    }
    return std::nullopt;
}

const CycleDescriptor kCycle7{.number = 7,
                              .name = KERF_TR_NOOP("DATUM SHIFT"),
                              .activation = Activation::Def,
                              .group = CycleGroup::Transformation,
                              .oldStyle = true,
                              .parameters = kShift};
const CycleDescriptor kCycle8{.number = 8,
                              .name = KERF_TR_NOOP("MIRROR IMAGE"),
                              .activation = Activation::Def,
                              .group = CycleGroup::Transformation,
                              .oldStyle = true,
                              .parameters = kMirror};
const CycleDescriptor kCycle10{.number = 10,
                               .name = KERF_TR_NOOP("ROTATION"),
                               .activation = Activation::Def,
                               .group = CycleGroup::Transformation,
                               .oldStyle = true,
                               .parameters = kRotation};
const CycleDescriptor kCycle11{.number = 11,
                               .name = KERF_TR_NOOP("SCALING"),
                               .activation = Activation::Def,
                               .group = CycleGroup::Transformation,
                               .oldStyle = true,
                               .parameters = kScaling};
const CycleDescriptor kCycle26{.number = 26,
                               .name = KERF_TR_NOOP("AXIS-SPECIFIC SCALING"),
                               .activation = Activation::Def,
                               .group = CycleGroup::Transformation,
                               .oldStyle = true,
                               .parameters = kAxisScaling};
const CycleDescriptor kCycle247{.number = 247,
                                .name = KERF_TR_NOOP("PRESETTING"),
                                .activation = Activation::Def,
                                .group = CycleGroup::Transformation,
                                .parameters = kPresetting};
const CycleDescriptor kCycle19{.number = 19,
                               .name = KERF_TR_NOOP("WORKING PLANE"),
                               .activation = Activation::Def,
                               .group = CycleGroup::Transformation,
                               .oldStyle = true,
                               .parameters = kWorkingPlane};

}  // namespace kerf::cycles
