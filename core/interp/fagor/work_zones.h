#pragma once

#include <array>
#include <optional>

#include "core/geometry/contour_element.h"

namespace kerf::fagor {

// The work zones of G20, G21 and G22 (spec part 1 §6.8): limits per axis in machine coordinates
// (radius), only the programmed axes limited; each zone disabled, no-entry or no-exit. Zone 5
// exists only as variables (the PLC sets it) and stays disabled here.
class WorkZones {
public:
    static constexpr int kCount = 5;
    enum class Mode : uint8_t { Disabled = 0, NoEntry = 1, NoExit = 2 };

    void setLower(int zone, Axis axis, double value);
    void setUpper(int zone, Axis axis, double value);
    void setMode(int zone, Mode mode);

    Mode mode(int zone) const;
    std::optional<double> lower(int zone, Axis axis) const;
    std::optional<double> upper(int zone, Axis axis) const;
    bool anyEnabled() const;

    // The first zone the tip path (machine coordinates) violates, or nothing; lines and arcs are
    // checked exactly (every axis, including those moving along with an arc).
    std::optional<int> violation(const ContourElement& path) const;

private:
    struct Zone {
        std::array<std::optional<double>, kAxisCount> lower{};
        std::array<std::optional<double>, kAxisCount> upper{};
        Mode mode = Mode::Disabled;
    };
    bool inside(const Zone& zone, const Pose& p) const;
    bool enters(const Zone& zone, const ContourElement& path) const;
    bool leaves(const Zone& zone, const ContourElement& path) const;

    std::array<Zone, kCount> m_zones{};
};

}  // namespace kerf::fagor
