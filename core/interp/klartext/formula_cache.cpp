#include "core/interp/klartext/formula_cache.h"

#include <functional>

namespace kerf::klartext {

FormulaCache::Entry& FormulaCache::entryFor(std::string_view text) {
    return m_entries[std::hash<std::string_view>{}(text) % kEntries];
}

}  // namespace kerf::klartext
