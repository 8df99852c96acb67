#include "ui/shell/message_panel.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "ui/common/block_name.h"
#include "ui/common/diagnostic_text.h"
#include "ui/shell/softkey_bar.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

namespace {

constexpr int kSeverityRole = Qt::UserRole;
constexpr int kLineRole = Qt::UserRole + 1;
constexpr int kFromCheckRole = Qt::UserRole + 2;
constexpr int kBlockNumberRole = Qt::UserRole + 3;
constexpr int kDialectRole = Qt::UserRole + 4;
constexpr int kCauseRole = Qt::UserRole + 5;
constexpr int kStandingRole = Qt::UserRole + 6;

// Run messages kept; the oldest beyond this go (the check's findings are replaced by each check).
constexpr int kMaxRunMessages = 200;

QColor severityColor(Severity severity) {
    switch (severity) {
        case Severity::Error:
            return QColor(0xc0, 0x1c, 0x1c);
        case Severity::Warning:
            return QColor(0xa0, 0x60, 0x00);
        case Severity::Note:
            return QColor(0x30, 0x50, 0x90);
    }
    return {};
}

}  // namespace

MessagePanel::MessagePanel(QWidget* parent) : QWidget(parent) {
    setObjectName("messagePanel");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_line = new QPushButton(this);
    m_line->setObjectName("messageLine");
    m_line->setFlat(true);
    m_line->setMinimumHeight(SoftkeyBar::kMinimumKeyHeight);
    m_line->setFocusPolicy(Qt::NoFocus);
    m_line->setStyleSheet(QStringLiteral("text-align: left; padding-left: 8px;"));
    connect(m_line, &QPushButton::clicked, this, [this] { setListVisible(m_list->isHidden()); });
    // The TNC's CE key for the message line.
    m_clearKey = new QPushButton(QStringLiteral("CE"), this);
    m_clearKey->setObjectName("messageClear");
    m_clearKey->setFixedSize(2 * kTouchHeight, kTouchHeight);
    m_clearKey->setFocusPolicy(Qt::NoFocus);
    connect(m_clearKey, &QPushButton::clicked, this, &MessagePanel::acknowledge);
    auto* lineRow = new QHBoxLayout();
    lineRow->setContentsMargins(0, 0, 0, 0);
    lineRow->addWidget(m_line, 1);
    lineRow->addWidget(m_clearKey);
    layout->addLayout(lineRow);

    m_list = new QTreeWidget(this);
    m_list->setObjectName("messageList");
    m_list->setRootIsDecorated(false);
    m_list->setColumnCount(3);
    m_list->setHeaderLabels({tr("Severity"), tr("Message"), tr("Block")});
    m_list->header()->setSectionResizeMode(1, QHeaderView::Stretch);
    m_list->header()->setStretchLastSection(false);
    makeTouchSizedRows(*m_list);
    // The header and four rows.
    m_list->setMaximumHeight(5 * kTouchHeight + 8);
    m_list->hide();
    connect(m_list, &QTreeWidget::itemActivated, this,
            [this](QTreeWidgetItem* item) { activate(m_list->indexOfTopLevelItem(item)); });
    connect(m_list, &QTreeWidget::itemClicked, this,
            [this](QTreeWidgetItem* item) { activate(m_list->indexOfTopLevelItem(item)); });
    layout->addWidget(m_list);
    refreshLine();
}

void MessagePanel::setPlaceOfLine(std::function<Place(int line)> placeOfLine) {
    m_placeOfLine = std::move(placeOfLine);
}

QTreeWidgetItem* MessagePanel::makeItem(Severity severity, const QString& text, int line,
                                        bool fromCheck, MessageCause cause) {
    const Place place = line > 0 && m_placeOfLine ? m_placeOfLine(line) : Place{};
    auto* item = new QTreeWidgetItem(
        {severityText(severity), text,
         line > 0 ? blockShortName(place.blockNumber, line, place.dialect) : QString()});
    item->setData(0, kBlockNumberRole, static_cast<qlonglong>(place.blockNumber));
    item->setData(0, kDialectRole, static_cast<int>(place.dialect));
    item->setData(0, kSeverityRole, static_cast<int>(severity));
    item->setData(0, kLineRole, line);
    item->setData(0, kFromCheckRole, fromCheck);
    item->setData(0, kCauseRole, static_cast<int>(cause));
    item->setData(0, kStandingRole, true);
    item->setForeground(0, severityColor(severity));
    return item;
}

void MessagePanel::setStanding(QTreeWidgetItem* item, bool standing) {
    item->setData(0, kStandingRole, standing);
    const QColor text = standing ? m_list->palette().color(QPalette::Text)
                                 : m_list->palette().color(QPalette::Disabled, QPalette::Text);
    for (int column = 0; column < item->columnCount(); ++column)
        item->setForeground(column, text);
    if (standing)
        item->setForeground(
            0, severityColor(static_cast<Severity>(item->data(0, kSeverityRole).toInt())));
}

