#pragma once

#include <vector>

#include "ui/cycles/path_function.h"
#include "ui/cycles/word_fields_dialog.h"

namespace kerf::ui {

// The dialog of a path function or TOOL CALL: one row per word (coordinates, radius
// compensation, feed, M functions ...). Enter moves to the next row and finishes on the last,
// Esc cancels; refused input keeps the dialog open with a message.
class PathFunctionDialog : public WordFieldsDialog {
    Q_OBJECT

public:
    explicit PathFunctionDialog(PathFunction function, QWidget* parent = nullptr);

    // The block without its number, e.g. "L X+10 Y+5 RL F200 M3".
    QString block() const;

protected:
    std::optional<QString> checkRow(int field, const QString& text) const override;
    std::optional<QString> checkBlock(const QStringList& values) const override;
    QString rowDescription(int field) const override;
    QString dialogTitle() const override;

private:
    PathFunction m_function;
    std::vector<PathField> m_fields;
};

}  // namespace kerf::ui
