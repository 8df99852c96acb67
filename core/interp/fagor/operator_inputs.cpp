#include "core/interp/fagor/operator_inputs.h"

#include <algorithm>
#include <cctype>

#include "core/interp/fagor/user_screen.h"

namespace kerf::fagor {

namespace {

bool isNameChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

}  // namespace

std::vector<int> operatorInputsRead(std::string_view text) {
    std::vector<int> found;
    bool quoted = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') quoted = false;
        if (c == '"') quoted = !quoted;
        if (quoted) continue;
        if (c == ';') {
            const size_t end = text.find('\n', i);
            if (end == std::string_view::npos) break;
            i = end - 1;
            continue;
        }
        const bool startsName = i == 0 || !isNameChar(text[i - 1]);
        if (!startsName || i + 2 >= text.size()) continue;
        if (std::toupper(static_cast<unsigned char>(c)) != 'I' ||
            std::toupper(static_cast<unsigned char>(text[i + 1])) != 'B') {
            continue;
        }
        size_t j = i + 2;
        int n = 0;
        while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j])) != 0 &&
               n < UserScreen::kInputs) {
            n = n * 10 + (text[j] - '0');
            ++j;
        }
        if (j == i + 2 || n >= UserScreen::kInputs || (j < text.size() && isNameChar(text[j])))
            continue;
        if (std::find(found.begin(), found.end(), n) == found.end()) found.push_back(n);
        i = j - 1;
    }
    std::sort(found.begin(), found.end());
    return found;
}

}  // namespace kerf::fagor
