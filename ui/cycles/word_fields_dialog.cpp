#include "ui/cycles/word_fields_dialog.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>

#include "ui/cycles/dialog_parts.h"

namespace kerf::ui {

WordFieldsDialog::WordFieldsDialog(QWidget* parent, const char* objectName) : QDialog(parent) {
    setObjectName(objectName);
}

void WordFieldsDialog::build(const QString& title, const std::vector<WordRow>& rows,
                             const char* messageObjectName, int inputWidth) {
    auto* layout = new QVBoxLayout(this);
    auto* heading = new QLabel(title, this);
    heading->setStyleSheet(QStringLiteral("font-weight: bold; font-size: 16px;"));
    layout->addWidget(heading);
    auto* grid = new QGridLayout;
    m_grid = grid;
    grid->setColumnStretch(3, 1);
    for (size_t i = 0; i < rows.size(); ++i) {
        const int row = static_cast<int>(i);
        auto* label = new QLabel(rows[i].word, this);
        label->setStyleSheet(QStringLiteral("font-weight: bold;"));
        QWidget* input = nullptr;
        if (!rows[i].choices.isEmpty()) {
            auto* combo = new QComboBox(this);
            combo->addItems(rows[i].choices);
            input = combo;
        } else {
            input = new QLineEdit(this);
        }
        input->setMinimumHeight(kTouchHeight);
        input->setMinimumWidth(inputWidth);
        input->installEventFilter(this);
        auto* description = new QLabel(this);
        description->setWordWrap(true);
        grid->addWidget(label, row, 0);
        grid->addWidget(input, row, 1);
        grid->addWidget(description, row, 3);
        m_inputs.push_back(input);
        m_descriptions.push_back(description);
    }
    layout->addLayout(grid);
    m_message = addRefusalLine(*this, *layout, messageObjectName);
    addOkCancel(*this, *layout, m_ok, m_cancel);
    retranslate();
    if (!m_inputs.empty()) m_inputs.front()->setFocus();
}

QString WordFieldsDialog::text(int field) const {
    QWidget* input = m_inputs.at(static_cast<size_t>(field));
    if (auto* combo = qobject_cast<QComboBox*>(input)) return combo->currentText();
    return static_cast<QLineEdit*>(input)->text().trimmed();
}

void WordFieldsDialog::setValues(const QStringList& values) {
    for (size_t i = 0; i < m_inputs.size(); ++i) {
        const QString value = values.value(static_cast<int>(i));
        if (auto* combo = qobject_cast<QComboBox*>(m_inputs[i]))
            combo->setCurrentIndex(std::max(0, combo->findText(value.toUpper())));
        else
            static_cast<QLineEdit*>(m_inputs[i])->setText(value);
    }
}

QStringList WordFieldsDialog::values() const {
    QStringList list;
    for (int i = 0; i < fieldCount(); ++i)
        list << text(i);
    return list;
}

void WordFieldsDialog::addToRow(int field, QWidget* widget) {
    widget->setMinimumHeight(kTouchHeight);
    m_grid->addWidget(widget, field, 2);
}

void WordFieldsDialog::setMessage(const QString& text) {
    m_message->setText(text);
}

QString WordFieldsDialog::message() const {
    return m_message->text();
}

void WordFieldsDialog::accept() {
    if (const auto error = checkBlock(values())) {
        m_message->setText(*error);
        return;
    }
    m_message->clear();
    QDialog::accept();
}

void WordFieldsDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange && m_ok != nullptr) retranslate();
    QDialog::changeEvent(event);
}

bool WordFieldsDialog::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::KeyPress) return QDialog::eventFilter(watched, event);
    const int key = static_cast<QKeyEvent*>(event)->key();
    if (key != Qt::Key_Return && key != Qt::Key_Enter) return QDialog::eventFilter(watched, event);
    for (size_t i = 0; i < m_inputs.size(); ++i) {
        if (m_inputs[i] != watched) continue;
        const int field = static_cast<int>(i);
        if (const auto error = checkRow(field, text(field))) {
            m_message->setText(*error);
            return true;
        }
        m_message->clear();
        if (i + 1 < m_inputs.size())
            m_inputs[i + 1]->setFocus();
        else
            accept();
        return true;
    }
    return QDialog::eventFilter(watched, event);
}

void WordFieldsDialog::retranslate() {
    setWindowTitle(dialogTitle());
    for (size_t i = 0; i < m_descriptions.size(); ++i)
        m_descriptions[i]->setText(rowDescription(static_cast<int>(i)));
    m_ok->setText(tr("OK"));
    m_cancel->setText(tr("Cancel"));
}

}  // namespace kerf::ui
