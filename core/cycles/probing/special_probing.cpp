// The special probing cycles of spec 5: 441 FAST PROBING (settings for the following cycles)
// and 444 PROBING IN 3-D (one point of a surface checked along its normal).
#include <cstdlib>

#include "core/cycles/probing/measurement_status.h"
#include "core/cycles/probing/probe_sequence.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor k441Parameters[] = {
    {.q = 396,
     .description = KERF_TR_NOOP("Positioning feed rate of the probe (FMAX: rapid traverse)"),
     .unit = Unit::FeedPerMinute,
     .min = 0.0,
     .max = kLength,
     .keywords = kFeedMax | kFeedAuto},
    choice(397, KERF_TR_NOOP("Pre-position at machine rapid: 0 no (Q396), 1 yes"), 0, 1, 0),
    choice(399, KERF_TR_NOOP("Angle tracking: 0 no, 1 orient the probe before each touch"), 0, 1,
           0),
    choice(400, KERF_TR_NOOP("Automatic interruption: 0 never, 1 when a cycle shows its log"), 0, 1,
           1)};

std::optional<CycleError> run441(const CycleValues& v, const ProbeData&, ProbingMachine&,
                                 ProbingResults& results) {
    FastProbing settings;
    settings.positioning = v.feed(396);
    settings.machineRapid = v.integer(397) == 1;
    settings.tracking = v.integer(399) == 1;
    settings.interrupt = v.integer(400) == 1;
    results.fastProbing = settings;
    return std::nullopt;
}

constexpr ParameterDescriptor normal(uint16_t q, const char* description) {
    return {.q = q, .description = description, .min = -10.0, .max = 10.0};
}

constexpr ParameterDescriptor k444Parameters[] = {
    length(263, KERF_TR_NOOP("Nominal point, main axis")),
    length(264, KERF_TR_NOOP("Nominal point, secondary axis")),
    length(294, KERF_TR_NOOP("Nominal point, tool axis")),
    normal(581, KERF_TR_NOOP("Surface normal, main axis component")),
    normal(582, KERF_TR_NOOP("Surface normal, secondary axis component")),
    normal(583, KERF_TR_NOOP("Surface normal, tool axis component")),
    kSetUpClearance,
    kClearanceHeight,
    {.q = 400,
     .description = KERF_TR_NOOP("Tolerance along the normal, e.g. \"0.4-0.1\""),
     .unit = Unit::Text,
     .optional = true},
    choice(309, KERF_TR_NOOP("Tolerance error: 0 nothing, 1 stop, 2 stop on undersize only"), 0, 2,
           0)};

constexpr uint16_t k444Results[] = {151, 152, 153, 161, 162, 163, 164, 183};

// QS400 (spec 5, 444): "[+]upper[-lower]" or "-lower"; anything else (also "nan", "inf"), or
// all zero, is no tolerance. Limits are signed deviations along the normal.
struct NormalTolerance {
    double upper = 0.0;
    double lower = 0.0;
    bool set = false;
};

NormalTolerance parseNormalTolerance(const std::string& text) {
    size_t start = text.find_first_not_of(' ');
    const size_t stop = text.find_last_not_of(' ');
    if (start == std::string::npos) return {};
    const std::string body = text.substr(start, stop - start + 1);
    auto number = [](const char* from, const char** end) {
        char* e = nullptr;
        const double value = std::strtod(from, &e);
        *end = std::isfinite(value) ? e : from;  // not finite: as if nothing was read
        return value;
    };
    NormalTolerance t;
    const char* at = body.c_str();
    const char* end = at;
    if (*at != '-') {
        t.upper = number(at, &end);
        if (end == at || t.upper < 0.0) return {};
        at = end;
    }
    if (*at == '-') {
        const char* from = at + 1;
        t.lower = -number(from, &end);
        if (end == from || t.lower > 0.0) return {};
        at = end;
    }
    if (*at != '\0') return {};
    t.set = t.upper != 0.0 || t.lower != 0.0;
    return t;
}

std::optional<CycleError> run444(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    const Vec3 n(v.number(581), v.number(582), v.number(583));
    if (n.norm() < 1e-9) {
        return probingError(444, "PRB-008",
                            KERF_TR_NOOP("cycle {1}: the surface normal Q581..Q583 is zero"));
    }
    const Vec3 normalUnit = n.normalized();
    const Vec3 nominal(v.number(263), v.number(264), v.number(294));
    ProbeSequence sequence(444, v, probe, machine);
    const Vec3 start = nominal + sequence.standOff() * normalUnit;
    Vec3 ball;
    if (auto e = sequence.touchFromPoint(start, -normalUnit, ball)) return e;
    const Vec3 touched = ball - probe.ballRadius * normalUnit;
    const Vec3 deviation = touched - nominal;
    const double along = deviation.dot(normalUnit);
    const NormalTolerance tolerance = parseNormalTolerance(v.text(400));
    int status = 0;
    if (tolerance.set && along > tolerance.upper) status = 1;  // oversize: rework
    if (tolerance.set && along < tolerance.lower) status = 2;  // undersize: scrap
    for (int i = 0; i < 3; ++i) {
        results.set(static_cast<uint16_t>(151 + i), touched[i]);
        results.set(static_cast<uint16_t>(161 + i), deviation[i]);
    }
    results.set(164, along);
    results.set(183, status);
    std::vector<std::string> log{"Nominal values:", logLine("point, main axis", nominal.x()),
                                 logLine("point, secondary axis", nominal.y()),
                                 logLine("point, tool axis", nominal.z())};
    if (tolerance.set) {
        log.push_back("Given limits along the normal:");
        log.push_back(logLine("upper limit", tolerance.upper));
        log.push_back(logLine("lower limit", tolerance.lower));
    }
    log.insert(
        log.end(),
        {"Actual values:", logLine("point, main axis", touched.x()),
         logLine("point, secondary axis", touched.y()), logLine("point, tool axis", touched.z()),
         "Deviations:", logLine("along the normal", along),
         std::string("Status: ") + (status == 0   ? "good"
                                    : status == 1 ? "rework"
                                                  : "scrap"),
         "Probing direction:", logLine("main axis", -normalUnit.x() * probe.maxPath),
         logLine("secondary axis", -normalUnit.y() * probe.maxPath),
         logLine("tool axis", -normalUnit.z() * probe.maxPath)});
    results.protocol = std::move(log);
    const int reaction = v.integer(309);
    if ((reaction == 1 && status != 0) || (reaction == 2 && status == 2)) {
        results.toleranceStop =
            probingError(444, "PRB-006", KERF_TR_NOOP("cycle {1}: tolerance exceeded ({2})"),
                         {status == 2 ? "scrap" : "rework"});
    }
    return std::nullopt;
}

}  // namespace

const ProbingCycleDescriptor kProbe441{
    441, KERF_TR_NOOP("FAST PROBING"), k441Parameters, run441, {}};
const ProbingCycleDescriptor kProbe444{444, KERF_TR_NOOP("PROBING IN 3-D"), k444Parameters, run444,
                                       k444Results};

}  // namespace kerf::cycles::probing
