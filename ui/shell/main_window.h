#pragma once

#include <QMainWindow>
#include <QString>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "core/machine/machine_config.h"
#include "core/task/machining_clock.h"
#include "core/task/move_check.h"
#include "core/task/operating_mode.h"
#include "ui/files/new_program.h"
#include "ui/session/machine_session.h"
#include "ui/shell/softkey_bar.h"
#include "ui/shell/workspace.h"

class QLabel;

namespace kerf::ui {

class FileManager;
class MachineKeys;
class MessagePanel;
class ModeController;
class PositionDisplay;
class StatusTabs;
class ProgramPanel;
class ModPage;
class SettingsPage;
class TableChooser;
class TableEditor;
class GraphicsPanel;
class TestRunController;
class UserScreenRun;
class UserScreenView;
class Workspace;

// What the window needs from the outside: the machine and the folders it works in.
struct HmiContext {
    machine::MachineConfig machine;
    std::filesystem::path ncRoot;          // programs and tables; the file manager stays inside
    std::filesystem::path recoveryFolder;  // autosave copies of unsaved programs
    bool programmingStation = false;       // no machine: Programming and Test run only
    std::string machineSource;  // --machine: a built-in name or the TOML file (settings write it)
    MotionFactory motion;       // the machine connection; none: no program run, no manual operation
    task::MachiningClockFactory machiningClock;  // the test run's time; none: no time
    task::MoveCheckFactory checkMoves;           // the machine's work-area check for the test run
};

// The operator panel: a header naming the machine mode and the programming mode, the message
// line and list, the workspace in the chosen layout, the vertical mode keys and the softkey
// bar whose rows follow the mode on screen.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(HmiContext context, QWidget* parent = nullptr);
    ~MainWindow() override;

    ModeController& modes() const { return *m_modes; }
    SoftkeyBar* softkeys() const { return m_softkeys; }
    MachineKeys* machineKeys() const { return m_machineKeys; }
    MessagePanel* messages() const { return m_messages; }
    Workspace* workspace() const { return m_workspace; }
    ProgramPanel* program() const { return m_program; }
    FileManager* files() const { return m_files; }
    TableEditor* tables() const { return m_tables; }
    GraphicsPanel* graphics() const { return m_graphics; }
    TestRunController* testRun() const { return m_testRun; }
    // Program run's graphics: the playback that follows the machine (nullptr without one).
    TestRunController* liveRun() const { return m_liveRun; }
    // Test run of the editor's program (main_window_testrun.cpp).
    void startTestRun();
    PositionDisplay* positions() const { return m_positions; }
    MachineSession* session() const { return m_session; }  // nullptr without a machine

    // Full-screen pages over the workspace panels.
    void showFiles();
    // Opens a table of the NC root (created with the standard columns if it does not exist).
    bool showTable(const std::filesystem::path& path);
    void showPanels();
    // Opens a file chosen in the file manager: tables in the table editor, the rest as programs.
    bool openFile(const std::filesystem::path& path);

    // Opens a program in the editor; unsaved edits of the one shown are saved or discarded first
    // as the operator answers (false: cancelled, or the file cannot be read).
    bool openProgram(const std::filesystem::path& path);
    // New program (main_window_programs.cpp): asks for the name, the unit and (mill) the blank,
    // writes the program into the folder chosen in the file manager (the NC root when none) and
    // opens it in Programming.
    bool newProgram();

