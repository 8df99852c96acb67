#pragma once

#include <QWidget>

class QSplitter;
class QStackedWidget;

namespace kerf::ui {

// The workspace layouts an operator can choose, as on the TNC's screen-layout key.
enum class WorkspaceLayout { Program, ProgramGraphics, ProgramStatus, PositionsStatus };

// The area between the message line and the softkeys. It shows the panels of the chosen layout
// side by side, or one full-screen page (file manager, table editor) over them. Program + status
// stacks the positions over the status tabs right of the program, so a running program, its
// positions and its state are all on the screen.
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

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void equalizeHalves();

    QWidget* m_program;
    QWidget* m_graphics;
    QWidget* m_status;
    QWidget* m_positions;
    QSplitter* m_splitter = nullptr;
    QSplitter* m_side = nullptr;  // positions over status (program + status)
    QStackedWidget* m_pages = nullptr;
    WorkspaceLayout m_layout = WorkspaceLayout::Program;
    bool m_equalHalves = false;  // the two panels share the width until the operator drags
};

}  // namespace kerf::ui
