#include "core/cycles/probing/measurement_status.h"

#include <cmath>
#include <cstdio>

#include "core/base/translate.h"
#include "core/cycles/probing/probe_sequence.h"

namespace kerf::cycles::probing {

void MeasurementStatus::size(double actual, double max, double min) {
    if (max == 0.0 && min == 0.0) return;
    const bool inside = m_feature == Feature::Inside;
    const bool pattern = m_feature == Feature::Pattern;
    if (actual > max) (inside || pattern ? m_scrap : m_rework) = true;
    if (actual < min) (inside && !pattern ? m_rework : m_scrap) = true;
}

void MeasurementStatus::position(double deviation, double tolerance) {
    if (tolerance > 0.0 && std::fabs(deviation) > tolerance) m_scrap = true;
}

void MeasurementStatus::write(int cycle, const CycleValues& values, ProbingResults& results) const {
    results.set(180, good() ? 1.0 : 0.0);
    results.set(181, m_rework ? 1.0 : 0.0);
    results.set(182, m_scrap ? 1.0 : 0.0);
    if (!good() && values.integer(309) == 1) {
        results.toleranceStop =
            probingError(cycle, "PRB-006", KERF_TR_NOOP("cycle {1}: tolerance exceeded ({2})"),
                         {m_scrap ? "scrap" : "rework"});
    }
}

std::string logLine(const std::string& label, double value) {
    char number[64];
    // A value that rounds to zero prints as +0.0000, never -0.0000.
    std::snprintf(number, sizeof number, "%+.4f", std::fabs(value) < 0.00005 ? 0.0 : value);
    std::string line = label;
    if (line.size() < 28) line.resize(28, ' ');
    return line + number;
}

std::vector<std::string> circleLog(const CircleLog& log) {
    const Vec2 deviation = log.actualCentre - log.nominalCentre;
    return {
        "Nominal values:",
        logLine("  centre main axis", log.nominalCentre.x()),
        logLine("  centre secondary axis", log.nominalCentre.y()),
        logLine("  diameter", log.nominalDiameter),
        "Given limits:",
        logLine("  max. centre main axis", log.nominalCentre.x() + log.centreToleranceMain),
        logLine("  min. centre main axis", log.nominalCentre.x() - log.centreToleranceMain),
        logLine("  max. centre secondary", log.nominalCentre.y() + log.centreToleranceSecondary),
        logLine("  min. centre secondary", log.nominalCentre.y() - log.centreToleranceSecondary),
        logLine("  max. diameter", log.maxDiameter),
        logLine("  min. diameter", log.minDiameter),
        "Actual values:",
        logLine("  centre main axis", log.actualCentre.x()),
        logLine("  centre secondary axis", log.actualCentre.y()),
        logLine("  diameter", log.actualDiameter),
        "Deviations:",
        logLine("  centre main axis", deviation.x()),
        logLine("  centre secondary axis", deviation.y()),
        logLine("  diameter", log.actualDiameter - log.nominalDiameter),
        "Further measuring results:",
        logLine("  measuring height", log.measuringHeight)};
}

}  // namespace kerf::cycles::probing
