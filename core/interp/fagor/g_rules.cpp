#include "core/interp/fagor/g_rules.h"

#include <string>

#include "core/base/translate.h"
#include "core/interp/fagor/g_functions.h"

namespace kerf::fagor {

namespace {

std::string gName(int n) {
    return "G" + std::string(n < 10 ? "0" : "") + std::to_string(n);
}

bool fail(Problem& problem, size_t offset, const char* code, const char* text,
          std::vector<std::string> args) {
    problem = Problem{offset, code, text, std::move(args)};
    return false;
}

// Whether the block holds anything besides `g` and the words `g` takes as arguments.
bool onlyOwnArguments(const IsoBlock& iso, int g) {
    if (iso.gCount > 1 || iso.f.present || iso.t.present || iso.d.present || iso.mCount != 0 ||
        iso.l.present || iso.r.present || iso.q.present || iso.k.present || iso.i2.present ||
        iso.cycle.g >= 0) {
        return false;
    }
    const bool axesAllowed = g == 14 || g == 16 || g == 72 || g == 92 || g == 233;
    const bool sAllowed = g == 72 || g == 92;
    const bool ijAllowed = g == 93;
    if (iso.axisMask != 0 && !axesAllowed) return false;
    if (iso.s.present && !sAllowed) return false;
    if ((iso.i1.present || iso.j.present) && !ijAllowed) return false;
    if (g == 92 && iso.axisMask != 0 && iso.s.present) return false;
    if (g == 72 && iso.axisMask != 0 && iso.s.present) return false;
    return true;
}

}  // namespace

bool checkGFunctions(const IsoBlock& iso, Problem& problem) {
    for (uint8_t i = 0; i < iso.gCount; ++i) {
        const WordValue& w = iso.g[i];
        const int n = static_cast<int>(w.value);
        const GFunction* g = gFunction(n);
        if (g == nullptr) {
            return fail(problem, w.offset, "unknown-g",
                        KERF_TR_NOOP("{1} does not exist on the 8035 T"), {gName(n)});
        }
        if ((g->flags & kNotSupported) != 0) {
            return fail(problem, w.offset, "not-supported",
                        KERF_TR_NOOP("{1} ({2}) is not supported"), {gName(n), g->meaning});
        }
        for (uint8_t j = 0; j < i; ++j) {
            const int m = static_cast<int>(iso.g[j].value);
            const GFunction* other = gFunction(m);
            if (other == nullptr || m == n) continue;
            bool conflict = g->group != GGroup::None && g->group == other->group;
            if (conflict && g->group == GGroup::Mirror) {
                conflict = !((g->flags & kCombinable) != 0 && (other->flags & kCombinable) != 0);
            }
            if (n == 52 || m == 52) {
                const int partner = n == 52 ? m : n;
                conflict = partner == 0 || partner == 2 || partner == 3 || partner == 33 ||
                           partner == 34 || partner == 41 || partner == 42 || partner == 75 ||
                           partner == 76;
            }
            if (n == 75 || n == 76 || m == 75 || m == 76) {
                // Probing moves (spec part 2 §3): not with each other, G00, G02, G03, G33, G34,
                // G41, G42 (nor G52, above); G01 is what they run as.
                const int partner = n == 75 || n == 76 ? m : n;
                conflict = partner == 0 || partner == 2 || partner == 3 || partner == 33 ||
                           partner == 34 || partner == 41 || partner == 42 || partner == 52 ||
                           partner == 75 || partner == 76;
            }
            if (n == 74 || m == 74) conflict = true;
            if (conflict) {
                return fail(problem, w.offset, "incompatible-g",
                            KERF_TR_NOOP("incompatible G functions {1} and {2} (error 7)"),
                            {gName(m), gName(n)});
            }
        }
        const bool plainDwell = n == 4 && !iso.gK.present;
        if (((g->flags & kAlone) != 0 || plainDwell) && !onlyOwnArguments(iso, n)) {
            return fail(problem, w.offset, "alone", KERF_TR_NOOP("{1} must be alone in its block"),
                        {gName(n)});
        }
    }
    return true;
}

}  // namespace kerf::fagor
