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
std::optional<Axis> axisFromLetter(char letter);
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
