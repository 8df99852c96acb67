#include "ui/shell/renumber_prompt.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>
#include <QTextBlock>
#include <algorithm>
#include <optional>

#include "ui/editor/program_editor.h"
#include "ui/shell/message_panel.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

namespace {

// The texts' translation context.
class RenumberPrompt {
    Q_DECLARE_TR_FUNCTIONS(kerf::ui::RenumberPrompt)
};

// The program's first label, 10 when it has none.
int firstLabel(const ProgramEditor& editor) {
    for (QTextBlock block = editor.document()->begin(); block.isValid(); block = block.next()) {
        if (const auto number = readBlockNumber(block.text(), program::Dialect::Fagor))
            return static_cast<int>(std::min(number->number, kFagorMaxLabel));
    }
    return 10;
}

std::optional<BlockNumbering> askForNumbering(QWidget* parent, const ProgramEditor& editor) {
    QDialog dialog(parent);
    dialog.setObjectName(QStringLiteral("renumberPrompt"));
    dialog.setWindowTitle(RenumberPrompt::tr("Renumber blocks"));
    auto* form = new QFormLayout(&dialog);
    auto* first = new QSpinBox(&dialog);
    first->setObjectName(QStringLiteral("firstLabel"));
    first->setRange(0, static_cast<int>(kFagorMaxLabel));
    first->setValue(firstLabel(editor));
    auto* step = new QSpinBox(&dialog);
    step->setObjectName(QStringLiteral("labelStep"));
    step->setRange(1, 1000);
    step->setValue(10);
    form->addRow(RenumberPrompt::tr("First block number N"), first);
    form->addRow(RenumberPrompt::tr("Step"), step);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    form->addRow(buttons);
    makeTouchSized(dialog);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    return BlockNumbering{first->value(), step->value()};
}

}  // namespace

QString renumberProblemText(const RenumberProblem& problem) {
    switch (problem.kind) {
        case RenumberProblem::Kind::ComputedReference:
            return RenumberPrompt::tr(
                       "Blocks not renumbered: line %1 names a label through a "
                       "parameter, which could not follow it")
                .arg(problem.line);
        case RenumberProblem::Kind::ProfileLabelTooLong:
            return RenumberPrompt::tr(
                       "Blocks not renumbered: the profile of the cycle in line %1 "
                       "would start or end at N%2; G66, G68 and G69 take labels of "
                       "4 digits")
                .arg(problem.line)
                .arg(problem.label);
        case RenumberProblem::Kind::LabelTooLong:
            return RenumberPrompt::tr(
                       "Blocks not renumbered: line %1 would get N%2, beyond "
                       "N99999999")
                .arg(problem.line)
                .arg(problem.label);
        case RenumberProblem::Kind::LabelInUse:
            return RenumberPrompt::tr(
                       "Blocks not renumbered: line %1 would get N%2, which line %3 "
                       "carries already; the new line has no block number")
                .arg(problem.line)
                .arg(problem.label)
                .arg(problem.otherLine);
    }
    return {};
}

void renumberBlocks(QWidget* parent, ProgramEditor& editor, MessagePanel& messages) {
    if (editor.dialect() != program::Dialect::Fagor) {
        editor.renumber();
        return;
    }
    const auto numbering = askForNumbering(parent, editor);
    if (!numbering) return;
    if (const auto problem = editor.renumber(*numbering))
        messages.addMessage(Severity::Error, renumberProblemText(*problem), problem->line);
}

}  // namespace kerf::ui
