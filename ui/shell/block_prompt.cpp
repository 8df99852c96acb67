#include "ui/shell/block_prompt.h"

#include <QCoreApplication>
#include <QInputDialog>
#include <QTextBlock>

#include "ui/common/block_name.h"
#include "ui/editor/block_numbers.h"
#include "ui/editor/program_editor.h"
#include "ui/shell/message_panel.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

namespace {

// The texts' translation context.
class BlockPrompt {
    Q_DECLARE_TR_FUNCTIONS(kerf::ui::BlockPrompt)
};

}  // namespace

std::optional<int> askForBlockLine(QWidget* parent, const QString& title,
                                   const ProgramEditor& editor, MessagePanel& messages) {
    const QTextDocument& document = *editor.document();
    const program::Dialect dialect = editor.dialect();
    QInputDialog dialog(parent);
    dialog.setObjectName(QStringLiteral("blockPrompt"));
    dialog.setWindowTitle(title);
    dialog.setInputMode(QInputDialog::IntInput);
    const int currentLine = editor.currentLine();
    makeTouchSized(dialog);
    if (!numbersBlocks(document, dialect)) {
        dialog.setLabelText(BlockPrompt::tr("Line"));
        dialog.setIntRange(1, document.blockCount());
        dialog.setIntValue(currentLine);
        if (dialog.exec() != QDialog::Accepted) return std::nullopt;
        return dialog.intValue();
    }
    dialog.setLabelText(dialect == program::Dialect::Klartext ? BlockPrompt::tr("Block number")
                                                              : BlockPrompt::tr("Block number N"));
    dialog.setIntRange(0, 1 << 30);
    // The block the cursor is in (the line's own number, if it has one).
    dialog.setIntValue(static_cast<int>(
        std::max<long long>(0, blockNumberOfLine(document, currentLine, dialect))));
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    const long long number = dialog.intValue();
    if (const auto line = lineOfBlock(document, number, dialect)) return *line;
    messages.addMessage(
        Severity::Error,
        BlockPrompt::tr("The program has no block %1").arg(blockShortName(number, 0, dialect)));
    return std::nullopt;
}

}  // namespace kerf::ui
