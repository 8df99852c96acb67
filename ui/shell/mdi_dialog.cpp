#include "ui/shell/mdi_dialog.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "ui/touch/touch_size.h"

namespace kerf::ui {

MdiDialog::MdiDialog(const QStringList& history, QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("mdiDialog"));
    setWindowTitle(tr("Positioning with MDI"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Block (arrow keys: the blocks run before)"), this));
    m_block = new QComboBox(this);
    m_block->setObjectName(QStringLiteral("mdiBlock"));
    m_block->setEditable(true);
    m_block->setInsertPolicy(QComboBox::NoInsert);
    m_block->setMinimumWidth(420);
    m_block->addItems(history);
    // A new block starts from an empty field; the history stays one arrow key away.
    m_block->setCurrentIndex(-1);
    m_block->clearEditText();
    layout->addWidget(m_block);
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    m_ok = new QPushButton(tr("OK"), this);
    m_ok->setObjectName(QStringLiteral("mdiOk"));
    m_ok->setDefault(true);
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName(QStringLiteral("mdiCancel"));
    buttons->addWidget(m_ok);
    buttons->addWidget(m_cancel);
    layout->addLayout(buttons);
    connect(m_ok, &QPushButton::clicked, this, &QDialog::accept);
    connect(m_cancel, &QPushButton::clicked, this, &QDialog::reject);
    makeTouchSized(*this);
}

QString MdiDialog::block() const {
    return m_block->currentText().trimmed();
}

}  // namespace kerf::ui
