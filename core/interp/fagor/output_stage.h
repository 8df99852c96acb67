#pragma once

#include <array>
#include <optional>

#include "core/canon/commands.h"
#include "core/interp/fagor/work_zones.h"
#include "core/interp/path/path_move.h"
#include "core/interp/path/value_guard.h"

namespace kerf::fagor {

// The last stage before the canonical stream: applies the per-axis scale factors of G72 X..C to
// the computed displacements (spec part 1 §10.5, after compensation), checks the tip path against
// the enabled work zones before anything moves, and sums the distance each axis travels (DIST).
// A command with a number outside the canonical stream's range is refused, before and after
// scaling.
class OutputStage final : public canon::Sink {
public:
    void setTarget(canon::Sink* target) { m_target = target; }
    void reset(const Pose& position);
    // Machine coordinates = stream coordinates + offset (the zero offset the run started with).
    void setMachineOffset(const Pose& offset) { m_machineOffset = offset; }
    void setZones(const WorkZones* zones) { m_zones = zones; }
    // Factor 1 switches the axis's scaling off; otherwise displacements from the axis's present
    // position on are multiplied by the factor.
    void setAxisScale(Axis axis, double factor);
    double axisScale(Axis axis) const { return m_scale[static_cast<size_t>(axisIndex(axis))]; }

    void consume(const canon::Command& command) override;

    // A zone violation, an arc that per-axis scaling would distort or a number out of range;
    // later commands are dropped.
    std::optional<interp::PathError> takeError();
    bool failed() const { return m_failed; }
    const Pose& position() const { return m_position; }
    double distance(Axis axis) const { return m_distance[static_cast<size_t>(axisIndex(axis))]; }
    void setDistance(Axis axis, double value) {
        m_distance[static_cast<size_t>(axisIndex(axis))] = value;
    }

private:
    bool scaling() const { return m_scaledAxes != 0; }
    Pose scaled(const Pose& p) const;
    bool check(const ContourElement& path, const SourceLocation& at);
    bool refuseUnsafe(const canon::Command& command);
    void addDistance(const ContourElement& path);

    canon::Sink* m_target = nullptr;
    Pose m_position{};  // last output position
    Pose m_unscaled{};  // the same before per-axis scaling
    Pose m_machineOffset{};
    const WorkZones* m_zones = nullptr;
    std::array<double, kAxisCount> m_scale{1, 1, 1, 1, 1, 1, 1, 1, 1};
    std::array<double, kAxisCount> m_anchorOut{};
    std::array<double, kAxisCount> m_anchorProgrammed{};
    AxisMask m_scaledAxes = 0;
    std::array<double, kAxisCount> m_distance{};
    std::optional<interp::PathError> m_error;
    bool m_failed = false;
};

}  // namespace kerf::fagor