void MessagePanel::resolve(const std::function<bool(MessageCause)>& holds) {
    bool changed = false;
    for (int i = 0; i < m_list->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = m_list->topLevelItem(i);
        const auto cause = static_cast<MessageCause>(item->data(0, kCauseRole).toInt());
        if (cause == MessageCause::None || !item->data(0, kStandingRole).toBool() || holds(cause))
            continue;
        setStanding(item, false);
        changed = true;
    }
    if (changed) refreshLine();
}

void MessagePanel::acknowledge() {
    if (QTreeWidgetItem* shown = shownItem()) {
        setStanding(shown, false);
        refreshLine();
    }
}

int MessagePanel::standingCount() const {
    int count = 0;
    for (int i = 0; i < m_list->topLevelItemCount(); ++i)
        if (m_list->topLevelItem(i)->data(0, kStandingRole).toBool()) ++count;
    return count;
}

void MessagePanel::setCheckDiagnostics(const DiagnosticList& diagnostics) {
    for (int i = m_list->topLevelItemCount() - 1; i >= 0; --i) {
        if (m_list->topLevelItem(i)->data(0, kFromCheckRole).toBool())
            delete m_list->takeTopLevelItem(i);
    }
    for (const Diagnostic& d : diagnostics) {
        m_list->addTopLevelItem(makeItem(d.severity, translatedMessage(d), static_cast<int>(d.line),
                                         true, MessageCause::None));
    }
    refreshLine();
}

void MessagePanel::addMessage(Severity severity, const QString& text, int line,
                              MessageCause cause) {
    // Newest first: the run's messages sit above the check's findings, the latest at the top.
    m_list->insertTopLevelItem(0, makeItem(severity, text, line, false, cause));
    int runMessages = 0;
    for (int i = 0; i < m_list->topLevelItemCount(); ++i) {
        if (!m_list->topLevelItem(i)->data(0, kFromCheckRole).toBool()) ++runMessages;
    }
    for (int i = m_list->topLevelItemCount() - 1; i >= 0 && runMessages > kMaxRunMessages; --i) {
        if (m_list->topLevelItem(i)->data(0, kFromCheckRole).toBool()) continue;
        delete m_list->takeTopLevelItem(i);
        --runMessages;
    }
    refreshLine();
}

void MessagePanel::forgetLines() {
    for (int i = 0; i < m_list->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = m_list->topLevelItem(i);
        item->setData(0, kLineRole, 0);
        item->setText(2, QString());
    }
    refreshLine();
}

void MessagePanel::clearMessages() {
    m_list->clear();
    refreshLine();
}

int MessagePanel::messageCount() const {
    return m_list->topLevelItemCount();
}

void MessagePanel::activate(int row) {
    QTreeWidgetItem* item = m_list->topLevelItem(row);
    if (item == nullptr) return;
    const int line = item->data(0, kLineRole).toInt();
    if (line > 0) emit lineActivated(line);
}

void MessagePanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        m_list->setHeaderLabels({tr("Severity"), tr("Message"), tr("Block")});
        refreshLine();
    }
    QWidget::changeEvent(event);
}

void MessagePanel::setListVisible(bool visible) {
    m_list->setVisible(visible);
}

QTreeWidgetItem* MessagePanel::shownItem() const {
    // The most severe message that stands, the newest of them (the list is newest first).
    QTreeWidgetItem* worst = nullptr;
    int worstSeverity = -1;
    for (int i = 0; i < m_list->topLevelItemCount(); ++i) {
        QTreeWidgetItem* item = m_list->topLevelItem(i);
        if (!item->data(0, kStandingRole).toBool()) continue;
        const int severity = item->data(0, kSeverityRole).toInt();
        if (severity > worstSeverity) {
            worst = item;
            worstSeverity = severity;
        }
    }
    return worst;
}

void MessagePanel::refreshLine() {
    // The line shows the message that stands out and how many others stand.
    QTreeWidgetItem* worst = shownItem();
    m_clearKey->setEnabled(worst != nullptr);
    if (worst == nullptr) {
        m_line->setText(tr("No messages"));
        m_line->setStyleSheet(QStringLiteral("text-align: left; padding-left: 8px;"));
        return;
    }
    const int line = worst->data(0, kLineRole).toInt();
    const QString block =
        line <= 0 ? QString()
                  : tr("%1: ").arg(blockName(
                        worst->data(0, kBlockNumberRole).toLongLong(), line,
                        static_cast<program::Dialect>(worst->data(0, kDialectRole).toInt())));
    const int worstSeverity = worst->data(0, kSeverityRole).toInt();
    const int others = standingCount() - 1;
    QString text = tr("%1 - %2%3").arg(worst->text(0), block, worst->text(1));
    if (others > 0) text += tr(" (%n more)", nullptr, others);
    m_line->setText(text);
    m_line->setStyleSheet(QStringLiteral("text-align: left; padding-left: 8px; color: %1;")
                              .arg(severityColor(static_cast<Severity>(worstSeverity)).name()));
}

}  // namespace kerf::ui
