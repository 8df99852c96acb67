#pragma once

#include <QPlainTextEdit>

#include "core/base/diagnostic.h"
#include "core/program/dialect.h"

namespace kerf::ui {

class VisibleHighlighter;

// The program text: block-structured editing with automatic block numbers, syntax colours for
// the visible lines, and the check's diagnostics underlined on their lines.
class ProgramEditor : public QPlainTextEdit {
    Q_OBJECT

public:
    // Up to this many lines, inserting a block renumbers the blocks after it at once (as the
    // TNC does); longer programs are renumbered on save, so that Enter stays instant.
    static constexpr int kLiveRenumberLimit = 20000;

    explicit ProgramEditor(QWidget* parent = nullptr);

    // Shows a document built elsewhere (ProgramLoader) and takes ownership of it.
    void adoptDocument(QTextDocument* document);
    void setDialect(program::Dialect dialect);
    program::Dialect dialect() const;
    VisibleHighlighter& highlighter() const { return *m_highlighter; }

    // Inserts a line break with the next block number, as Enter does.
    void insertBlock();
    // Gives every numbered line its block number (Klartext: its line index; ISO: the first
    // number then steps of 10). One undo step; false if all numbers were already right.
    bool renumber();
    bool numbersStale() const { return m_numbersStale; }

    // 1-based line; the line is moved to the middle of the view.
    void goToLine(int line);
    int currentLine() const;
    void setDiagnostics(const DiagnosticList& diagnostics);

protected:
    void keyPressEvent(QKeyEvent* event) override;

private:
    VisibleHighlighter* m_highlighter = nullptr;
    bool m_numbersStale = false;
};

}  // namespace kerf::ui
