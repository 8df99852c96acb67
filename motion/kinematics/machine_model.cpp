#include "motion/kinematics/machine_model.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace kerf::motion {

MachineModel makeMachineModel(const machine::MachineConfig& config, const MotionOptions& options) {
    MachineModel model;
    model.options = options;
    model.jointAxis.fill(-1);
    double minJerk = 1e300;
    for (const machine::AxisConfig& axis : config.axes) {
        auto index = axisFromLetter(axis.letter);
        if (!index || !axis.enabled) continue;
        AxisModel& m = model.axes[static_cast<size_t>(axisIndex(*index))];
        m.enabled = true;
        m.rotary = axis.type == machine::AxisType::Rotary;
        // An endless rotary axis has no soft limits (1e9 deg: far beyond any program).
        m.minLimit = axis.endless ? -1e9 : axis.minLimit;
        m.maxLimit = axis.endless ? 1e9 : axis.maxLimit;
        m.velocity = axis.maxVelocityPerS;
        m.accel = axis.maxAccelerationPerS2;
        m.jerk = axis.maxJerkPerS3;
        m.home = axis.homePosition;
        m.homeSequence = axis.homeSequence;
        if (!m.rotary) minJerk = std::min(minJerk, m.jerk);
    }
    for (int i = 0; i < kAxisCount; ++i) {
        if (model.axes[static_cast<size_t>(i)].enabled) {
            model.jointAxis[static_cast<size_t>(model.jointCount++)] = i;
        }
    }
    model.homingCount = model.jointCount;
    std::iota(model.homingOrder.begin(), model.homingOrder.begin() + model.homingCount, 0);
    // jointAxis is in display order, so a stable sort keeps it within one sequence number.
    std::stable_sort(model.homingOrder.begin(), model.homingOrder.begin() + model.homingCount,
                     [&model](int a, int b) {
                         auto sequence = [&model](int joint) {
                             const int axis = model.jointAxis[static_cast<size_t>(joint)];
                             return model.axes[static_cast<size_t>(axis)].homeSequence;
                         };
                         return sequence(a) < sequence(b);
                     });
    model.spindleJoint = model.jointCount++;
    if (auto tool = axisFromLetter(config.toolAxis)) model.toolAxis = axisIndex(*tool);
    model.periodS = config.servoPeriodMs / 1000.0;
    model.rapidVelocity = config.rapidVelocityMmPerS;
    model.maxFeed = config.maxFeedMmPerS;
    model.toleranceMm = config.pathToleranceMm;
    model.spindleMaxRpm = config.spindle.maxRpm;
    // The moving average turns a curvature step of a = v^2 / R into a ramp of jerk a / T and
    // cuts arcs by a T^2 / 24; T = cbrt(24 tol / J) balances both at the tolerance.
    double filterTime = options.filterTimeS;
    if (filterTime <= 0.0 && minJerk < 1e300)
        filterTime = std::cbrt(24.0 * model.toleranceMm / minJerk);
    model.filterTaps = std::max(1, static_cast<int>(std::lround(filterTime / model.periodS)));
    return model;
}

double jointFromAxis(const MachineModel& model, int axis, double tip, double toolLength) noexcept {
    double joint = tip + model.options.workOffset[static_cast<size_t>(axis)];
    if (axis == model.toolAxis) joint += toolLength;
    return joint;
}

double axisFromJoint(const MachineModel& model, int axis, double joint,
                     double toolLength) noexcept {
    double tip = joint - model.options.workOffset[static_cast<size_t>(axis)];
    if (axis == model.toolAxis) tip -= toolLength;
    return tip;
}

}  // namespace kerf::motion
