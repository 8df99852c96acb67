#include "app/runner/picture_output.h"

#include <cstdio>

namespace kerf::app {

std::optional<std::pair<int, int>> parsePictureSize(const std::string& text) {
    int width = 0;
    int height = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &tail) != 2) return std::nullopt;
    if (width < 16 || height < 16 || width > 8192 || height > 8192) return std::nullopt;
    return std::make_pair(width, height);
}

}  // namespace kerf::app
