#include "ui/cycles/cycle_catalogue_dialog.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include "core/cycles/cycle_registry.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

CycleCatalogueDialog::CycleCatalogueDialog(QWidget* parent)
    : QDialog(parent), m_sections(cycleCatalogue()) {
    setObjectName("cycleCatalogue");
    auto* layout = new QVBoxLayout(this);
    auto* groups = new QHBoxLayout;
    for (size_t i = 0; i < m_sections.size(); ++i) {
        auto* button = new QPushButton(this);
        button->setCheckable(true);
        button->setAutoDefault(false);
        button->setMinimumHeight(kTouchHeight + 8);
        const int section = static_cast<int>(i);
        connect(button, &QPushButton::clicked, this, [this, section] { showGroup(section); });
        groups->addWidget(button);
        m_groups.push_back(button);
    }
    layout->addLayout(groups);
    m_list = new QListWidget(this);
    m_list->setStyleSheet(QStringLiteral("QListWidget::item { min-height: 48px; }"));
    connect(m_list, &QListWidget::itemActivated, this, [this] { accept(); });
    layout->addWidget(m_list, 1);
    auto* numberRow = new QHBoxLayout;
    m_numberLabel = new QLabel(this);
    m_number = new QLineEdit(this);
    m_number->setMinimumHeight(kTouchHeight);
    m_number->setMaximumWidth(160);
    connect(m_number, &QLineEdit::returnPressed, this, [this] { chooseNumber(); });
    m_message = new QLabel(this);
    m_message->setStyleSheet(QStringLiteral("color: #b00000; font-weight: bold;"));
    numberRow->addWidget(m_numberLabel);
    numberRow->addWidget(m_number);
    numberRow->addWidget(m_message, 1);
    layout->addLayout(numberRow);
    auto* buttons = new QHBoxLayout;
    m_ok = new QPushButton(this);
    m_cancel = new QPushButton(this);
    for (QPushButton* button : {m_ok, m_cancel}) {
        button->setAutoDefault(false);
        button->setMinimumHeight(kTouchHeight);
        button->setMinimumWidth(120);
        buttons->addWidget(button);
    }
    buttons->addStretch(1);
    connect(m_ok, &QPushButton::clicked, this, &CycleCatalogueDialog::accept);
    connect(m_cancel, &QPushButton::clicked, this, &CycleCatalogueDialog::reject);
    layout->addLayout(buttons);
    retranslate();
    showGroup(0);
}

void CycleCatalogueDialog::showGroup(int section) {
    if (section < 0 || section >= static_cast<int>(m_sections.size())) return;
    m_section = section;
    m_list->clear();
    for (size_t i = 0; i < m_groups.size(); ++i)
        m_groups[i]->setChecked(static_cast<int>(i) == section);
    for (const cycles::CycleDescriptor* cycle : m_sections[static_cast<size_t>(section)].cycles) {
        auto* item = new QListWidgetItem(cycleTitle(*cycle), m_list);
        item->setData(Qt::UserRole, cycle->number);
    }
    m_list->setCurrentRow(0);
}

void CycleCatalogueDialog::chooseNumber() {
    bool ok = false;
    const int number = m_number->text().trimmed().toInt(&ok);
    const cycles::CycleDescriptor* cycle = ok ? cycles::findCycle(number) : nullptr;
    // Obsolete cycles run in old programs, but a TNC 320 no longer inserts them.
    if (!cycle || cycle->obsolete) {
        m_message->setText(tr("There is no cycle %1").arg(m_number->text().trimmed()));
        return;
    }
    m_selected = cycle;
    QDialog::accept();
}

void CycleCatalogueDialog::accept() {
    if (!m_number->text().trimmed().isEmpty()) return chooseNumber();
    const QListWidgetItem* item = m_list->currentItem();
    if (!item) return;
    m_selected = cycles::findCycle(item->data(Qt::UserRole).toInt());
    QDialog::accept();
}

void CycleCatalogueDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(event);
}

void CycleCatalogueDialog::retranslate() {
    setWindowTitle(tr("Cycle definition"));
    for (size_t i = 0; i < m_groups.size(); ++i)
        m_groups[i]->setText(groupTitle(m_sections[i].group));
    m_numberLabel->setText(tr("Cycle number"));
    m_ok->setText(tr("OK"));
    m_cancel->setText(tr("Cancel"));
    for (int row = 0; row < m_list->count(); ++row) {
        QListWidgetItem* item = m_list->item(row);
        item->setText(cycleTitle(*cycles::findCycle(item->data(Qt::UserRole).toInt())));
    }
}

}  // namespace kerf::ui
