#include "ui/cycles/program_entry.h"

#include <QPlainTextEdit>

#include "core/cycles/cycle_registry.h"
#include "ui/cycles/cycle_block.h"
#include "ui/cycles/cycle_catalogue_dialog.h"
#include "ui/cycles/cycle_dialog.h"
#include "ui/cycles/path_function_dialog.h"
#include "ui/cycles/program_blocks.h"

namespace kerf::ui {

ProgramEntry::ProgramEntry(QPlainTextEdit& editor, QWidget* dialogParent)
    : m_editor(editor), m_parent(dialogParent) {}

// The editor is read-only while a program runs, loads, renumbers or saves: nothing is written.
bool ProgramEntry::chooseCycle() {
    if (m_editor.isReadOnly()) return false;
    CycleCatalogueDialog catalogue(m_parent);
    if (catalogue.exec() != QDialog::Accepted || !catalogue.selectedCycle()) return false;
    return defineCycle(catalogue.selectedCycle()->number);
}

bool ProgramEntry::defineCycle(int number) {
    if (m_editor.isReadOnly()) return false;
    const cycles::CycleDescriptor* cycle = cycles::findCycle(number);
    if (!cycle) return false;
    CycleDialog dialog(*cycle, programIsInch(*m_editor.document()), m_parent);
    if (dialog.exec() != QDialog::Accepted) return false;
    insertBlocks(m_editor, dialog.blocks());
    return true;
}

bool ProgramEntry::editCycleAtCursor() {
    if (m_editor.isReadOnly()) return false;
    const QTextDocument& document = *m_editor.document();
    const auto range = cycleDefinitionAt(document, m_editor.textCursor().blockNumber());
    if (!range) return false;
    const auto read = readCycleBlocks(blockTexts(document, *range));
    if (!read) return false;
    CycleDialog dialog(*read->cycle, programIsInch(document), m_parent);
    dialog.setValues(read->values);
    if (dialog.exec() != QDialog::Accepted) return false;
    replaceBlocks(m_editor, *range, dialog.blocks());
    return true;
}

bool ProgramEntry::cycleCall() {
    if (m_editor.isReadOnly()) return false;
    insertBlocks(m_editor, {QStringLiteral("CYCL CALL")});
    return true;
}

bool ProgramEntry::pathFunction(PathFunction function) {
    if (m_editor.isReadOnly()) return false;
    PathFunctionDialog dialog(function, m_parent);
    if (dialog.exec() != QDialog::Accepted) return false;
    insertBlocks(m_editor, {dialog.block()});
    return true;
}

}  // namespace kerf::ui
