#pragma once

#include <QString>
#include <QWidget>
#include <functional>

#include "core/base/diagnostic.h"
#include "core/program/dialect.h"
#include "ui/common/message_cause.h"

class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace kerf::ui {

// The message line under the header and the message list it opens: each message has a
// severity, a text and the block it refers to, named by its block number (the file line where
// the line has none). Activating a message that names a line asks the editor to jump there.
// The list is newest first: the run's messages (the latest 200) above the last check's findings
// (in file order, replaced by each check); the line shows the newest of the most severe that
// still stand. A message whose cause is gone (resolve) or that was cleared with CE stays in the
// list, greyed, but leaves the line.
class MessagePanel : public QWidget {
    Q_OBJECT

public:
    explicit MessagePanel(QWidget* parent = nullptr);

    // The block number written on a line of the program shown (-1: none) and its dialect.
    struct Place {
        int64_t blockNumber = -1;
        program::Dialect dialect = program::Dialect::Klartext;
    };
    // How messages name their lines: asked once per message, when it arrives.
    void setPlaceOfLine(std::function<Place(int line)> placeOfLine);

    // Replaces the program check's messages (messages from other sources stay).
    void setCheckDiagnostics(const DiagnosticList& diagnostics);
    // Adds one message from the HMI itself (refused mode change, save error ...).
    void addMessage(Severity severity, const QString& text, int line = 0,
                    MessageCause cause = MessageCause::None);
    // The messages whose cause no longer holds leave the line.
    void resolve(const std::function<bool(MessageCause)>& holds);
    // CE: the message on the line leaves it (the next one standing takes its place).
    void acknowledge();
    // The messages that still stand (on the line or behind it).
    int standingCount() const;
    void clearMessages();
    // Another program is shown: the lines the messages name were lines of the one before, so
    // they no longer lead into the editor (the messages themselves stay).
    void forgetLines();

    int messageCount() const;
    QTreeWidget* list() const { return m_list; }
    QPushButton* line() const { return m_line; }
    QPushButton* clearKey() const { return m_clearKey; }
    // Activates message `row` of the list as a click would.
    void activate(int row);
    void setListVisible(bool visible);

signals:
    void lineActivated(int line);

protected:
    void changeEvent(QEvent* event) override;

private:
    QTreeWidgetItem* makeItem(Severity severity, const QString& text, int line, bool fromCheck,
                              MessageCause cause);
    void setStanding(QTreeWidgetItem* item, bool standing);
    // The newest of the most severe messages that stand (nullptr: none).
    QTreeWidgetItem* shownItem() const;
    void refreshLine();

    std::function<Place(int line)> m_placeOfLine;
    QPushButton* m_line = nullptr;
    QPushButton* m_clearKey = nullptr;
    QTreeWidget* m_list = nullptr;
};

}  // namespace kerf::ui
