#include "core/tables/detail/number_style_inference.h"

#include <algorithm>
#include <array>

#include "core/tables/tnc_table.h"

namespace kerf::tables::detail {

namespace {

// How a column writes its numbers, counted over its cells.
struct ColumnVotes {
    int plus = 0;    // "+5"
    int noSign = 0;  // "5"
    int comma = 0;
    int point = 0;
    std::array<int, 10> decimals{};
    int numbers = 0;
};

ColumnVotes countColumn(const TncTable& table, size_t column) {
    ColumnVotes votes;
    for (size_t row = 0; row < table.rowCount(); ++row) {
        std::string_view text = table.cell(row, column);
        auto style = numberStyleOf(text);
        if (!style) continue;
        ++votes.numbers;
        if (style->explicitSign) {
            ++votes.plus;
        } else if (text.front() != '-') {
            ++votes.noSign;
        }
        if (text.find(',') != std::string_view::npos) ++votes.comma;
        if (text.find('.') != std::string_view::npos) ++votes.point;
        ++votes.decimals[static_cast<size_t>(std::min(style->decimals, 9))];
    }
    return votes;
}

char tableSeparator(const TncTable& table) {
    int comma = 0;
    int point = 0;
    for (size_t column = 0; column < table.columns().size(); ++column) {
        ColumnVotes votes = countColumn(table, column);
        comma += votes.comma;
        point += votes.point;
    }
    return comma > point ? ',' : '.';
}

}  // namespace

NumberStyle inferNumberStyle(const TncTable& table, std::optional<size_t> row, size_t column,
                             double value) {
    const ColumnFormat& format = table.columnFormat(column);
    std::string_view own = row ? table.cell(*row, column) : std::string_view();
    std::optional<NumberStyle> ownStyle = numberStyleOf(own);
    ColumnVotes votes = countColumn(table, column);

    NumberStyle style;
    // A negative number tells nothing about how the column writes positive ones.
    if (ownStyle && own.front() != '-') {
        style.explicitSign = ownStyle->explicitSign;
    } else if (votes.plus != votes.noSign) {
        style.explicitSign = votes.plus > votes.noSign;
    } else {
        style.explicitSign = format.explicitSign;
    }

    if (own.find(',') != std::string_view::npos) {
        style.decimalSeparator = ',';
    } else if (own.find('.') != std::string_view::npos) {
        style.decimalSeparator = '.';
    } else if (votes.comma != votes.point) {
        style.decimalSeparator = votes.comma > votes.point ? ',' : '.';
    } else {
        style.decimalSeparator = tableSeparator(table);
    }

    int decimals = format.defaultDecimals;
    if (ownStyle) {
        decimals = ownStyle->decimals;
    } else if (votes.numbers > 0) {
        auto mostUsed = std::max_element(votes.decimals.begin(), votes.decimals.end());
        decimals = static_cast<int>(mostUsed - votes.decimals.begin());
    }
    if (format.kind == CellKind::Integer) {
        style.decimals = 0;
    } else {
        style.decimals =
            std::max(decimals, minimalDecimals(value, std::max(decimals, kMaxDecimals)));
    }
    return style;
}

}  // namespace kerf::tables::detail
