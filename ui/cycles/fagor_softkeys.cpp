#include "ui/cycles/fagor_softkeys.h"

#include <QCoreApplication>

#include "ui/common/fagor_mode_names.h"
#include "ui/cycles/fagor_cycle_fields.h"
#include "ui/cycles/fagor_program_entry.h"
#include "ui/editor/program_editor.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

namespace {

// The twelve cycles, seven per row with Back as the eighth key.
std::vector<SoftkeyRow> cycleRows(ProgramEditor* editor, QWidget* parent, SoftkeyPaging paging) {
    std::vector<SoftkeyRow> rows;
    const std::vector<int>& cycles = fagorCycleNumbers();
    for (size_t i = 0; i < cycles.size(); ++i) {
        if (i % 7 == 0) rows.emplace_back();
        const int g = cycles[i];
        rows.back().push_back({QStringLiteral("fagorCycle%1").arg(g),
                               QStringLiteral("G%1\n%2").arg(g).arg(fagorCycleName(g)),
                               [editor, parent, paging, g] {
                                   if (defineFagorCycle(*editor, parent, g)) paging.back();
                                   editor->setFocus();
                               }});
    }
    for (SoftkeyRow& row : rows)
        row.push_back({"back", QCoreApplication::translate("kerf", "Back"), paging.back});
    return rows;
}

}  // namespace

std::vector<SoftkeyRow> fagorProgrammingRows(ProgramEditor* editor, QWidget* parent,
                                             SoftkeyPaging paging) {
    return {{
        {"fagorCycles", QCoreApplication::translate("kerf", "Canned\ncycles"),
         [editor, parent, paging] { paging.show(cycleRows(editor, parent, paging)); }},
        {"editCycle", QCoreApplication::translate("kerf", "Edit\ncycle"),
         [editor, parent] {
             if (!editFagorCycleAtCursor(*editor, parent))
                 informTouch(
                     parent,
                     QCoreApplication::translate(
                         "kerf", fagorProgrammingModeName(task::ProgrammingMode::Programming)),
                     QCoreApplication::translate("kerf",
                                                 "Put the cursor on a canned cycle block "
                                                 "(G66-G89) to edit it."));
             editor->setFocus();
         }},
    }};
}

}  // namespace kerf::ui
