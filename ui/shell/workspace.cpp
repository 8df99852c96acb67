#include "ui/shell/workspace.h"

#include <QSplitter>
#include <QStackedWidget>
#include <QVBoxLayout>

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
    for (QWidget* panel : {m_program, m_graphics, m_status, m_positions})
        m_splitter->addWidget(panel);
    m_pages->addWidget(m_splitter);
    layout->addWidget(m_pages);
    setLayoutKind(WorkspaceLayout::Program);
}

void Workspace::setLayoutKind(WorkspaceLayout layout) {
    m_layout = layout;
    // Which panels a layout shows, left to right; the splitter keeps the others hidden.
    QWidget* left = layout == WorkspaceLayout::PositionsStatus ? m_positions : m_program;
    QWidget* right = nullptr;
    if (layout == WorkspaceLayout::ProgramGraphics) right = m_graphics;
    if (layout == WorkspaceLayout::ProgramStatus || layout == WorkspaceLayout::PositionsStatus)
        right = m_status;
    for (QWidget* panel : {m_program, m_graphics, m_status, m_positions}) {
        panel->setVisible(panel == left || panel == right);
    }
    // Program first, the other panel right of it: order the splitter accordingly.
    m_splitter->insertWidget(0, left);
    if (right != nullptr) {
        m_splitter->insertWidget(1, right);
        const int half = m_splitter->width() / 2;
        m_splitter->setSizes({half, half, 0, 0});
    }
    showPanels();
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
