#include "ui/shell/workspace.h"

#include <QSplitter>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace kerf::ui {

Workspace::Workspace(QWidget* program, QWidget* graphics, QWidget* status, QWidget* positions,
                     QWidget* parent)
    : QWidget(parent),
      m_program(program),
      m_graphics(graphics),
      m_status(status),
      m_positions(positions) {
    setObjectName("workspace");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_pages = new QStackedWidget(this);
    m_splitter = new QSplitter(Qt::Horizontal, m_pages);
    m_splitter->setChildrenCollapsible(false);
    // The operator's drag of the handle stands until the next layout.
    connect(m_splitter, &QSplitter::splitterMoved, this, [this] { m_equalHalves = false; });
    for (QWidget* panel : {m_program, m_graphics, m_status, m_positions})
        m_splitter->addWidget(panel);
    m_side = new QSplitter(Qt::Vertical, m_splitter);
    m_side->setChildrenCollapsible(false);
    m_splitter->addWidget(m_side);
    m_pages->addWidget(m_splitter);
    layout->addWidget(m_pages);
    setLayoutKind(WorkspaceLayout::Program);
}

void Workspace::setLayoutKind(WorkspaceLayout layout) {
    m_layout = layout;
    // Which panels a layout shows, left to right; the splitter keeps the others hidden.
    const bool stacked = layout == WorkspaceLayout::ProgramStatus;
    QWidget* left = layout == WorkspaceLayout::PositionsStatus ? m_positions : m_program;
    QWidget* right = nullptr;
    if (layout == WorkspaceLayout::ProgramGraphics) right = m_graphics;
    if (layout == WorkspaceLayout::PositionsStatus) right = m_status;
    if (stacked) right = m_side;
    // The positions and the status move between the side column and the splitter itself.
    QSplitter* home = stacked ? m_side : m_splitter;
    home->addWidget(m_positions);
    home->addWidget(m_status);
    for (QWidget* panel :
         {m_program, m_graphics, m_status, m_positions, static_cast<QWidget*>(m_side)}) {
        const bool inSide = panel->parentWidget() == m_side;
        panel->setVisible(panel == left || panel == right || (stacked && inSide));
    }
    // Program first, the other panel right of it: order the splitter accordingly.
    m_splitter->insertWidget(0, left);
    if (right != nullptr) {
        m_splitter->insertWidget(1, right);
        m_equalHalves = true;
        equalizeHalves();
    }
    showPanels();
}

void Workspace::equalizeHalves() {
    const int half = width() / 2;  // the splitter fills the workspace
    m_splitter->setSizes({half, half, 0, 0, 0});
    if (m_layout == WorkspaceLayout::ProgramStatus) {
        // The positions as tall as they need, the status tabs the rest.
        const int positions = m_positions->sizeHint().height();
        m_side->setSizes({positions, std::max(0, height() - positions)});
    }
}

void Workspace::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // A layout chosen before the window had its size gets its halves now (the splitter's own
    // resizing would keep the panels' minimum widths instead).
    if (m_equalHalves) equalizeHalves();
}

void Workspace::showPage(QWidget* page) {
    if (m_pages->indexOf(page) < 0) m_pages->addWidget(page);
    m_pages->setCurrentWidget(page);
}

void Workspace::showPanels() {
    m_pages->setCurrentWidget(m_splitter);
}

QWidget* Workspace::currentPage() const {
    return m_pages->currentWidget();
}

QString Workspace::layoutText(WorkspaceLayout layout) {
    switch (layout) {
        case WorkspaceLayout::Program:
            return tr("Program");
        case WorkspaceLayout::ProgramGraphics:
            return tr("Program +\ngraphics");
        case WorkspaceLayout::ProgramStatus:
            return tr("Program +\nstatus");
        case WorkspaceLayout::PositionsStatus:
            return tr("Positions +\nstatus");
    }
    return {};
}

}  // namespace kerf::ui
