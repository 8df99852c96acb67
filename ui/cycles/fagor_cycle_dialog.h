#pragma once

#include <QDialog>
#include <QStringList>
#include <vector>

#include "ui/cycles/fagor_cycle_fields.h"

class QLabel;
class QLineEdit;
class QPushButton;
class QScrollArea;

namespace kerf::ui {

class CycleHelpPicture;

// The dialog of one FAGOR canned cycle (G66-G89): one row per parameter (letter, meaning, input,
// unit, the manual's format), required ones marked with '*', and the help picture highlighting
// the parameter being entered. Enter checks the field and moves on (on the last one it
// finishes), Esc cancels; refused input keeps the dialog open with the interpreter's message.
class FagorCycleDialog : public QDialog {
    Q_OBJECT

public:
    explicit FagorCycleDialog(int g, QWidget* parent = nullptr);

    // Fills the fields with the values of an existing cycle block (fagorCycleFields order).
    void setValues(const QStringList& values);
    QStringList values() const;
    // The cycle block of the entered values ("G68 X0 Z0 C2 S10 E20").
    QString block() const;

    int fieldCount() const { return static_cast<int>(m_fields.size()); }
    QLineEdit* input(int field) const { return m_inputs.at(static_cast<size_t>(field)); }
    // The field of parameter `letter`, -1 if the cycle has none.
    int fieldOf(char letter) const;
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
    bool refuse(int field, const QString& message);
    void enterPressed(int field);

    int m_g;
    std::vector<FagorField> m_fields;
    std::vector<QLineEdit*> m_inputs;
    std::vector<QLabel*> m_descriptions;
    QScrollArea* m_scroll = nullptr;
    QLabel* m_title = nullptr;
    QLabel* m_legend = nullptr;
    QLabel* m_message = nullptr;
    QLabel* m_fieldHelp = nullptr;
    QPushButton* m_ok = nullptr;
    QPushButton* m_cancel = nullptr;
    CycleHelpPicture* m_picture = nullptr;
    int m_current = 0;
};

}  // namespace kerf::ui
