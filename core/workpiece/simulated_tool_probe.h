#pragma once

#include <optional>

#include "core/geometry/axes.h"

namespace kerf::workpiece {

// The stylus of a tool touch probe (TT): a disc, or a cube with sides along x and y, whose
// measuring surface (the top face) is centred on `top`; its sides reach down without end.
struct ToolProbeStylus {
    Vec3 top{0.0, 0.0, 0.0};
    double diameter = 0.0;  // a cube's side
    bool cube = false;
};

// The real tool in the spindle: a cylinder about the tool axis (z) whose flat end face lies
// `length` below the spindle's gauge point and whose radius is `radius` (a rotating tool sweeps
// that cylinder with its longest tooth; the simulation gives every tooth the same size).
struct RealTool {
    double length = 0.0;
    double radius = 0.0;
    // A touch probe's ball centre off the spindle axis at spindle angle 0 (x, y); it turns with
    // the spindle. The TT's tools run true.
    Vec2 centreOffset{0.0, 0.0};
};

// A simulated TT in machine coordinates: where the real tool touches the stylus. Qt- and VTK-free.
class SimulatedToolProbe {
public:
    explicit SimulatedToolProbe(ToolProbeStylus stylus) : m_stylus(stylus) {}

    // Where the gauge point, starting at `gauge` and moving along the unit vector `direction`,
    // is when the tool first touches the stylus, or nothing when it travels `maxPath` freely.
    std::optional<Vec3> touch(const Vec3& gauge, const Vec3& direction, double maxPath,
                              const RealTool& tool) const;
    // True when the tool already touches the stylus (a deflected TT).
    bool touches(const Vec3& gauge, const RealTool& tool) const;

private:
    // The distance between tool and stylus, negative when they overlap; exact where a face or
    // the rim of the disc is nearest.
    double distance(const Vec3& gauge, const RealTool& tool) const;

    ToolProbeStylus m_stylus;
};

}  // namespace kerf::workpiece
