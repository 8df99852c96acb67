#include "ui/cycles/fk_solution_keys.h"

#include <QCoreApplication>
#include <QTextBlock>

#include "ui/cycles/program_blocks.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"

namespace kerf::ui {

bool writeFkSelect(ProgramPanel& panel, int solution) {
    const std::optional<ProgramPanel::FkOffer> offer = panel.fkOffer();
    if (!offer || panel.fkOfferStale() || solution < 1 || solution > offer->solutions) return false;
    ProgramEditor& editor = *panel.editor();
    const QStringList block{QStringLiteral("FSELECT %1").arg(solution)};
    if (offer->selectLine > 0) {
        const int line = static_cast<int>(offer->selectLine) - 1;
        replaceBlocks(editor, {line, line}, block);
        editor.setTextCursor(QTextCursor(editor.document()->findBlockByNumber(line)));
        return true;
    }
    editor.setTextCursor(
        QTextCursor(editor.document()->findBlockByNumber(static_cast<int>(offer->afterLine) - 1)));
    insertBlocks(editor, block);
    return true;
}

SoftkeyRow fkSolutionRow(ProgramPanel& panel) {
    ProgramPanel* p = &panel;
    return {
        {"fkShowSolution", QCoreApplication::translate("kerf", "Show\nsolution"),
         [p] { p->showNextFkSolution(); }},
        {"fkSelectSolution", QCoreApplication::translate("kerf", "Select\nsolution"),
         [p] {
             if (const auto offer = p->fkOffer()) writeFkSelect(*p, offer->shown);
         }},
    };
}

}  // namespace kerf::ui
