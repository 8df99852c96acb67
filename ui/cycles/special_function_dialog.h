#pragma once

#include <vector>

#include "ui/cycles/program_reference.h"
#include "ui/cycles/special_function.h"
#include "ui/cycles/word_fields_dialog.h"

class QPushButton;

namespace kerf::ui {

// The dialog of a special function (PLANE, FUNCTION TCPM, M128, SEL PGM, CALL PGM): one row per
// word. Enter moves to the next row and finishes on the last, Esc cancels; refused input keeps
// the dialog open with a message. With the program's place known, the program name of SEL PGM and
// CALL PGM has "Select file": the NC root's programs in a ProgramFileDialog, the chosen one
// written as the TNC writes it (programReference).
class SpecialFunctionDialog : public WordFieldsDialog {
    Q_OBJECT

public:
    explicit SpecialFunctionDialog(SpecialFunction function, ProgramPlace place = {},
                                   QWidget* parent = nullptr);

    // Opens the file list; the chosen program's name goes into the field (false: cancelled or
    // refused, the reason in message()).
    bool selectFile();
    // The "Select file" button; none without an NC root or for a function without a program.
    QPushButton* selectFileButton() const { return m_selectFile; }

protected:
    std::optional<QString> checkRow(int field, const QString& text) const override;
    std::optional<QString> checkBlock(const QStringList& values) const override;
    QString rowDescription(int field) const override;
    QString dialogTitle() const override;
    void changeEvent(QEvent* event) override;

private:
    SpecialFunction m_function;
    std::vector<SpecialField> m_fields;
    ProgramPlace m_place;
    int m_programField = -1;
    QPushButton* m_selectFile = nullptr;
};

}  // namespace kerf::ui
