#include "ui/tables/table_chooser.h"

#include <QEvent>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace kerf::ui {

TableChooser::TableChooser(std::filesystem::path ncRoot, bool lathe, QWidget* parent)
    : QWidget(parent), m_ncRoot(std::move(ncRoot)), m_kinds(offeredTables(lathe)) {
    setObjectName("tableChooser");
    auto* layout = new QVBoxLayout(this);
    m_title = new QLabel(this);
    m_title->setStyleSheet(QStringLiteral("font-weight: bold; font-size: 16px;"));
    layout->addWidget(m_title);
    for (TableKind kind : m_kinds) {
        auto* button = new QPushButton(this);
        button->setMinimumHeight(56);  // a finger's target
        button->setStyleSheet(QStringLiteral("text-align: left; padding: 6px 12px;"));
        connect(button, &QPushButton::clicked, this, [this, kind] { choose(kind); });
        layout->addWidget(button);
        m_buttons.push_back(button);
    }
    layout->addStretch(1);
    retranslate();
}

std::filesystem::path TableChooser::pathOf(TableKind kind) const {
    return standardTablePath(m_ncRoot, kind);
}

void TableChooser::choose(TableKind kind) {
    emit openRequested(pathOf(kind));
}

QString TableChooser::kindName(TableKind kind) {
    switch (kind) {
        case TableKind::Tool:
            return tr("Tool\ntable");
        case TableKind::Preset:
            return tr("Preset\ntable");
        case TableKind::Datum:
            return tr("Datum\ntable");
        case TableKind::Point:
            return tr("Point\ntable");
        case TableKind::Probe:
            return tr("Touch probe\ntable");
        case TableKind::FagorToolOffsets:
            return tr("Tool\noffsets");
        case TableKind::FagorZeroOffsets:
            return tr("Zero\noffsets");
        case TableKind::FagorTools:
            return tr("Tool\ntable");
        case TableKind::OtherTnc:
            break;
    }
    return tr("Table");
}

QString TableChooser::kindDescription(TableKind kind) {
    switch (kind) {
        case TableKind::Tool:
            return tr("Lengths, radii, wear and life of the tools");
        case TableKind::Preset:
            return tr("Reference points of the workpieces, in machine coordinates");
        case TableKind::Datum:
            return tr("Zero offsets relative to the active preset (CYCL DEF 7)");
        case TableKind::Point:
            return tr("Machining positions for patterns (SEL PATTERN)");
        case TableKind::Probe:
            return tr("Workpiece touch probes: centre offset, feeds, probing path");
        case TableKind::FagorToolOffsets:
            return tr("Tool offsets D: X, Z, nose radius R, location code F, wear I, K");
        case TableKind::FagorZeroOffsets:
            return tr("Zero offsets G54-G59, G159 N7-N20 and the PLC offset, from machine zero");
        case TableKind::FagorTools:
            return tr("Tools T: offset D, family, tool life, nose angle and width");
        case TableKind::OtherTnc:
            break;
    }
    return {};
}

void TableChooser::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void TableChooser::retranslate() {
    m_title->setText(tr("Tables"));
    for (size_t i = 0; i < m_kinds.size(); ++i) {
        const TableKind kind = m_kinds[i];
        m_buttons[i]->setText(QStringLiteral("%1  (%2)\n%3")
                                  .arg(kindName(kind).replace(QLatin1Char('\n'), QLatin1Char(' ')),
                                       QString::fromStdString(pathOf(kind).filename().string()),
                                       kindDescription(kind)));
    }
}

}  // namespace kerf::ui
