#pragma once

#include <QRegularExpression>
#include <QString>

namespace kerf::ui {

// Patterns of the words the block dialogs accept, matched against a whole entry.

// A number as the operator types it: sign optional, decimal point or comma.
inline const QString kNumberPattern = QStringLiteral(R"([+-]?(\d+([.,]\d*)?|[.,]\d+))");
// A Q, QL or QR parameter in place of a number.
inline const QString kParameterPattern = QStringLiteral(R"([+-]?Q[LR]?\d+)");

// Whether the whole of `text` matches `pattern`, letters in either case.
inline bool matchesWhole(const QString& pattern, const QString& text) {
    const QRegularExpression re(QLatin1Char('^') + pattern + QLatin1Char('$'),
                                QRegularExpression::CaseInsensitiveOption);
    return re.match(text).hasMatch();
}

}  // namespace kerf::ui
