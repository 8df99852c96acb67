#pragma once

// Binds a schema entry to a struct member through a chain of member pointers, so that each
// parameter is listed exactly once: bindField<&MachineConfig::spindle, &SpindleConfig::maxRpm>(...)
// yields its descriptor (default read from a default-constructed owner) and typed get/set.

#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/machine/machine_config.h"
#include "core/machine/parameter_descriptor.h"

namespace kerf::machine::detail {

// Converts between a member type and ParameterValue. set() receives a value that
// checkParameterValue() accepted.
template <typename T>
struct FieldCodec;

template <>
struct FieldCodec<double> {
    static constexpr ParameterType type = ParameterType::Number;
    static ParameterValue get(double v) { return v; }
    static void set(double& field, const ParameterValue& v) {
        const auto* integer = std::get_if<int64_t>(&v);
        field = integer ? static_cast<double>(*integer) : std::get<double>(v);
    }
};

template <>
struct FieldCodec<int> {
    static constexpr ParameterType type = ParameterType::Integer;
    static ParameterValue get(int v) { return int64_t{v}; }
    // The range check keeps the value inside int.
    static void set(int& field, const ParameterValue& v) {
        field = static_cast<int>(std::get<int64_t>(v));
    }
};

template <>
struct FieldCodec<bool> {
    static constexpr ParameterType type = ParameterType::Bool;
    static ParameterValue get(bool v) { return v; }
    static void set(bool& field, const ParameterValue& v) { field = std::get<bool>(v); }
};

template <>
struct FieldCodec<std::string> {
    static constexpr ParameterType type = ParameterType::String;
    static ParameterValue get(const std::string& v) { return v; }
    static void set(std::string& field, const ParameterValue& v) {
        field = std::get<std::string>(v);
    }
};

// Enumerations are stored as their index into `names()`.
template <typename E>
struct EnumCodec {
    static constexpr ParameterType type = ParameterType::Enum;
    static ParameterValue get(E v) {
        return std::string(FieldCodec<E>::names()[static_cast<size_t>(v)]);
    }
    static void set(E& field, const ParameterValue& v) {
        const auto& names = FieldCodec<E>::names();
        for (size_t i = 0; i < names.size(); ++i) {
            if (names[i] == std::get<std::string>(v)) field = static_cast<E>(i);
        }
    }
};

template <>
struct FieldCodec<MachineKind> : EnumCodec<MachineKind> {
    static const std::vector<std::string_view>& names() {
        static const std::vector<std::string_view> list{"mill", "lathe"};
        return list;
    }
};

template <>
struct FieldCodec<AxisType> : EnumCodec<AxisType> {
    static const std::vector<std::string_view>& names() {
        static const std::vector<std::string_view> list{"linear", "rotary"};
        return list;
    }
};

template <>
struct FieldCodec<SpindleDriveMode> : EnumCodec<SpindleDriveMode> {
    static const std::vector<std::string_view>& names() {
        static const std::vector<std::string_view> list{"csv", "pv"};
        return list;
    }
};

template <>
struct FieldCodec<ToolProbeShape> : EnumCodec<ToolProbeShape> {
    static const std::vector<std::string_view>& names() {
        static const std::vector<std::string_view> list{"disc", "cube"};
        return list;
    }
};

template <>
struct FieldCodec<KinematicsType> : EnumCodec<KinematicsType> {
    static const std::vector<std::string_view>& names() {
        static const std::vector<std::string_view> list{"none", "table", "table-table",
                                                        "head-table", "head-head"};
        return list;
    }
};

// A char member holds an axis letter, written as a one-letter string.
template <>
struct FieldCodec<char> {
    static constexpr ParameterType type = ParameterType::Enum;
    static const std::vector<std::string_view>& names() {
        static const std::vector<std::string_view> list{"X", "Y", "Z", "A", "B",
                                                        "C", "U", "V", "W"};
        return list;
    }
    static ParameterValue get(char v) { return std::string(1, v); }
    static void set(char& field, const ParameterValue& v) { field = std::get<std::string>(v)[0]; }
};

template <typename T>
concept HasNames = requires {
    T::names();
};

template <typename M>
struct MemberPointer;
template <typename Owner, typename T>
struct MemberPointer<T Owner::*> {
    using OwnerType = Owner;
};

// The table entry: descriptor plus typed access to the member it describes.
template <typename Owner>
struct FieldBinding {
    ParameterDescriptor descriptor;
    ParameterValue (*get)(const Owner&) = nullptr;
    void (*set)(Owner&, const ParameterValue&) = nullptr;
};

// What a table entry states by hand; type, default and enum values come from the member.
struct FieldSpec {
    std::string_view key;
    std::string_view unit = {};
    std::string_view rotaryUnit = {};
    double minimum = 0.0;
    double maximum = 0.0;
    const char* description = "";
};

template <auto First, auto... Rest>
struct MemberChain {
    using Owner = typename MemberPointer<decltype(First)>::OwnerType;
    template <typename O>
    static auto& access(O& owner) {
        return ((owner.*First).*....*Rest);
    }
    using Value = std::remove_cvref_t<decltype(access(std::declval<Owner&>()))>;
};

template <auto... Members>
FieldBinding<typename MemberChain<Members...>::Owner> bindField(ParameterScope scope,
                                                                const FieldSpec& spec) {
    using Chain = MemberChain<Members...>;
    using Owner = typename Chain::Owner;
    using Codec = FieldCodec<typename Chain::Value>;
    FieldBinding<Owner> binding;
    ParameterDescriptor& d = binding.descriptor;
    d.key = spec.key;
    d.scope = scope;
    d.type = Codec::type;
    d.unit = spec.unit;
    d.rotaryUnit = spec.rotaryUnit;
    const Owner defaults{};
    d.defaultValue = Codec::get(Chain::access(defaults));
    d.minimum = spec.minimum;
    d.maximum = spec.maximum;
    if constexpr (HasNames<Codec>) d.enumValues = Codec::names();
    d.description = spec.description;
    binding.get = [](const Owner& owner) { return Codec::get(Chain::access(owner)); };
    binding.set = [](Owner& owner, const ParameterValue& v) {
        Codec::set(Chain::access(owner), v);
    };
    return binding;
}

}  // namespace kerf::machine::detail
