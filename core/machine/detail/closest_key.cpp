#include "core/machine/detail/closest_key.h"

#include <algorithm>

namespace kerf::machine::detail {

namespace {

// Levenshtein distance; keys are short, so the plain two-row algorithm is enough.
size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<size_t> previous(b.size() + 1);
    std::vector<size_t> current(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j)
        previous[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

}  // namespace

std::string_view closestKey(std::string_view typed,
                            const std::vector<std::string_view>& candidates) {
    // Allow one edit per three characters, at most two, so short keys are not "corrected" wildly.
    size_t allowed = std::clamp<size_t>(typed.size() / 3, 1, 2);
    std::string_view best;
    size_t bestDistance = allowed + 1;
    for (std::string_view candidate : candidates) {
        size_t distance = editDistance(typed, candidate);
        if (distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

}  // namespace kerf::machine::detail
