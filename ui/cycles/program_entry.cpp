#include "ui/cycles/program_entry.h"

#include <QCoreApplication>
#include <QPlainTextEdit>

#include "core/cycles/cycle_registry.h"
#include "ui/cycles/cycle_block.h"
#include "ui/cycles/cycle_catalogue_dialog.h"
#include "ui/cycles/cycle_dialog.h"
#include "ui/cycles/iso_blocks.h"
#include "ui/cycles/path_function_dialog.h"
#include "ui/cycles/program_blocks.h"
#include "ui/cycles/special_function_dialog.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

ProgramEntry::ProgramEntry(QPlainTextEdit& editor, QWidget* dialogParent, program::Dialect dialect,
                           ProgramPlace place)
    : m_editor(editor), m_parent(dialogParent), m_dialect(dialect), m_place(std::move(place)) {}

bool ProgramEntry::explain(const QString& why) {
    informTouch(m_parent, QCoreApplication::translate("kerf", "Programming"), why);
    return false;
}

bool ProgramEntry::write(const QStringList& blocks, const LineRange* replace) {
    QStringList written = blocks;
    if (m_dialect == program::Dialect::TncIso) {
        const IsoResult iso = isoCycleBlock(blocks);
        if (!iso.error.isEmpty()) return explain(iso.error);
        written = QStringList{iso.block};
    }
    if (replace)
        replaceBlocks(m_editor, *replace, written, m_dialect);
    else
        insertBlocks(m_editor, written, m_dialect);
    return true;
}

bool ProgramEntry::writePath(PathFunction function, const QStringList& values) {
    if (m_dialect != program::Dialect::TncIso) {
        insertBlocks(m_editor, {writePathFunction(function, values)}, m_dialect);
        return true;
    }
    const IsoResult iso = isoPathBlock(function, values);
    if (!iso.error.isEmpty()) return explain(iso.error);
    insertBlocks(m_editor, {iso.block}, m_dialect);
    return true;
}

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
    return write(dialog.blocks());
}

bool ProgramEntry::editCycleAtCursor() {
    if (m_editor.isReadOnly()) return false;
    const QTextDocument& document = *m_editor.document();
    const auto range = cycleDefinitionAt(document, m_editor.textCursor().blockNumber(), m_dialect);
    if (!range) return false;
    const auto read = readCycleBlocks(blockTexts(document, *range, m_dialect));
    if (!read) return false;
    CycleDialog dialog(*read->cycle, programIsInch(document), m_parent);
    dialog.setValues(read->values);
    if (dialog.exec() != QDialog::Accepted) return false;
    return write(dialog.blocks(), &*range);
}

bool ProgramEntry::cycleCall() {
    if (m_editor.isReadOnly()) return false;
    insertBlocks(m_editor,
                 {m_dialect == program::Dialect::TncIso ? QStringLiteral("G79")
                                                        : QStringLiteral("CYCL CALL")},
                 m_dialect);
    return true;
}

bool ProgramEntry::pathFunction(PathFunction function) {
    if (m_editor.isReadOnly()) return false;
    PathFunctionDialog dialog(function, m_parent);
    if (dialog.exec() != QDialog::Accepted) return false;
    return writePath(function, dialog.values());
}

bool ProgramEntry::specialFunction(SpecialFunction function) {
    if (m_editor.isReadOnly()) return false;
    QStringList values;
    if (!specialFields(function).empty()) {
        SpecialFunctionDialog dialog(function, m_place, m_parent);
        if (dialog.exec() != QDialog::Accepted) return false;
        values = dialog.values();
    }
    insertBlocks(m_editor, {writeSpecialFunction(function, values, m_dialect)}, m_dialect);
    return true;
}

}  // namespace kerf::ui
