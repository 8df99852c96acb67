#include "ui/files/new_program_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "ui/touch/touch_size.h"

namespace kerf::ui {

NewProgramDialog::NewProgramDialog(const machine::MachineConfig& machine, QWidget* parent)
    : QDialog(parent) {
    setObjectName(QStringLiteral("newProgramDialog"));
    setWindowTitle(tr("New program"));
    setMinimumWidth(520);
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout();
    m_name = new QLineEdit(this);
    m_name->setObjectName(QStringLiteral("newProgramName"));
    m_name->setMinimumHeight(kTouchHeight);
    form->addRow(tr("Program name"), m_name);
    m_unit = new QComboBox(this);
    m_unit->setObjectName(QStringLiteral("newProgramUnit"));
    m_unit->addItems({QStringLiteral("MM"), QStringLiteral("INCH")});
    m_unit->setMinimumHeight(kTouchHeight);
    form->addRow(tr("Unit"), m_unit);
    if (machine.kind != machine::MachineKind::Lathe) {
        const NewProgramSpec defaults;
        const char* axes[] = {"X", "Y", "Z"};
        for (int i = 0; i < 6; ++i) {
            auto* field = new QDoubleSpinBox(this);
            field->setObjectName(QStringLiteral("blank%1%2")
                                     .arg(i < 3 ? QStringLiteral("Min") : QStringLiteral("Max"))
                                     .arg(QLatin1String(axes[i % 3])));
            field->setRange(-99999.9999, 99999.9999);
            field->setDecimals(4);
            field->setMinimumHeight(kTouchHeight);
            const size_t axis = static_cast<size_t>(i % 3);
            field->setValue(i < 3 ? defaults.blankMin[axis] : defaults.blankMax[axis]);
            m_blank[static_cast<size_t>(i)] = field;
            const QString label = i < 3 ? tr("Blank MIN %1").arg(QLatin1String(axes[i % 3]))
                                        : tr("Blank MAX %1").arg(QLatin1String(axes[i % 3]));
            form->addRow(label, field);
        }
    }
    layout->addLayout(form);
    m_problem = new QLabel(this);
    m_problem->setObjectName(QStringLiteral("newProgramProblem"));
    m_problem->setStyleSheet(QStringLiteral("color: #c01c1c;"));
    m_problem->hide();
    layout->addWidget(m_problem);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    for (QAbstractButton* button : buttons->buttons())
        button->setMinimumHeight(kTouchHeight);
    connect(buttons, &QDialogButtonBox::accepted, this, &NewProgramDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

NewProgramSpec NewProgramDialog::spec() const {
    NewProgramSpec spec;
    spec.name = m_name->text().trimmed().toStdString();
    spec.inch = m_unit->currentIndex() == 1;
    for (size_t i = 0; i < 3; ++i) {
        if (m_blank[i] == nullptr) continue;
        spec.blankMin[i] = m_blank[i]->value();
        spec.blankMax[i] = m_blank[i + 3]->value();
    }
    return spec;
}

void NewProgramDialog::accept() {
    const QString name = m_name->text().trimmed();
    QString problem;
    if (name.isEmpty() || name.contains(QLatin1Char('/')) || name.contains(QLatin1Char('\\')) ||
        name.contains(QLatin1Char(' '))) {
        problem = tr("Give the program a name without spaces or folders");
    }
    for (size_t i = 0; i < 3 && problem.isEmpty(); ++i) {
        if (m_blank[i] != nullptr && !(m_blank[i]->value() < m_blank[i + 3]->value()))
            problem = tr("The blank's MIN point must lie below its MAX point on every axis");
    }
    if (!problem.isEmpty()) {
        m_problem->setText(problem);
        m_problem->show();
        return;
    }
    QDialog::accept();
}

}  // namespace kerf::ui
