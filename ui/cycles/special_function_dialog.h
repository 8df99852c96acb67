#pragma once

#include <vector>

#include "ui/cycles/special_function.h"
#include "ui/cycles/word_fields_dialog.h"

namespace kerf::ui {

// The dialog of a special function (PLANE, FUNCTION TCPM, M128, SEL PGM, CALL PGM): one row per
// word. Enter moves to the next row and finishes on the last, Esc cancels; refused input keeps
// the dialog open with a message.
class SpecialFunctionDialog : public WordFieldsDialog {
    Q_OBJECT

public:
    explicit SpecialFunctionDialog(SpecialFunction function, QWidget* parent = nullptr);

protected:
    std::optional<QString> checkRow(int field, const QString& text) const override;
    std::optional<QString> checkBlock(const QStringList& values) const override;
    QString rowDescription(int field) const override;
    QString dialogTitle() const override;

private:
    SpecialFunction m_function;
    std::vector<SpecialField> m_fields;
};

}  // namespace kerf::ui
