#include "core/interp/klartext/contour_labels.h"

#include "core/base/translate.h"
#include "core/interp/klartext/cursor.h"

namespace kerf::klartext {

ContourLabelList parseContourLabels(std::string_view text) {
    ContourLabelList out;
    auto fail = [&](size_t at, const char* message) {
        out.labels.clear();
        out.error = message;
        out.errorOffset = at;
        return out;
    };
    size_t at = text.find_first_of("0123456789");
    while (at != std::string_view::npos && at < text.size()) {
        size_t end = at;
        long value = 0;
        while (end < text.size() && isDigit(text[end]) && value <= 65535) {
            value = value * 10 + (text[end] - '0');
            ++end;
        }
        if (value < 1 || value > 65535) {
            return fail(at, KERF_TR_NOOP("cycle 14: a label number from 1 to 65535 expected"));
        }
        out.labels.push_back({static_cast<int>(value), at});
        while (end < text.size() && (text[end] == ' ' || text[end] == '\t'))
            ++end;
        if (end >= text.size() || text[end] == ';') break;
        if (text[end] != '/') {
            return fail(end, KERF_TR_NOOP("cycle 14: label numbers are separated by '/'"));
        }
        at = text.find_first_of("0123456789", end + 1);
    }
    if (out.labels.empty() || out.labels.size() > kMaxContourLabels) {
        return fail(0, KERF_TR_NOOP("cycle 14 lists 1 to 12 label numbers"));
    }
    return out;
}

}  // namespace kerf::klartext
