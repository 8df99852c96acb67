#include "core/machine/machine_schema.h"

#include <set>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "core/machine/machine_validation.h"

namespace kerf::machine {
namespace {

std::vector<const ParameterDescriptor*> allDescriptors() {
    std::vector<const ParameterDescriptor*> list;
    for (const auto& d : machineParameters())
        list.push_back(&d);
    for (const auto& d : axisParameters())
        list.push_back(&d);
    return list;
}

TEST(MachineSchema, EveryDefaultIsInsideItsRange) {
    for (const ParameterDescriptor* d : allDescriptors()) {
        SCOPED_TRACE(std::string(d->key));
        for (AxisType type : {AxisType::Linear, AxisType::Rotary}) {
            MaybeError error = checkParameterValue(*d, d->key, d->defaultValue, type);
            EXPECT_FALSE(error) << error->message();
        }
        if (d->type == ParameterType::Number || d->type == ParameterType::Integer) {
            EXPECT_LT(d->minimum, d->maximum);
        }
    }
}

TEST(MachineSchema, EveryDescriptorIsComplete) {
    std::set<std::string_view> keys;
    for (const ParameterDescriptor* d : allDescriptors()) {
        SCOPED_TRACE(std::string(d->key));
        EXPECT_TRUE(keys.insert(d->key).second) << "duplicate key";
        EXPECT_FALSE(std::string_view(d->description).empty());
        EXPECT_EQ(std::string_view(d->description).find('\n'), std::string_view::npos);
        bool numeric = d->type == ParameterType::Number || d->type == ParameterType::Integer;
        EXPECT_EQ(d->unit.empty(), !numeric) << "numbers have units, other values none";
        if (d->scope == ParameterScope::Axis) {
            EXPECT_EQ(d->rotaryUnit.empty(), !numeric);
        }
        EXPECT_EQ(d->enumValues.empty(), d->type != ParameterType::Enum);
    }
    for (const auto& d : machineParameters())
        EXPECT_EQ(d.scope, ParameterScope::Machine);
    for (const auto& d : axisParameters())
        EXPECT_EQ(d.scope, ParameterScope::Axis);
}

TEST(MachineSchema, DefaultsAreThoseOfTheStructs) {
    MachineConfig config;
    config.axes = {defaultAxis('X'), defaultAxis('C')};
    for (const auto& d : machineParameters()) {
        EXPECT_EQ(getParameter(config, d.key).value(), d.defaultValue) << d.key;
    }
    for (const auto& d : axisParameters()) {
        if (d.key == "type") continue;
        EXPECT_EQ(getParameter(config, axisParameterKey('X', d.key)).value(), d.defaultValue);
        EXPECT_EQ(getParameter(config, axisParameterKey('C', d.key)).value(), d.defaultValue);
    }
    EXPECT_EQ(getParameter(config, "axes.X.type").value(), ParameterValue(std::string("linear")));
    EXPECT_EQ(getParameter(config, "axes.C.type").value(), ParameterValue(std::string("rotary")));
    EXPECT_EQ(config.servoPeriodMs, 1.0);
    EXPECT_EQ(config.pathToleranceMm, 0.01);
}

TEST(MachineSchema, DescribesTypesUnitsAndRanges) {
    const ParameterDescriptor* d = findParameter("axes.X.max_acceleration");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->key, "max_acceleration");
    EXPECT_EQ(d->type, ParameterType::Number);
    EXPECT_EQ(parameterUnit(*d, AxisType::Linear), "mm/s^2");
    EXPECT_EQ(parameterUnit(*d, AxisType::Rotary), "deg/s^2");
    EXPECT_EQ(formatAllowedValues(*d), "1 … 100000 mm/s^2");
    const ParameterDescriptor* rpm = findParameter("spindle.max_rpm");
    ASSERT_NE(rpm, nullptr);
    EXPECT_EQ(rpm->type, ParameterType::Integer);
    const ParameterDescriptor* kind = findParameter("kind");
    ASSERT_NE(kind, nullptr);
    EXPECT_EQ(kind->enumValues, (std::vector<std::string_view>{"mill", "lathe"}));
    EXPECT_EQ(formatAllowedValues(*findParameter("axes.A.enabled")), "true, false");
    EXPECT_EQ(findParameter("axes.Q.max_velocity"), nullptr);
    EXPECT_EQ(findParameter("axes.X.speed"), nullptr);
    EXPECT_EQ(findParameter("spindle"), nullptr);
    char letter = 0;
    EXPECT_NE(findParameter("axes.W.home", &letter), nullptr);
    EXPECT_EQ(letter, 'W');
}

TEST(MachineSchema, ListsEveryKeyOfAMachine) {
    MachineConfig lathe = loadMachine("lathe").value();
    std::vector<std::string> keys = parameterKeys(lathe);
    EXPECT_EQ(keys.size(), machineParameters().size() + 3 * axisParameters().size());
    EXPECT_EQ(keys.front(), "name");
    EXPECT_EQ(keys.back(), "axes.C.following_error_window");
    for (const std::string& key : keys)
        EXPECT_TRUE(getParameter(lathe, key).ok()) << key;
}

TEST(MachineSchema, GetAndSetByKey) {
    MachineConfig mill = loadMachine("mill").value();
    EXPECT_EQ(getParameter(mill, "axes.Y.min_limit").value(), ParameterValue(-300.0));
    EXPECT_EQ(getParameter(mill, "spindle.max_rpm").value(), ParameterValue(int64_t{12000}));
    EXPECT_EQ(getParameter(mill, "tool_axis").value(), ParameterValue(std::string("Z")));

    EXPECT_FALSE(setParameter(mill, "axes.X.max_velocity", 123.5));
    EXPECT_EQ(mill.axis('X')->maxVelocityPerS, 123.5);
    EXPECT_FALSE(setParameter(mill, "rapid_velocity", int64_t{400}));  // integer for a number
    EXPECT_EQ(mill.rapidVelocityMmPerS, 400.0);
    EXPECT_FALSE(setParameter(mill, "spindle.min_rpm", int64_t{100}));
    EXPECT_EQ(mill.spindle.minRpm, 100);
    EXPECT_FALSE(setParameter(mill, "kind", std::string("lathe")));
    EXPECT_EQ(mill.kind, MachineKind::Lathe);
    EXPECT_FALSE(setParameter(mill, "tool_axis", std::string("X")));
    EXPECT_EQ(mill.toolAxis, 'X');
    EXPECT_FALSE(setParameter(mill, "axes.Z.optional", true));
    EXPECT_TRUE(mill.axis('Z')->optional);
    EXPECT_FALSE(setParameter(mill, "name", std::string("Renamed")));
    EXPECT_EQ(mill.name, "Renamed");
}

TEST(MachineSchema, SetRejectsBadValuesAndKeepsTheOldOne) {
    MachineConfig mill = loadMachine("mill").value();
    MachineConfig before = mill;
    auto message = [](const MaybeError& error) { return error ? error->message() : "(none)"; };
    EXPECT_EQ(message(setParameter(mill, "axes.X.max_acceleration", -5.0)),
              "axes.X.max_acceleration = -5 is outside the allowed range 1 … 100000 mm/s^2");
    EXPECT_EQ(message(setParameter(mill, "spindle.max_rpm", 2.5)),
              "spindle.max_rpm = 2.5 has the wrong type; expected an integer");
    EXPECT_EQ(message(setParameter(mill, "spindle.max_rpm", int64_t{1} << 40)),
              "spindle.max_rpm = 1099511627776 is outside the allowed range 0 … 100000 rpm");
    EXPECT_EQ(message(setParameter(mill, "kind", std::string("router"))),
              "kind = \"router\" is not one of mill, lathe");
    EXPECT_EQ(message(setParameter(mill, "axes.X.enabled", std::string("yes"))),
              "axes.X.enabled = \"yes\" has the wrong type; expected true or false");
    EXPECT_EQ(message(setParameter(mill, "axes.A.max_velocity", 1.0)),
              "the machine has no axis for axes.A.max_velocity");
    EXPECT_EQ(message(setParameter(mill, "axes.X.speed", 1.0)), "unknown key axes.X.speed");
    EXPECT_EQ(message(setParameter(mill, "spindle", 1.0)), "unknown key spindle");
    EXPECT_EQ(mill, before);
    EXPECT_FALSE(getParameter(mill, "axes.B.home").ok());
}

TEST(MachineSchema, ValidationOfProgrammaticConfigs) {
    MachineConfig config = loadMachine("mill").value();
    EXPECT_TRUE(validateMachine(config).empty());
    config.axes.push_back(defaultAxis('X'));
    config.axes.push_back(defaultAxis('Q'));
    config.rapidVelocityMmPerS = 0.0;
    DiagnosticList problems = validateMachine(config, "ui");
    std::vector<std::string> lines;
    for (const Diagnostic& d : problems)
        lines.push_back(d.format());
    EXPECT_EQ(lines, (std::vector<std::string>{
                         "ui: error: rapid_velocity = 0 is outside the allowed range 0.1 … 5000 "
                         "mm/s",
                         "ui: error: axis X is listed twice",
                         "ui: error: axis letter Q is not one of X, Y, Z, A, B, C, U, V, W"}));
}

TEST(MachineSchema, FormatsNumbersShortAndWithAnExponentOnlyWhenHugeOrTiny) {
    EXPECT_EQ(formatNumber(-5.0), "-5");
    EXPECT_EQ(formatNumber(0.01), "0.01");
    EXPECT_EQ(formatNumber(100000.0), "100000");
    EXPECT_EQ(formatNumber(10000000.0), "10000000");
    EXPECT_EQ(formatNumber(0.1 + 0.2), "0.30000000000000004");
    EXPECT_EQ(formatNumber(-0.0), "0");
    // Huge and tiny values in exponent form, which TOML reads back.
    EXPECT_EQ(formatNumber(1e300), "1e+300");
    EXPECT_EQ(formatNumber(-2.5e-9), "-2.5e-09");
    EXPECT_EQ(formatParameterValue(std::string("a \"b\"\\\n")), "\"a \\\"b\\\"\\\\\\n\"");
}

}  // namespace
}  // namespace kerf::machine
