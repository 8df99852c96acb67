#include "core/cycles/pattern/pattern_definition.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/base/saturating.h"
#include "core/base/translate.h"

namespace kerf::cycles {

namespace {

constexpr size_t kMaxPoints = 100000;

Vec2 direction(double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    return {std::cos(a), std::sin(a)};
}

std::optional<double> surfaceOf(const PatternElement::Word& z) {
    if (!z.present || z.value == 0.0) return std::nullopt;
    return z.value;
}

std::optional<CycleError> count(const PatternElement::Word& word, const char* name, int& out) {
    out = word.present ? saturatingInt(std::round(word.value)) : 0;
    if (out >= 1 && out <= 99999 && std::fabs(word.value - out) < 1e-9) return std::nullopt;
    return CycleError{"pattern",
                      KERF_TR_NOOP("PATTERN DEF: {1} must be a whole number from 1 to "
                                   "99999"),
                      {name}};
}

std::optional<CycleError> tooMany() {
    return CycleError{"pattern",
                      KERF_TR_NOOP("PATTERN DEF: more than {1} positions"),
                      {std::to_string(kMaxPoints)}};
}

}  // namespace

std::optional<CycleError> patternPoints(const std::vector<PatternElement>& elements,
                                        std::vector<PatternPoint>& points) {
    points.clear();
    Vec2 last(0.0, 0.0);
    double lastZ = 0.0;
    for (const PatternElement& e : elements) {
        const Vec2 origin(e.x.value, e.y.value);
        const std::optional<double> surface = surfaceOf(e.z);
        auto add = [&](const Vec2& p, std::optional<double> s) {
            if (points.size() >= kMaxPoints) return false;
            points.push_back({p, s, 0.0});
            return true;
        };
        switch (e.kind) {
            case PatternElement::Kind::Pos: {
                Vec2 p(e.x.incremental ? last.x() + e.x.value : e.x.value,
                       e.y.incremental ? last.y() + e.y.value : e.y.value);
                if (!e.x.present) p.x() = last.x();
                if (!e.y.present) p.y() = last.y();
                double z = e.z.incremental ? lastZ + e.z.value : (e.z.present ? e.z.value : lastZ);
                last = p;
                lastZ = z;
                if (!add(p, z != 0.0 ? std::optional<double>(z) : std::nullopt)) return tooMany();
                break;
            }
            case PatternElement::Kind::Row: {
                int n = 0;
                if (auto err = count(e.num, "NUM", n)) return err;
                const Vec2 step = e.d.value * direction(e.rot.value);
                for (int i = 0; i < n; ++i) {
                    if (!add(origin + static_cast<double>(i) * step, surface)) return tooMany();
                }
                break;
            }
            case PatternElement::Kind::Pat:
            case PatternElement::Kind::Frame: {
                int nx = 0, ny = 0;
                if (auto err = count(e.numX, "NUMX", nx)) return err;
                if (auto err = count(e.numY, "NUMY", ny)) return err;
                const Vec2 along = e.dx.value * direction(e.rot.value + e.rotX.value);
                const Vec2 across = e.dy.value * direction(90.0 + e.rot.value + e.rotY.value);
                const bool frame = e.kind == PatternElement::Kind::Frame;
                for (int j = 0; j < ny; ++j) {
                    for (int i = 0; i < nx; ++i) {
                        const bool edge = i == 0 || j == 0 || i == nx - 1 || j == ny - 1;
                        if (frame && !edge) continue;
                        const Vec2 p = origin + static_cast<double>(i) * along +
                                       static_cast<double>(j) * across;
                        if (!add(p, surface)) return tooMany();
                    }
                }
                break;
            }
            case PatternElement::Kind::Circ:
            case PatternElement::Kind::PitchCirc: {
                int n = 0;
                if (auto err = count(e.num, "NUM", n)) return err;
                const double step = e.kind == PatternElement::Kind::Circ ? 360.0 / n : e.step.value;
                for (int i = 0; i < n; ++i) {
                    const Vec2 p =
                        origin +
                        e.d.value / 2.0 * direction(e.start.value + step * static_cast<double>(i));
                    if (!add(p, surface)) return tooMany();
                }
                break;
            }
        }
    }
    return std::nullopt;
}

}  // namespace kerf::cycles
