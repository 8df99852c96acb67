#pragma once

#include <QPlainTextEdit>
#include <optional>

#include "core/base/diagnostic.h"
#include "core/program/dialect.h"
#include "ui/editor/block_numbers.h"
#include "ui/editor/label_references.h"

namespace kerf::ui {

class RenumberJob;
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

    // Inserts a line break with the next block number, as Enter does (planBlockInsertion: the
    // blocks after it renumbered; a FAGOR program's references follow their labels, and when they
    // could not, no number changes, the new line gets none and labelsKept() says why).
    void insertBlock();
    // Gives every block its number (Klartext: the previous block's + 1, BEGIN PGM 0, lines that
    // continue a block unnumbered; ISO: as `numbering` says, by default the first number then
    // steps of 10). Only changed numbers are rewritten, as one undo step. Up to
    // kLiveRenumberLimit lines this happens at once; longer programs are renumbered in slices
    // between events (the editor read-only meanwhile), so that the UI stays responsive.
    // renumbered() tells when it is done. A FAGOR program whose labels could not keep their
    // references (fagorRenumberProblem) is left as it is: the problem is returned and
    // renumbered(false) emitted at once.
    std::optional<RenumberProblem> renumber(BlockNumbering numbering = {});
    // The same at once, whatever the length; false if all numbers were already right.
    bool renumberNow(BlockNumbering numbering = {});
    bool renumbering() const;
    bool numbersStale() const { return m_numbersStale; }

    // 1-based line; the line is moved to the middle of the view.
    void goToLine(int line);
    int currentLine() const;
    void setDiagnostics(const DiagnosticList& diagnostics);

signals:
    // `changed`: some number was rewritten.
    void renumbered(bool changed);
    // Enter left the numbers of a FAGOR program as they were: renumbering would have broken it.
    void labelsKept(const kerf::ui::RenumberProblem& problem);

protected:
    void keyPressEvent(QKeyEvent* event) override;

private:
    VisibleHighlighter* m_highlighter = nullptr;
    bool m_numbersStale = false;
    RenumberJob* m_renumberJob = nullptr;
    bool m_readOnlyBeforeRenumber = false;
};

}  // namespace kerf::ui
