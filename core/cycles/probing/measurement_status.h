#pragma once

#include <string>
#include <vector>

#include "core/cycles/probing/probing_cycle.h"
#include "core/geometry/axes.h"

namespace kerf::cycles::probing {

// Tolerance monitoring of the measuring cycles (spec 1.13): collects the monitored quantities,
// then sets Q180 (good), Q181 (rework), Q182 (scrap) and, with Q309 = 1, the program stop.
class MeasurementStatus {
public:
    // Pattern: the diameter of a bolt-hole circle (430), scrap either way.
    enum class Feature : uint8_t { Inside, Outside, Pattern };
    explicit MeasurementStatus(Feature feature) : m_feature(feature) {}

    // A size with limits `max`, `min` (both 0: not monitored).
    void size(double actual, double max, double min);
    // A position deviation with a tolerance (0: not monitored): beyond it is scrap.
    void position(double deviation, double tolerance);

    bool good() const { return !m_rework && !m_scrap; }
    void write(int cycle, const CycleValues& values, ProbingResults& results) const;

private:
    Feature m_feature;
    bool m_rework = false;
    bool m_scrap = false;
};

// "label   value" with 4 decimals, the line format of the measuring logs (spec 1.15).
std::string logLine(const std::string& label, double value);

// The measuring log of a circle (421, 422, 430): nominal centre and diameter with the limits,
// actual values, deviations, and the measuring height (spec 1.15).
struct CircleLog {
    Vec2 nominalCentre;
    double nominalDiameter = 0.0;
    double centreToleranceMain = 0.0;       // Q279
    double centreToleranceSecondary = 0.0;  // Q280
    double maxDiameter = 0.0;
    double minDiameter = 0.0;
    Vec2 actualCentre;
    double actualDiameter = 0.0;
    double measuringHeight = 0.0;  // Q261
};
std::vector<std::string> circleLog(const CircleLog& log);

}  // namespace kerf::cycles::probing
