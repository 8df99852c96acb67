#include "ui/shell/main_window.h"

#include <QCloseEvent>
#include <QEvent>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QTreeWidget>
#include <QVBoxLayout>

#include "core/program/nc_root.h"
#include "ui/common/diagnostic_text.h"
#include "ui/cycles/fk_solution_keys.h"
#include "ui/cycles/programming_softkeys.h"
#include "ui/editor/block_numbers.h"
#include "ui/editor/find_bar.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/files/file_manager.h"
#include "ui/shell/block_prompt.h"
#include "ui/shell/machine_keys.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/renumber_prompt.h"
#include "ui/shell/ui_language.h"
#include "ui/shell/workspace.h"
#include "ui/status/position_display.h"
#include "ui/status/status_tabs.h"
#include "ui/tables/table_editor.h"
#include "ui/tables/table_kinds.h"
#include "ui/viewport/graphics_panel.h"

namespace kerf::ui {

namespace {

QLabel* makeModeLabel(const QString& name, QWidget* parent) {
    auto* label = new QLabel(parent);
    label->setObjectName(name);
    label->setMinimumHeight(36);
    label->setMargin(6);
    return label;
}

}  // namespace

MainWindow::MainWindow(HmiContext context, QWidget* parent)
    : QMainWindow(parent), m_context(std::move(context)) {
    m_modes = new ModeController(!m_context.programmingStation, this);
    m_modes->setFagorNames(m_context.machine.kind == machine::MachineKind::Lathe);
    auto* central = new QWidget(this);
    auto* layout = new QVBoxLayout(central);
    layout->setContentsMargins(6, 6, 6, 6);

    auto* header = new QHBoxLayout();
    m_machineMode = makeModeLabel("machineMode", central);
    m_programmingMode = makeModeLabel("programmingMode", central);
    header->addWidget(m_machineMode, 1);
    header->addWidget(m_programmingMode, 1);
    layout->addLayout(header);

    m_messages = new MessagePanel(central);
    layout->addWidget(m_messages);

    ProgramPanel::Settings programSettings;
    programSettings.machine = m_context.machine;
    programSettings.ncRoot = m_context.ncRoot;
    programSettings.recoveryFolder = m_context.recoveryFolder;
    m_program = new ProgramPanel(programSettings, central);
    // Messages name the blocks of the program shown by their numbers.
    m_messages->setPlaceOfLine([editor = m_program->editor()](int line) {
        return MessagePanel::Place{blockNumberOfLine(*editor->document(), line, editor->dialect()),
                                   editor->dialect()};
    });
    // Enter in a FAGOR program that could not renumber its labels safely says why.
    connect(m_program->editor(), &ProgramEditor::labelsKept, this,
            [this](const RenumberProblem& problem) {
                m_messages->addMessage(Severity::Warning, renumberProblemText(problem),
                                       problem.line);
            });
    // Before a run reports one, the tabs name the parameters of the machine's language (the
    // lathe's FAGOR P) also on the screen that has not run a program yet.
    const char parameterLetter = m_context.machine.kind == machine::MachineKind::Lathe ? 'P' : 'Q';
    m_machineProgramStatus.parameterLetter = parameterLetter;
    m_testRunProgramStatus.parameterLetter = parameterLetter;
    createGraphics(central);
    m_status = new StatusTabs(parameterLetter, central);
    m_positions = new PositionDisplay(m_context.machine, central);
    m_workspace = new Workspace(m_program, m_graphics, m_status, m_positions, central);

    auto* middle = new QHBoxLayout();
    m_machineKeys = new MachineKeys(*m_modes, central);
    middle->addWidget(m_workspace, 1);
    middle->addWidget(m_machineKeys);
    layout->addLayout(middle, 1);

    m_files = new FileManager(m_context.ncRoot, central);
    m_tables = new TableEditor(m_context.ncRoot, central);
    m_files->hide();
    m_tables->hide();
    auto relay = [this](Severity severity, const QString& text) {
        m_messages->addMessage(severity, text);
    };
    connect(m_files, &FileManager::message, m_messages, relay);
    connect(m_tables, &TableEditor::message, m_messages, relay);
    connect(m_files, &FileManager::openRequested, this,
            [this](const std::filesystem::path& path) { openFile(path); });
    createSetupPages(central);

    m_softkeys = new SoftkeyBar(central);
    layout->addWidget(m_softkeys);
    setCentralWidget(central);

    connect(m_modes, &ModeController::modesChanged, this, [this] {
        refreshHeader();
        showPanels();
    });
    connect(m_modes, &ModeController::refused, this, [this](const QString& text) {
        // Refused while the machine moves: gone once it stands.
        m_messages->addMessage(Severity::Error, text, 0, MessageCause::Busy);
    });
    connect(m_messages, &MessagePanel::lineActivated, this, [this](int line) {
        showPanels();
        m_program->editor()->goToLine(line);
    });
    connectSession();
    connect(m_program, &ProgramPanel::diagnosticsChanged, m_messages,
            &MessagePanel::setCheckDiagnostics);
    connect(m_program, &ProgramPanel::fileChanged, m_messages, &MessagePanel::forgetLines);
    connect(m_program, &ProgramPanel::message, m_messages, relay);
    // The FK solution keys come and go with an element that has several solutions.
    connect(m_program, &ProgramPanel::fkOfferChanged, this, [this] {
        if (m_page == Page::Panels && m_modes->screen() == ScreenMode::Programming &&
            !testRunOnScreen())
            refreshSoftkeys();
    });
    retranslate();
    resize(1280, 800);
}

MainWindow::~MainWindow() = default;

bool MainWindow::openFile(const std::filesystem::path& path) {
    // From the file manager: a file of the NC root, judged after its links (docs/files.md).
    if (const MaybeError refused = program::NcRoot(m_context.ncRoot).admit(path)) {
        m_messages->addMessage(Severity::Error, translatedMessage(*refused));
        return false;
    }
    if (isTableFile(path)) return showTable(path);
    if (!openProgram(path)) return false;
    m_modes->requestProgrammingMode(task::ProgrammingMode::Programming);
    return true;
}

void MainWindow::showFiles() {
    m_page = Page::Files;
    m_workspace->showPage(m_files);
    refreshSoftkeys();
}

bool MainWindow::showTable(const std::filesystem::path& path) {
    // The tables of the NC root (TOOL.T, PRESET.PR ...) go through its file-access layer.
    const program::NcRoot root(m_context.ncRoot);
    if (const MaybeError refused = root.admit(path)) {
        m_messages->addMessage(Severity::Error, translatedMessage(*refused));
        return false;
    }
    std::error_code error;
    if (!std::filesystem::exists(std::filesystem::symlink_status(path, error))) {
        // A fresh NC root gets the standard tables, as a new control has them.
        const std::string content = defaultTableContent(tableKindOf(path), path);
        if (!content.empty()) {
            if (const MaybeError failed = root.replace(path, content)) {
                m_messages->addMessage(Severity::Error, translatedMessage(*failed));
                return false;
            }
        }
    }
    if (!settleUnsavedTableEdits() || !m_tables->open(path)) return false;
    m_page = Page::Table;
    m_workspace->showPage(m_tables);
    refreshSoftkeys();
    return true;
}

void MainWindow::showPanels() {
    m_page = Page::Panels;
    m_workspace->showPanels();
    refreshSoftkeys();
}

bool MainWindow::setLanguage(const QString& code) {
    return switchLanguage(code);
}

void MainWindow::cycleLayout() {
    const int next = (static_cast<int>(m_workspace->layoutKind()) + 1) % 4;
    m_workspace->setLayoutKind(static_cast<WorkspaceLayout>(next));
    if (m_session != nullptr && m_modes->screen() == ScreenMode::Machine)
        m_machineModeLayouts[m_modes->machineMode()] = m_workspace->layoutKind();
}

void MainWindow::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslate() {
    setWindowTitle(tr("Kerf - %1").arg(QString::fromStdString(m_context.machine.name)));
    m_machineKeys->retranslate();
    refreshHeader();
    refreshSoftkeys();
}

void MainWindow::refreshHeader() {
    // The mode on screen is highlighted; the other one stays named in the header.
    const bool machineOnScreen = m_modes->screen() == ScreenMode::Machine;
    const QString active = QStringLiteral("background: #1f4e79; color: white; font-weight: bold;");
    const QString passive = QStringLiteral("background: #d9d9d9; color: #303030;");
    m_machineMode->setText(m_modes->machineConnected()
                               ? m_modes->machineModeText(m_modes->machineMode())
                               : tr("Programming station"));
    m_programmingMode->setText(m_modes->programmingModeText(m_modes->programmingMode()));
    m_machineMode->setStyleSheet(machineOnScreen ? active : passive);
    m_programmingMode->setStyleSheet(machineOnScreen ? passive : active);
}

SoftkeyRow MainWindow::commonRow() {
    const std::filesystem::path root = m_context.ncRoot;
    return {
        {"layout", tr("Screen\nlayout"), [this] { cycleLayout(); }},
        {"files", tr("Files"), [this] { showFiles(); }},
        {"toolTable", tr("Tool\ntable"), [this, root] { showTable(root / "TOOL.T"); }},
        {"tables", tr("Tables"), [this] { showSetupPage(Page::TableChooser); }},
        {"mod", tr("MOD"), [this] { showSetupPage(Page::Mod); }},
        {"messages", tr("Message\nlist"),
         [this] { m_messages->setListVisible(m_messages->list()->isHidden()); }},
        {"clearMessages", tr("Clear\nmessages"), [this] { m_messages->clearMessages(); }},
        {"language", tr("Language\n%1").arg(currentLanguage().toUpper()),
         [this] { nextLanguage(); }},
    };
}

void MainWindow::nextLanguage() {
    const QStringList languages = availableLanguages();
    const int next = (static_cast<int>(languages.indexOf(currentLanguage())) + 1) %
                     static_cast<int>(languages.size());
    setLanguage(languages[next]);
}

std::vector<SoftkeyRow> MainWindow::fileRows() {
    return {
        {
            {"fileOpen", tr("Open"), [this] { m_files->openSelected(); }},
            {"fileCopy", tr("Copy"), [this] { m_files->copySelected(); }},
            {"fileMove", tr("Move"), [this] { m_files->moveSelected(); }},
            {"fileRename", tr("Rename"), [this] { m_files->renameSelected(); }},
            {"fileDelete", tr("Delete"), [this] { m_files->deleteSelected(); }},
            {"fileProtect", tr("Protect /\nunprotect"), [this] { m_files->toggleProtection(); }},
            {"fileNewFolder", tr("New\nfolder"), [this] { m_files->newFolder(); }},
            {"back", tr("Back"), [this] { showPanels(); }},
        },
        {
            {"fileNewProgram", tr("New\nprogram"), [this] { newProgram(); }},
            {"back", tr("Back"), [this] { showPanels(); }},
        }};
}

std::vector<SoftkeyRow> MainWindow::tableRows() {
    return {{
        {"tableSave", tr("Save"), [this] { m_tables->save(); }},
        {"tableInsert", tr("Insert\nrow"), [this] { m_tables->insertRow(); }},
        {"tableDelete", tr("Delete\nrow"), [this] { m_tables->deleteRow(); }},
        {"tableUndo", tr("Undo"), [this] { m_tables->undo(); }},
        {"back", tr("Back"), [this] { showPanels(); }},
    }};
}

void MainWindow::refreshSoftkeys() {
    if (m_page == Page::Files) return m_softkeys->setRows(fileRows());
    if (m_page == Page::Table) return m_softkeys->setRows(tableRows());
    if (m_page == Page::UserScreen) return m_softkeys->setRows(userScreenRows());
    if (m_page != Page::Panels) return m_softkeys->setRows(setupRows());
    std::vector<SoftkeyRow> rows;
    if (testRunOnScreen()) {
        rows = testRunRows();
        rows.push_back(commonRow());
    } else if (m_modes->screen() == ScreenMode::Programming) {
        ProgramEditor* editor = m_program->editor();
        if (m_program->fkOffer()) rows.push_back(fkSolutionRow(*m_program));
        rows.push_back({
            {"save", tr("Save"), [this] { m_program->save(); }},
            {"find", tr("Find /\nreplace"), [this] { m_program->findBar()->open(); }},
            {"undo", tr("Undo"), [editor] { editor->undo(); }},
            {"redo", tr("Redo"), [editor] { editor->redo(); }},
            {"goto", tr("Go to\nblock"),
             [this, editor] {
                 if (const auto line =
                         askForBlockLine(this, tr("Go to block"), *editor, *m_messages))
                     editor->goToLine(*line);
             }},
            {"renumber", tr("Renumber\nblocks"),
             [this, editor] { renumberBlocks(this, *editor, *m_messages); }},
            {"check", tr("Check\nprogram"), [this] { m_program->checkProgram(); }},
            {"restore", tr("Restore\nautosave"), [this] { m_program->restoreRecovery(); }},
        });
        // CYCL DEF, CYCL CALL, TOOL CALL and the path functions (ui/cycles).
        const SoftkeyPaging paging{
            [this](std::vector<SoftkeyRow> r) { m_softkeys->setRows(std::move(r)); },
            [this] { refreshSoftkeys(); },
            [this] {
                return ProgramPlace{m_context.ncRoot, m_program->path().empty()
                                                          ? std::filesystem::path()
                                                          : m_program->path().parent_path()};
            }};
        rows.push_back(commonRow());
        for (SoftkeyRow& row : programmingEntryRows(editor, this, paging))
            rows.push_back(std::move(row));
    } else {
        rows = machineRows();
        rows.push_back(commonRow());
    }
    if (m_context.machine.kind == machine::MachineKind::Lathe && !testRunOnScreen())
        rows.push_back(userScreenOpenRow());
    m_softkeys->setRows(std::move(rows));
}

}  // namespace kerf::ui
