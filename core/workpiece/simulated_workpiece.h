#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "core/geometry/axes.h"
#include "core/workpiece/removed_material.h"
#include "core/workpiece/tool_sweep.h"

namespace kerf::workpiece {

// Shapes in the blank's programmed position, workpiece coordinates with the tool axis along z
// (a sphere: cycle 460's calibration sphere).
struct Box {
    Vec3 min{0.0, 0.0, 0.0};
    Vec3 max{0.0, 0.0, 0.0};
};
// A cylinder about a line parallel to `axis` (the tool axis unless told), from `axialMin` to
// `axialMax` along it. `centre` places the line in the other two axes, in the order x, y, z
// leaves them (Z: x y, X: y z, Y: x z): a blank lying on an A or B table.
struct Cylinder {
    Vec2 centre{0.0, 0.0};
    double radius = 0.0;
    double axialMin = 0.0;
    double axialMax = 0.0;
    Axis axis = Axis::Z;
};

struct Sphere {
    Vec3 centre{0.0, 0.0, 0.0};
    double radius = 0.0;
};

// Material (the blank, a stud) or a cavity cut out of it (a hole, a pocket).
struct Solid {
    std::variant<Box, Cylinder, Sphere> shape;
    bool material = true;
};

// How the real part lies compared with its programmed position: rotated by `rotationDeg` about
// the tool axis through the programmed origin, then shifted by `shift`. `origin` is where the
// solids' programmed origin lies in the coordinates of the touches (0 when they are the same).
struct Placement {
    Vec3 shift{0.0, 0.0, 0.0};
    double rotationDeg = 0.0;
    Vec3 origin{0.0, 0.0, 0.0};
};

// The part a simulated touch probe touches: solids combined as (union of material) minus (union
// of cavities), placed with a setup error the program does not know, minus what the program's
// tools removed (in the coordinates of the touches: the tools cut the part where it really is). Qt-
// and VTK-free, so the headless run, the simulated machine and the graphics can share it.
class SimulatedWorkpiece {
public:
    SimulatedWorkpiece() = default;
    explicit SimulatedWorkpiece(Placement placement);

    void add(const Solid& solid);
    void setRemoved(std::shared_ptr<const RemovedMaterial> removed) {
        m_removed = std::move(removed);
    }
    bool empty() const { return m_solids.empty(); }
    const Placement& placement() const { return m_placement; }

    // Where a ball of `radius` whose centre starts at `start` and moves along the unit vector
    // `direction` first touches the material: the ball centre at contact, or nothing when it
    // travels `maxPath` freely. Coordinates are those of the machine (the real part's frame).
    std::optional<Vec3> touch(const Vec3& start, const Vec3& direction, double maxPath,
                              double radius) const;
    // True when the ball already touches or penetrates material (a deflected stylus).
    bool touches(const Vec3& centre, double radius) const;

    // A cutter moving at rapid from tip `from` to tip `to` (the coordinates of touches) takes
    // material: a point of its end face that lies kCollisionDepth inside the cutter (the face
    // kCollisionDepth above the tip, shrunk by as much, sampled at its centre and at most
    // kCollisionSpacing apart on its rim) passes through material. Rims, not the body above:
    // a rapid meets material with its end first.
    bool rapidTakesMaterial(const Cutter& cutter, const Vec3& from, const Vec3& to) const;
    // [choice] Less than this (mm) into the material is grazing, not a collision: a rapid
    // retract along a wall the same tool finished touches it exactly.
    static constexpr double kCollisionDepth = 0.01;
    static constexpr double kCollisionSpacing = 1.0;

    // Where the free space is the union of several tool sweeps and the ball is wider than the
    // depth of any single one, the distance bound says "contact" too early; the ball is then
    // looked at on cells down to this size (mm), which bounds the error of such a contact.
    static constexpr double kCoverageResolution = 1e-4;

private:
    // The bound says the ball touches: true when a material point within `radius` lies just
    // past the nearest surface point the bound's gradient points to.
    bool nearestMaterialFound(const Vec3& centre, double radius) const;
    // True when no material lies within `radius` of the segment from `a` to `b` (of `a` when they
    // are the same), proven on an octree of cells down to kCoverageResolution; a cell that
    // cannot be decided there, or a proof of more than 200 000 cells, counts as material.
    bool provenFree(const Vec3& a, const Vec3& b, double radius) const;
    // How far the ball may move along `direction`, at most `limit`, proven free; 0 when it
    // cannot move.
    double provenClearance(const Vec3& centre, const Vec3& direction, double radius,
                           double limit) const;
    bool hasCuts() const { return m_removed && !m_removed->empty(); }

    // A lower bound of the distance from `p` to the material, negative inside; exact at faces
    // away from the edges where two solids meet.
    double distance(const Vec3& p) const;
    // The same for the blank before any cut (the material lies within it): cheaper.
    double blankDistance(const Vec3& p) const;
    // True when the segment from `a` to `b` passes through material.
    bool segmentInMaterial(const Vec3& a, const Vec3& b) const;
    // True when the disc of radius `rim` square to z, its centre moving from `a` to `b`, passes
    // through material: its centre or a point of its rim (at most kCollisionSpacing apart).
    bool faceInMaterial(const Vec3& a, const Vec3& b, double rim) const;

    Placement m_placement;
    // The placement's rotation undone (blankDistance runs for every point a query looks at).
    double m_cosBack = 1.0;
    double m_sinBack = 0.0;
    std::vector<Solid> m_solids;
    // The highest z of the material solids where the part really lies: a rapid above it is free.
    double m_materialTop = -std::numeric_limits<double>::infinity();
    std::shared_ptr<const RemovedMaterial> m_removed;
};

}  // namespace kerf::workpiece
