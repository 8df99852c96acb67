#pragma once

#include <QWidget>

class QSplitter;
class QStackedWidget;

namespace kerf::ui {

// The workspace layouts an operator can choose, as on the TNC's screen-layout key.
enum class WorkspaceLayout { Program, ProgramGraphics, ProgramStatus, PositionsStatus };

// The area between the message line and the softkeys. It shows the panels of the chosen layout
// side by side, or one full-screen page (file manager, table editor) over them.
class Workspace : public QWidget {
    Q_OBJECT

public:
    Workspace(QWidget* program, QWidget* graphics, QWidget* status, QWidget* positions,
              QWidget* parent = nullptr);

    WorkspaceLayout layoutKind() const { return m_layout; }
    void setLayoutKind(WorkspaceLayout layout);
    // Shows a full-screen page (added on first use); showPanels() returns to the layout.
    void showPage(QWidget* page);
    void showPanels();
    QWidget* currentPage() const;

    static QString layoutText(WorkspaceLayout layout);

private:
    QWidget* m_program;
    QWidget* m_graphics;
    QWidget* m_status;
    QWidget* m_positions;
    QSplitter* m_splitter = nullptr;
    QStackedWidget* m_pages = nullptr;
    WorkspaceLayout m_layout = WorkspaceLayout::Program;
};

}  // namespace kerf::ui
