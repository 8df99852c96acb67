#include "ui/shell/operator_input_dialog.h"

#include <QDialogButtonBox>
#include <QDoubleValidator>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

#include "ui/touch/touch_size.h"

namespace kerf::ui {

OperatorInputDialog::OperatorInputDialog(const std::vector<std::pair<int, double>>& inputs,
                                         QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("operatorInputDialog"));
    setWindowTitle(tr("Operator inputs"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("The program reads these inputs: enter their values"), this));
    auto* form = new QFormLayout;
    for (const auto& [n, value] : inputs) {
        auto* edit = new QLineEdit(QString::number(value, 'g', 12), this);
        edit->setObjectName(QStringLiteral("IB%1").arg(n));
        auto* validator = new QDoubleValidator(edit);
        validator->setLocale(QLocale::c());  // NC numbers use a point
        validator->setNotation(QDoubleValidator::StandardNotation);
        edit->setValidator(validator);
        form->addRow(QStringLiteral("IB%1").arg(n), edit);
        m_fields.emplace_back(n, edit);
    }
    layout->addLayout(form);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Start"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    // An empty or unfinished number cannot start the program.
    const auto updateOk = [this, buttons] {
        bool ok = true;
        for (const auto& [n, edit] : m_fields)
            ok = ok && edit->hasAcceptableInput();
        buttons->button(QDialogButtonBox::Ok)->setEnabled(ok);
    };
    for (const auto& [n, edit] : m_fields)
        connect(edit, &QLineEdit::textChanged, this, updateOk);
    layout->addWidget(buttons);
    makeTouchSized(*this);
}

std::vector<std::pair<int, double>> OperatorInputDialog::values() const {
    std::vector<std::pair<int, double>> out;
    for (const auto& [n, edit] : m_fields)
        out.emplace_back(n, QLocale::c().toDouble(edit->text()));
    return out;
}

QLineEdit* OperatorInputDialog::field(int n) const {
    for (const auto& [number, edit] : m_fields)
        if (number == n) return edit;
    return nullptr;
}

}  // namespace kerf::ui
