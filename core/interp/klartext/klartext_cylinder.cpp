// The cylinder-surface cycles 27, 28, 29 and 39 on a rotary table (spec §7): the cycle expands on
// the development of the cylinder (core/cycles/cylinder), and each point becomes an angle of the
// table that carries the workpiece and a position of the linear axes, written straight into the
// canonical stream (machine axes, like the moves of PLANE ... TURN).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/cycles/cylinder/cylinder_surface.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/workpiece/blank_solids.h"

namespace kerf::klartext {

namespace {

constexpr double kChordToleranceMm = 0.001;  // arcs of the development become chords
constexpr int kMaxChordsPerArc = 100000;
constexpr double kBlankMarginMm = 10.0;  // a derived blank reaches this far past the contour

// The blank a program without BLK FORM gets from its first cylinder-surface cycle [choice]: the
// cylinder of radius Q16 along the table's axis (the workpiece's X for an A table, Z for a C
// table), over the development's v range (the contour plus the tool, the slot's or ridge's half
// width and a margin), so that the test run draws and cuts a cylinder instead of a box derived
// from the feed path.
canon::StockCylinder derivedBlank(Axis along, const cycles::ContourTrain& train, double radiusMm,
                                  double besideMm) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const PlanarSegment& s : train.segments) {
        const double bulge = s.kind == PlanarSegment::Kind::Arc ? s.radius() : 0.0;
        for (const double v : {s.start.y(), s.end.y()}) {
            low = std::min(low, v - bulge);
            high = std::max(high, v + bulge);
        }
    }
    canon::StockCylinder blank;
    blank.axis = along;
    blank.radiusMm = radiusMm;
    blank.distanceMm = high + besideMm + kBlankMarginMm;
    blank.lengthMm = high - low + 2.0 * (besideMm + kBlankMarginMm);
    return blank;
}

}  // namespace

class KlartextInterpreter::CylinderOutput final : public CycleFunctions {
public:
    CylinderOutput(KlartextInterpreter& owner, const cycles::cylinder::CylinderPlacement& placement,
                   const cycles::cylinder::Chain* aligned, double toleranceMm, Axis table,
                   const Vec3& start, const Vec3& headOffset)
        : CycleFunctions(owner),
          m_placement(placement),
          m_aligned(aligned),
          m_tolerance(toleranceMm),
          m_table(table),
          m_local(start),
          m_headOffset(headOffset),
          m_at(owner.m_frame.toWorkpiece(owner.m_programmed)) {}

    void rapid(const Vec3& target) override { go(target, true, 0.0); }
    void line(const Vec3& target, const cycles::Feed& feed) override {
        if (ok()) go(target, feed.isRapid(), m.cycleFeed(feed));
    }
    void arc(const Vec3& target, const Vec2& center, double sweepRad,
             const cycles::Feed& feed) override {
        if (!ok()) return;
        const double f = m.cycleFeed(feed);
        const Vec2 from{m_local.x(), m_local.y()};
        const Vec2 r0 = from - center;
        const double radius = r0.norm();
        const double step =
            radius > m_tolerance ? 2.0 * std::acos(1.0 - m_tolerance / radius) : std::numbers::pi;
        const int pieces = std::clamp(static_cast<int>(std::ceil(std::fabs(sweepRad) / step)), 1,
                                      kMaxChordsPerArc);
        const double w0 = m_local.z();
        for (int i = 1; i <= pieces && ok(); ++i) {
            const double t = static_cast<double>(i) / pieces;
            const double a = sweepRad * t;
            const Vec2 p = i == pieces ? Vec2(target.x(), target.y())
                                       : center + Vec2(std::cos(a) * r0.x() - std::sin(a) * r0.y(),
                                                       std::sin(a) * r0.x() + std::cos(a) * r0.y());
            go({p.x(), p.y(), w0 + (target.z() - w0) * t}, feed.isRapid(), f);
        }
    }
    void threadMove(const Vec3&, double, double) override {
        m.fail("cycle", KERF_TR_NOOP("a thread cannot be cut on the development of a cylinder"));
    }

private:
    void go(const Vec3& local, bool rapid, double feed) {
        if (!ok()) return;
        const cycles::cylinder::CylinderPose pose =
            cycles::cylinder::placeOnCylinder(m_placement, local, m_aligned);
        const double preset = m.m_settings.presetInMachine[m_table];
        if (!m_turns) {
            // The table takes the turn of the first angle nearest to where it stands.
            const double current = m_at[m_table] + preset;
            m_turns = 360.0 * std::round((current - pose.angleDeg) / 360.0);
        }
        Pose target = m_at;
        target.setXyz(pose.linear + m_headOffset);
        target[m_table] = pose.angleDeg + *m_turns - preset;
        // F is the feed on the surface: the stream's feed runs along the linear axes (along the
        // rotary one when they stand still), so it is scaled by that length over the unrolled one.
        const double unrolled = (local - m_local).norm();
        const double linear = (target.xyz() - m_at.xyz()).norm();
        const double stream = linear > 1e-9 ? linear : std::fabs(target[m_table] - m_at[m_table]);
        if (!rapid && unrolled > 1e-9) feed *= stream / unrolled;
        m_local = local;
        if (!m.rotaryWithinLimits(m.m_frame.toProgram(target))) return;
        m.emitStreamMove(m_at, target, rapid, rapid ? m.m_feed : feed);
        m_at = target;
        m.m_programmed = m.m_frame.toProgram(m_at);
    }

