#pragma once

#include <QObject>
#include <optional>

namespace kerf::task {
struct MachineStatus;
}

namespace kerf::ui {

class MachineSession;
class ProgramPanel;

// While a program runs, the editor shows it read-only with the executing block highlighted and
// kept in view; when the run ends (or the panel opens another program) the editor is editable
// again and the highlight goes.
class ExecutingBlockFollower : public QObject {
    Q_OBJECT

public:
    ExecutingBlockFollower(MachineSession& session, ProgramPanel& program,
                           QObject* parent = nullptr);

    std::optional<int> highlightedLine() const { return m_line; }

private:
    void follow();
    void mark(std::optional<int> line);

    MachineSession& m_session;
    ProgramPanel& m_program;
    std::optional<int> m_line;
    bool m_following = false;
    bool m_wasReadOnly = false;
};

}  // namespace kerf::ui
