#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include <Eigen/Core>

namespace kerf {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

// Programmed axes, in the order the TNC and Fagor displays list them.
enum class Axis : uint8_t { X, Y, Z, A, B, C, U, V, W };
inline constexpr int kAxisCount = 9;

char axisLetter(Axis axis);
// Either case; inline (a table look-up) because every axis word of every block asks.
inline std::optional<Axis> axisFromLetter(char letter) {
    // "XYZABCUVW" by letter from 'A': the axis's index + 1, 0 for a letter that names none.
    constexpr std::array<uint8_t, 26> kByLetter{4, 5, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                                0, 0, 0, 0, 0, 0, 0, 7, 8, 9, 1, 2, 3};
    const auto index = static_cast<unsigned>((letter | 0x20) - 'a');
    if (index >= kByLetter.size() || kByLetter[index] == 0) return std::nullopt;
    return static_cast<Axis>(kByLetter[index] - 1);
}
inline constexpr int axisIndex(Axis axis) {
    return static_cast<int>(axis);
}

// A position of every programmed axis (linear in mm, rotary in degrees).
struct Pose {
    std::array<double, kAxisCount> values{};

    double& operator[](Axis axis) { return values[static_cast<size_t>(axis)]; }
    double operator[](Axis axis) const { return values[static_cast<size_t>(axis)]; }
    Vec3 xyz() const { return {values[0], values[1], values[2]}; }
    void setXyz(const Vec3& p) {
        values[0] = p.x();
        values[1] = p.y();
        values[2] = p.z();
    }
    friend bool operator==(const Pose&, const Pose&) = default;
};

// Bit set of axes (bit i = Axis i).
using AxisMask = uint16_t;
inline constexpr AxisMask axisBit(Axis axis) {
    return static_cast<AxisMask>(1u << axisIndex(axis));
}
inline constexpr AxisMask kXyzMask = axisBit(Axis::X) | axisBit(Axis::Y) | axisBit(Axis::Z);
inline constexpr AxisMask kAllAxesMask = static_cast<AxisMask>((1u << kAxisCount) - 1);
// The axes named by their letters ("XZ"); letters that are not axes are ignored.
AxisMask axisMaskOf(std::string_view letters);

}  // namespace kerf
