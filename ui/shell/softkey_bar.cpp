#include "ui/shell/softkey_bar.h"

#include <QHBoxLayout>
#include <QKeySequence>
#include <QPushButton>
#include <QShortcut>

#include "ui/shell/softkey_button.h"

namespace kerf::ui {

namespace {

QPushButton* makeKey(QWidget* parent) {
    auto* key = new SoftkeyButton(parent);
    key->setMinimumHeight(SoftkeyBar::kMinimumKeyHeight);
    key->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    key->setFocusPolicy(Qt::NoFocus);  // touching a key must not take the editor's focus
    return key;
}

}  // namespace

SoftkeyBar::SoftkeyBar(QWidget* parent) : QWidget(parent) {
    setObjectName("softkeyBar");
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    for (int i = 0; i < kKeys; ++i) {
        QPushButton* key = makeKey(this);
        key->setObjectName(QStringLiteral("softkey%1").arg(i + 1));
        connect(key, &QPushButton::clicked, this, [this, i] { press(i); });
        auto* shortcut = new QShortcut(QKeySequence(Qt::Key_F1 + i), this);
        shortcut->setContext(Qt::WindowShortcut);
        connect(shortcut, &QShortcut::activated, this, [this, i] { press(i); });
        layout->addWidget(key);
        m_buttons.push_back(key);
    }
    m_rowButton = makeKey(this);
    m_rowButton->setObjectName("softkeyNextRow");
    m_rowButton->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    connect(m_rowButton, &QPushButton::clicked, this, &SoftkeyBar::nextRow);
    auto* rowShortcut = new QShortcut(QKeySequence(Qt::Key_F9), this);
    rowShortcut->setContext(Qt::WindowShortcut);
    connect(rowShortcut, &QShortcut::activated, this, &SoftkeyBar::nextRow);
    layout->addWidget(m_rowButton);
    refresh();
}

void SoftkeyBar::setRows(std::vector<SoftkeyRow> rows) {
    m_rows = std::move(rows);
    for (SoftkeyRow& row : m_rows) {
        if (row.size() > static_cast<size_t>(kKeys)) row.resize(static_cast<size_t>(kKeys));
    }
    m_current = 0;
    refresh();
}

void SoftkeyBar::showRow(int row) {
    if (row < 0 || row >= rowCount()) return;
    m_current = row;
    refresh();
}

void SoftkeyBar::nextRow() {
    if (rowCount() > 1) showRow((m_current + 1) % rowCount());
}

bool SoftkeyBar::press(int index) {
    if (m_current >= rowCount() || index < 0) return false;
    const SoftkeyRow& row = m_rows[static_cast<size_t>(m_current)];
    if (static_cast<size_t>(index) >= row.size()) return false;
    const Softkey key = row[static_cast<size_t>(index)];  // the action may replace the rows
    if (!key.action) return false;
    key.action();
    emit pressed(key.id);
    return true;
}

QString SoftkeyBar::keyId(int index) const {
    if (m_current >= rowCount() || index < 0) return {};
    const SoftkeyRow& row = m_rows[static_cast<size_t>(m_current)];
    return static_cast<size_t>(index) < row.size() ? row[static_cast<size_t>(index)].id : QString();
}

bool SoftkeyBar::pressId(const QString& id) {
    for (int r = 0; r < rowCount(); ++r) {
        const SoftkeyRow& row = m_rows[static_cast<size_t>(r)];
        for (size_t k = 0; k < row.size(); ++k) {
            if (row[k].id == id) {
                showRow(r);
                return press(static_cast<int>(k));
            }
        }
    }
    return false;
}

void SoftkeyBar::refresh() {
    const SoftkeyRow empty;
    const SoftkeyRow& row = m_current < rowCount() ? m_rows[static_cast<size_t>(m_current)] : empty;
    for (size_t i = 0; i < m_buttons.size(); ++i) {
        QPushButton* button = m_buttons[i];
        const bool used = i < row.size() && row[i].action;
        button->setText(used ? row[i].text : QString());
        button->setEnabled(used);
        button->setToolTip(QStringLiteral("F%1").arg(i + 1));
    }
    m_rowButton->setText(rowCount() > 1
                             ? QStringLiteral("%1/%2 \u25B8").arg(m_current + 1).arg(rowCount())
                             : QString());
    m_rowButton->setEnabled(rowCount() > 1);
}

}  // namespace kerf::ui
