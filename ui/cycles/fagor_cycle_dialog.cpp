#include "ui/cycles/fagor_cycle_dialog.h"

#include <QCoreApplication>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

#include "ui/cycles/cycle_help_picture.h"
#include "ui/cycles/dialog_parts.h"
#include "ui/cycles/fagor_help_drawing.h"

namespace kerf::ui {

FagorCycleDialog::FagorCycleDialog(int g, QWidget* parent)
    : QDialog(parent), m_g(g), m_fields(fagorCycleFields(g)) {
    setObjectName("fagorCycleDialog");
    auto* outer = new QHBoxLayout(this);
    auto* left = new QVBoxLayout;
    outer->addLayout(left, 3);

    m_title = new QLabel(this);
    m_title->setObjectName("cycleTitle");
    m_title->setStyleSheet(QStringLiteral("font-weight: bold; font-size: 16px;"));
    left->addWidget(m_title);

    auto* rows = new QWidget;
    auto* grid = new QGridLayout(rows);
    grid->setColumnStretch(1, 1);
    for (size_t i = 0; i < m_fields.size(); ++i) {
        const int row = static_cast<int>(i);
        const FagorField& field = m_fields[i];
        auto* label =
            new QLabel(field.label() + (field.required() ? QStringLiteral("*") : ""), rows);
        label->setStyleSheet(QStringLiteral("font-weight: bold;"));
        auto* description = new QLabel(rows);
        description->setWordWrap(true);
        auto* input = new QLineEdit(rows);
        input->setObjectName(QStringLiteral("field_%1").arg(field.label()));
        input->setMinimumHeight(kTouchHeight);
        input->setMinimumWidth(120);
        input->installEventFilter(this);
        connect(input, &QLineEdit::returnPressed, this, [this, row] { enterPressed(row); });
        auto* format = new QLabel(fagorFormatText(*field.parameter), rows);
        format->setStyleSheet(QStringLiteral("color: #606060;"));
        grid->addWidget(label, row, 0);
        grid->addWidget(description, row, 1);
        grid->addWidget(input, row, 2);
        grid->addWidget(new QLabel(fagorUnitText(field.unit), rows), row, 3);
        grid->addWidget(format, row, 4);
        m_inputs.push_back(input);
        m_descriptions.push_back(description);
    }
    m_scroll = new QScrollArea(this);
    m_scroll->setWidget(rows);
    m_scroll->setWidgetResizable(true);
    left->addWidget(m_scroll, 1);
    m_legend = new QLabel(this);
    left->addWidget(m_legend);

    m_message = addRefusalLine(*this, *left, "cycleMessage");
    addOkCancel(*this, *left, m_ok, m_cancel);

    auto* right = new QVBoxLayout;
    m_picture = new CycleHelpPicture(this);
    m_picture->setDrawing(fagorHelpDrawing(g));
    right->addWidget(m_picture, 1);
    m_fieldHelp = new QLabel(this);
    m_fieldHelp->setObjectName("cycleFieldHelp");
    m_fieldHelp->setWordWrap(true);
    right->addWidget(m_fieldHelp);
    outer->addLayout(right, 2);

    retranslate();
    sizeToWindow(*this);
    if (!m_inputs.empty()) {
        setCurrentField(0);
        m_inputs.front()->setFocus();
    }
}

void FagorCycleDialog::setValues(const QStringList& values) {
    for (size_t i = 0; i < m_inputs.size(); ++i)
        m_inputs[i]->setText(values.value(static_cast<int>(i)));
}

QStringList FagorCycleDialog::values() const {
    QStringList list;
    for (const QLineEdit* input : m_inputs)
        list << input->text().trimmed();
    return list;
}

QString FagorCycleDialog::block() const {
    return writeFagorCycleBlock(m_g, m_fields, values());
}

int FagorCycleDialog::fieldOf(char letter) const {
    for (size_t i = 0; i < m_fields.size(); ++i) {
        if (m_fields[i].parameter->letter == letter) return static_cast<int>(i);
    }
    return -1;
}

void FagorCycleDialog::setCurrentField(int field) {
    if (field < 0 || field >= fieldCount()) return;
    m_current = field;
    const FagorField& f = m_fields[static_cast<size_t>(field)];
    m_picture->setField(f.label());
    // Enter moves down the parameters: the field being entered stays in view.
    m_scroll->ensureWidgetVisible(m_inputs[static_cast<size_t>(field)]);
    m_fieldHelp->setText(
        QStringLiteral("%1: %2").arg(f.label(), QCoreApplication::translate("kerf", f.meaning)));
}

QString FagorCycleDialog::message() const {
    return m_message->text();
}

bool FagorCycleDialog::refuse(int field, const QString& message) {
    m_message->setText(message);
    if (field < 0) return false;
    setCurrentField(field);
    m_inputs[static_cast<size_t>(field)]->setFocus();
    m_inputs[static_cast<size_t>(field)]->selectAll();
    return false;
}

void FagorCycleDialog::enterPressed(int field) {
    const auto refused = checkFagorField(m_g, m_fields[static_cast<size_t>(field)],
                                         m_inputs[static_cast<size_t>(field)]->text());
    if (refused) {
        refuse(field, *refused);
        return;
    }
    m_message->clear();
    if (field + 1 < fieldCount()) {
        setCurrentField(field + 1);
        m_inputs[static_cast<size_t>(field + 1)]->setFocus();
        m_inputs[static_cast<size_t>(field + 1)]->selectAll();
        return;
    }
    accept();
}

void FagorCycleDialog::accept() {
    if (const auto refused = checkFagorCycleBlock(m_g, m_fields, values())) {
        refuse(refused->field, refused->message);
        return;
    }
    QDialog::accept();
}

void FagorCycleDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(event);
}

bool FagorCycleDialog::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::FocusIn) {
        for (size_t i = 0; i < m_inputs.size(); ++i) {
            if (m_inputs[i] == watched) setCurrentField(static_cast<int>(i));
        }
    }
    return QDialog::eventFilter(watched, event);
}

void FagorCycleDialog::retranslate() {
    setWindowTitle(tr("Canned cycle"));
    m_title->setText(QStringLiteral("G%1  %2").arg(m_g).arg(fagorCycleName(m_g)));
    for (size_t i = 0; i < m_fields.size(); ++i)
        m_descriptions[i]->setText(QCoreApplication::translate("kerf", m_fields[i].meaning));
    m_legend->setText(tr("* required"));
    m_ok->setText(tr("OK"));
    m_cancel->setText(tr("Cancel"));
    setCurrentField(m_current);
}

}  // namespace kerf::ui
