#include "core/canon/value_limits.h"

#include <cmath>
#include <variant>

namespace kerf::canon {

namespace {

constexpr const char* kAxisNames[kAxisCount] = {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"};
constexpr const char* kCentreNames[3] = {"arc centre X", "arc centre Y", "arc centre Z"};

// Collects the first unsafe number; `!(|v| <= limit)` is also true for NaN.
class Inspector {
public:
    void check(const char* quantity, double value) {
        if (!m_found && !(std::fabs(value) <= kMaxStreamMagnitude)) {
            m_found = UnsafeValue{quantity, value};
        }
    }
    void check(const Pose& pose) {
        // Every move has a pose: one pass without branches, and the names only for a bad one.
        bool safe = true;
        for (double value : pose.values)
            safe &= std::fabs(value) <= kMaxStreamMagnitude;
        if (safe) return;
        for (size_t i = 0; i < pose.values.size(); ++i)
            check(kAxisNames[i], pose.values[i]);
    }
    void check(const char* const (&names)[3], const Vec3& v) {
        for (int i = 0; i < 3; ++i)
            check(names[i], v[i]);
    }
    void check(const ToolGeometry& g) {
        check("tool length", g.lengthMm);
        check("tool radius", g.radiusMm);
        check("tool radius 2", g.radius2Mm);
        check("tool tip X", g.tipXMm);
        check("tool tip Z", g.tipZMm);
    }

    void operator()(const RapidMove& c) { check(c.target); }
    void operator()(const LinearMove& c) {
        check(c.target);
        check("feed", c.feed);
    }
    void operator()(const ArcMove& c) {
        check(c.target);
        check(kCentreNames, c.center);
        check("arc angle", c.sweepRad);
        check("feed", c.feed);
    }
    void operator()(const SpindleSyncedMove& c) {
        check(c.target);
        check("lead", c.leadMmPerRev);
        check("spindle angle", c.startAngleDeg);
        check("lead change", c.leadChangeMmPerRev);
    }
    void operator()(const Dwell& c) { check("dwell time", c.seconds); }
    void operator()(const SpindleControl& c) {
        check("spindle speed", c.speedRpm);
        check("surface speed", c.surfaceSpeedMPerMin);
        check("spindle speed limit", c.maxRpm);
    }
    void operator()(const SpindleOrient& c) { check("spindle angle", c.angleDeg); }
    void operator()(const ToolChange& c) { check(c.geometry); }
    void operator()(const ToolUpdate& c) { check(c.geometry); }
    void operator()(const ProbeMove& c) {
        check(c.target);
        check("feed", c.feed);
    }
    void operator()(const StockDefinition& c) {
        if (const auto* box = std::get_if<StockBox>(&c.shape)) {
            static constexpr const char* kMin[3] = {"blank X", "blank Y", "blank Z"};
            check(kMin, box->min);
            check(kMin, box->max);
        } else if (const auto* revolved = std::get_if<StockRevolved>(&c.shape)) {
            static constexpr const char* kPoint[3] = {"blank X", "blank Y", "blank Z"};
            for (const Vec3& p : revolved->outline)
                check(kPoint, p);
        } else {
            const auto& cylinder = std::get<StockCylinder>(c.shape);
            check("blank radius", cylinder.radiusMm);
            check("blank inner radius", cylinder.innerRadiusMm);
            check("blank length", cylinder.lengthMm);
            check("blank distance", cylinder.distanceMm);
        }
    }
    void operator()(const ThreadRetraction& c) { check(c.distance); }
    void operator()(const PathTolerance& c) { check("path tolerance", c.toleranceMm); }
    // Commands without numbers.
    void operator()(const CoolantControl&) {}
    void operator()(const SetFeedMode&) {}
    void operator()(const SyncPoint&) {}
    void operator()(const Message&) {}
    void operator()(const ProgramStop&) {}
    void operator()(const MachineFunction&) {}
    void operator()(const DiameterMode&) {}
    void operator()(const ControlLocks&) {}

    const std::optional<UnsafeValue>& found() const { return m_found; }

private:
    std::optional<UnsafeValue> m_found;
};

}  // namespace

std::optional<UnsafeValue> findUnsafeValue(const CommandBody& body) {
    Inspector inspector;
    std::visit(inspector, body);
    return inspector.found();
}

}  // namespace kerf::canon
