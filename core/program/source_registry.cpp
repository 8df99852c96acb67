#include "core/program/source_registry.h"

#include <algorithm>

namespace kerf::program {

uint32_t SourceRegistry::add(std::string path) {
    auto it = std::find(m_paths.begin(), m_paths.end(), path);
    if (it != m_paths.end()) return static_cast<uint32_t>(it - m_paths.begin());
    m_paths.push_back(std::move(path));
    return static_cast<uint32_t>(m_paths.size() - 1);
}

std::string SourceRegistry::displayName(uint32_t id) const {
    const std::string& p = m_paths.at(id);
    size_t slash = p.find_last_of('/');
    return slash == std::string::npos ? p : p.substr(slash + 1);
}

}  // namespace kerf::program
