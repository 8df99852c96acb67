#pragma once

#include <QDialog>
#include <QStringList>
#include <vector>

#include "core/cycles/cycle_descriptor.h"
#include "ui/cycles/cycle_fields.h"

class QLabel;
class QLineEdit;
class QPushButton;

namespace kerf::ui {

class CycleHelpPicture;

// The dialog of one cycle, as the TNC asks for it after CYCL DEF: one row per parameter (Q
// number or word, meaning, input, unit, range) prefilled with the defaults, and the help
// picture highlighting the parameter being entered. Enter checks the field and moves to the
// next (on the last one it finishes), Esc cancels. Refused input keeps the dialog open with a
// message saying why.
class CycleDialog : public QDialog {
    Q_OBJECT

public:
    CycleDialog(const cycles::CycleDescriptor& cycle, bool inch, QWidget* parent = nullptr);

    // Fills the fields with the values of an existing definition (editing a CYCL DEF).
    void setValues(const QStringList& values);
    QStringList values() const;
    // The NC blocks for the entered values (see writeCycleBlocks).
    QStringList blocks() const;

    int fieldCount() const { return static_cast<int>(m_fields.size()); }
    QLineEdit* input(int field) const { return m_inputs.at(static_cast<size_t>(field)); }
    int currentField() const { return m_current; }
    void setCurrentField(int field);
    CycleHelpPicture* picture() const { return m_picture; }
    QString message() const;

    void accept() override;

protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void retranslate();
    bool checkField(int field);
    void enterPressed(int field);

    const cycles::CycleDescriptor& m_cycle;
    bool m_inch;
    std::vector<CycleField> m_fields;
    std::vector<QLineEdit*> m_inputs;
    std::vector<QLabel*> m_descriptions;
    std::vector<QLabel*> m_ranges;
    QLabel* m_title = nullptr;
    QLabel* m_message = nullptr;
    QLabel* m_fieldHelp = nullptr;
    QPushButton* m_ok = nullptr;
    QPushButton* m_cancel = nullptr;
    CycleHelpPicture* m_picture = nullptr;
    int m_current = 0;
};

}  // namespace kerf::ui
