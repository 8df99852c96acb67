#include "core/interp/klartext/statement_axes.h"

#include <cstring>

namespace kerf::klartext {

namespace {

const Coordinates* coordinatesOf(const Statement& statement) {
    return std::visit(
        [](const auto& block) -> const Coordinates* {
            using T = std::decay_t<decltype(block)>;
            if constexpr (std::is_same_v<T, LinearBlock> || std::is_same_v<T, LineNormalBlock> ||
                          std::is_same_v<T, CircleCenter> || std::is_same_v<T, CircleBlock> ||
                          std::is_same_v<T, CircleRadiusBlock> ||
                          std::is_same_v<T, CircleTangentBlock> ||
                          std::is_same_v<T, LinePolarBlock> ||
                          std::is_same_v<T, CirclePolarBlock> ||
                          std::is_same_v<T, CircleTangentPolarBlock> ||
                          std::is_same_v<T, ApproachBlock>) {
                return &block.coords;
            } else {
                return nullptr;
            }
        },
        statement);
}

}  // namespace

std::optional<Axis> axisMissingFrom(const Statement& statement, AxisMask machineAxes) {
    const Coordinates* coords = coordinatesOf(statement);
    if (coords == nullptr) return std::nullopt;
    const AxisMask missing = static_cast<AxisMask>(coords->present & ~machineAxes);
    if (missing == 0) return std::nullopt;
    for (int i = 0; i < kAxisCount; ++i) {
        if ((missing & axisBit(static_cast<Axis>(i))) != 0) return static_cast<Axis>(i);
    }
    return std::nullopt;
}

uint32_t columnOfAxisWord(std::string_view text, Axis axis) {
    const char letter = axisLetter(axis);
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != letter || i + 1 >= text.size()) continue;
        const bool wordStart =
            i == 0 || text[i - 1] == ' ' || (text[i - 1] == 'I' && (i == 1 || text[i - 2] == ' '));
        if (wordStart && std::strchr("+-0123456789Q", text[i + 1]) != nullptr) {
            const size_t start = (i > 0 && text[i - 1] == 'I') ? i - 1 : i;
            return static_cast<uint32_t>(start + 1);
        }
    }
    return 1;
}

}  // namespace kerf::klartext
