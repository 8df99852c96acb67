#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

// The label list of cycle 14 CONTOUR ("CYCL DEF 14.1 CONTOUR LABEL 1/2/3", the keyword depends on
// the language): read the same way by the run and by the program check.
namespace kerf::klartext {

struct ContourLabel {
    int number = 0;
    size_t offset = 0;  // in the text read
};

struct ContourLabelList {
    std::vector<ContourLabel> labels;
    const char* error = nullptr;  // translatable message when the list is malformed
    size_t errorOffset = 0;
};

inline constexpr size_t kMaxContourLabels = 12;

ContourLabelList parseContourLabels(std::string_view text);

}  // namespace kerf::klartext
