#pragma once

#include <QDialog>
#include <QStringList>
#include <vector>

#include "ui/cycles/special_function.h"

class QLabel;
class QPushButton;

namespace kerf::ui {

// The dialog of a special function (PLANE, FUNCTION TCPM, M128, SEL PGM, CALL PGM): one row per
// word. Enter moves to the next row and finishes on the last, Esc cancels; refused input keeps
// the dialog open with a message.
class SpecialFunctionDialog : public QDialog {
    Q_OBJECT

public:
    explicit SpecialFunctionDialog(SpecialFunction function, QWidget* parent = nullptr);

    void setValues(const QStringList& values);
    QStringList values() const;
    int fieldCount() const { return static_cast<int>(m_inputs.size()); }
    QWidget* input(int field) const { return m_inputs.at(static_cast<size_t>(field)); }
    QString message() const;

    void accept() override;

protected:
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void retranslate();
    QString text(int field) const;

    SpecialFunction m_function;
    std::vector<SpecialField> m_fields;
    std::vector<QWidget*> m_inputs;
    std::vector<QLabel*> m_descriptions;
    QLabel* m_message = nullptr;
    QPushButton* m_ok = nullptr;
    QPushButton* m_cancel = nullptr;
};

}  // namespace kerf::ui
