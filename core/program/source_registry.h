#pragma once

#include <string>
#include <vector>

namespace kerf::program {

// Numbers the files a run reads so that canonical commands carry a small file id. Id 0 is the
// main program.
class SourceRegistry {
public:
    uint32_t add(std::string path);
    const std::string& path(uint32_t id) const { return m_paths.at(id); }
    // The file name without folders, as traces and messages show it.
    std::string displayName(uint32_t id) const;
    size_t size() const { return m_paths.size(); }

private:
    std::vector<std::string> m_paths;
};

}  // namespace kerf::program