    // The questions the window asks; tests answer them, the defaults are message boxes.
    enum class UnsavedChoice { Save, Discard, Cancel };
    struct Prompts {
        std::function<UnsavedChoice(const QString& program)> unsavedEdits;
        std::function<bool(const QString& question)> confirm;
        std::function<std::optional<NewProgramSpec>()> newProgram;
    };
    void setPrompts(Prompts prompts);
    // FAGOR lathe: runs the user customisation program of the mode on screen (USEREDIT.PIM in
    // Programming, USERMAN.PIM in manual modes, USERDPLY.PIM in execution; NC root) on the user
    // screen (main_window_userscreen.cpp). False when there is none or it fails its check.
    bool openUserScreen();
    // Before a FAGOR program runs: the IBn values it reads (false: the operator cancelled).
    bool askOperatorInputs(std::vector<std::pair<int, double>>& inputs);
    UserScreenRun* userScreenRun() const { return m_userScreenRun; }
    UserScreenView* userScreenView() const { return m_userScreenView; }
    // Switches the HMI to another language at run time ("en", "pt", "pl").
    bool setLanguage(const QString& code);
    void cycleLayout();

protected:
    void changeEvent(QEvent* event) override;
    // Asks before quitting while a program runs or the spindle turns, and what to do with unsaved
    // edits; unsaved edits that are kept go to the recovery folder.
    void closeEvent(QCloseEvent* event) override;

private:
    bool showProgram(const std::filesystem::path& path);
    // Unsaved edits of the program shown: saved, discarded or kept (false: the operator cancels).
    bool settleUnsavedEdits();
    // The same for the table being edited, before another table opens and before quitting.
    bool settleUnsavedTableEdits();
    // Asks about the unsaved edits of `name`; true when they are saved or given up.
    bool settle(const QString& name, const std::function<bool()>& save,
                const std::function<void()>& discard);
    void retranslate();
    void refreshHeader();
    void refreshSoftkeys();
    SoftkeyRow commonRow();
    std::vector<SoftkeyRow> fileRows();
    std::vector<SoftkeyRow> tableRows();
    void nextLanguage();
    // The machine session's wiring, keys and program start (main_window_session.cpp).
    void connectSession();
    std::vector<SoftkeyRow> machineRows();
    void startEditorProgram(std::optional<uint32_t> startLine);
    // Program run's graphics and status tabs follow the machine (main_window_live.cpp).
    void connectLiveRun();
    // The status tabs at the machine's program status, with the machine's spindle and coolant
    // once no program moves it (the manual keys and a Stop change them); not while the test run
    // is on the screen.
    void showMachineProgramStatus();
    // The graphics panel and the test run (main_window_testrun.cpp).
    void createGraphics(QWidget* parent);
    bool testRunOnScreen() const;
    void prepareTestRun();
    std::vector<SoftkeyRow> testRunRows();

    // The FAGOR user screen (main_window_userscreen.cpp).
    std::vector<SoftkeyRow> userScreenRows();
    SoftkeyRow userScreenOpenRow();
    void userScreenChanged();
    void userScreenEnded(bool failed);

    enum class Page { Panels, Files, Table, TableChooser, Settings, Mod, UserScreen };
    // The tables chooser, machine parameters and MOD (main_window_setup.cpp).
    void createSetupPages(QWidget* central);
    void showSetupPage(Page page);
    std::vector<SoftkeyRow> setupRows();

    HmiContext m_context;
    Prompts m_prompts;
    ModeController* m_modes = nullptr;
    QLabel* m_machineMode = nullptr;
    QLabel* m_programmingMode = nullptr;
    MessagePanel* m_messages = nullptr;
    Workspace* m_workspace = nullptr;
    ProgramPanel* m_program = nullptr;
    GraphicsPanel* m_graphics = nullptr;
    TestRunController* m_testRun = nullptr;
    TestRunController* m_liveRun = nullptr;
    StatusTabs* m_status = nullptr;
    // The last status of the machine's run (or MDI block) and of the test run: the tabs show the
    // one of the screen on view, also after the other screen was shown.
    interp::ProgramStatus m_machineProgramStatus;
    interp::ProgramStatus m_testRunProgramStatus;
    bool m_showsTestRunStatus = false;
    PositionDisplay* m_positions = nullptr;
    MachineSession* m_session = nullptr;
    MachineKeys* m_machineKeys = nullptr;
    SoftkeyBar* m_softkeys = nullptr;
    FileManager* m_files = nullptr;
    TableEditor* m_tables = nullptr;
    TableChooser* m_tableChooser = nullptr;
    SettingsPage* m_settingsPage = nullptr;
    ModPage* m_modPage = nullptr;
    UserScreenRun* m_userScreenRun = nullptr;
    UserScreenView* m_userScreenView = nullptr;
    Page m_page = Page::Panels;
    // The layout the operator chose with the screen-layout key in each machine mode, brought back
    // when the mode is chosen again (as the TNC keeps one per mode).
    std::map<task::MachineMode, WorkspaceLayout> m_machineModeLayouts;
};

}  // namespace kerf::ui