    cycles::cylinder::CylinderPlacement m_placement;
    const cycles::cylinder::Chain* m_aligned;
    double m_tolerance;
    Axis m_table;
    Vec3 m_local;
    Vec3 m_headOffset;  // a turned swivel head: the linear axes beside the tip
    Pose m_at;          // stream coordinates
    std::optional<double> m_turns;
};

std::unique_ptr<cycles::CycleEmitter> KlartextInterpreter::cylinderOutput(
    const cycles::CycleValues& values, cycles::CycleContext& ctx) {
    const cycles::CycleDescriptor& d = *m_cycle->descriptor;
    const std::string number = std::to_string(d.number);
    // Spec §7: a rotary table carries the cylinder, the tool perpendicular to its axis.
    if (!m_kinematics || !m_kinematics->hasTable()) {
        fail("not-supported",
             KERF_TR_NOOP("cycle {1} needs a rotary table described in the machine file "
                          "([kinematics], docs/machine-config.md)"),
             {number});
        return nullptr;
    }
    if (m_tcpm) {
        fail("cycle", KERF_TR_NOOP("cycle {1} cannot run with M128/FUNCTION TCPM active"),
             {number});
        return nullptr;
    }
    const machine::RotaryAngles angles = currentTableAngles();
    cycles::cylinder::CylinderPlacement placement;
    placement.axis = m_kinematics->innerTableAxis(angles);
    placement.tool = m_kinematics->headTurn(angles) * Vec3::UnitZ();
    if (m_toolAxis != Axis::Z || std::fabs(placement.axis.dot(placement.tool)) > 1e-6) {
        fail("cycle",
             KERF_TR_NOOP("cycle {1}: the tool axis must be perpendicular to the axis of rotary "
                          "table {2} (tilt the table or the head first, e.g. with PLANE)"),
             {number, std::string(1, m_kinematics->innerTable())});
        return nullptr;
    }
    placement.axis -= placement.axis.dot(placement.tool) * placement.tool;
    placement.axis.normalize();
    placement.radiusMm = values.number(16);
    // The cylinder stands centred on the table: its axis is the table's axis, and the
    // development's Y counts from where the preset lies along it.
    const Vec3 preset = m_settings.presetInMachine.xyz() + m_frame.preset().xyz();
    const double length = m_tool.effectiveLength();
    const Vec3 headOffset = m_kinematics->headOffset(angles, length);
    const Vec3 presetNow =
        m_kinematics->axesOf(Vec3::Zero(), angles, preset, length) - headOffset + preset;
    const Vec3& pivot = m_kinematics->pivot();
    placement.origin = pivot + placement.axis * placement.axis.dot(presetNow - pivot) -
                       m_settings.presetInMachine.xyz();

    if (!captureTrain(d.number, ctx.train)) return nullptr;
    const double q21 = d.number == 28 ? values.number(21) : 0.0;
    const double tolerance = q21 > 0.0 ? std::min(q21, kChordToleranceMm) : kChordToleranceMm;
    if (placement.radiusMm > 0.0) {
        ctx.train = cycles::cylinder::unrolledInMm(ctx.train, placement.radiusMm,
                                                   values.integer(17) == 0, tolerance);
    }
    const Axis table = *axisFromLetter(m_kinematics->innerTable());
    // An A, B or C table turns the cylinder about the workpiece's X, Y or Z; the development's v
    // is then the workpiece's coordinate along it when the preset lies on the table's axis.
    const int along = axisIndex(table) - axisIndex(Axis::A);
    Vec3 offAxis = preset - pivot;
    offAxis[along] = 0.0;
    if (!m_blank && offAxis.norm() < 1e-6 && placement.radiusMm > 0.0 &&
        !ctx.train.segments.empty()) {
        const double slot = d.number == 28 || d.number == 29 ? std::fabs(values.number(20)) : 0.0;
        const canon::StockDefinition blank{
            derivedBlank(static_cast<Axis>(along), ctx.train, placement.radiusMm,
                         2.0 * m_tool.effectiveRadius() + slot / 2.0)};
        emit(blank);
        m_blank = workpiece::blankSolids(blank);
    }
    const Pose at = m_frame.toWorkpiece(m_programmed);
    const Vec3 fromAxis = at.xyz() - headOffset - placement.origin;
    const double angle = at[table] + m_settings.presetInMachine[table];
    ctx.start =
        Vec3(std::remainder(angle, 360.0) * std::numbers::pi / 180.0 * placement.radiusMm,
             fromAxis.dot(placement.axis), fromAxis.dot(placement.tool) - placement.radiusMm);

    const bool aligned = d.number != 27;
    return std::make_unique<CylinderOutput>(*this, placement,
                                            aligned ? &ctx.train.segments : nullptr, tolerance,
                                            table, ctx.start, headOffset);
}

}  // namespace kerf::klartext
