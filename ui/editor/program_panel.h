#pragma once

#include <QString>
#include <QWidget>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

#include "core/base/diagnostic.h"
#include "core/machine/machine_config.h"
#include "core/task/move_check.h"
#include "core/task/program_sketch.h"
#include "ui/editor/program_file.h"
#include "ui/editor/recovery_store.h"

class QLabel;
class QTimer;

namespace kerf::ui {

class BackgroundWriter;
class FindBar;
class FkSketchView;
class ProgramChecker;
class ProgramLoader;
class ProgramEditor;

// The program panel of the workspace: the open program's name, the editor and its find bar.
// It checks the text a moment after each edit, autosaves unsaved edits to the recovery store
// and saves atomically in the file's own encoding and line ends. A program with FK blocks gets
// the FK programming graphics beside the editor (FkSketchView), from the same check. The
// explicit "Check program" runs the program dry as `kerf check` does (too slow to repeat after
// every pause in typing on a large program, so the check while typing stays static).
class ProgramPanel : public QWidget {
    Q_OBJECT

public:
    struct Settings {
        machine::MachineConfig machine;
        std::filesystem::path ncRoot;
        std::filesystem::path recoveryFolder;
        int autosaveDelayMs = 3000;  // after the last edit
        int checkDelayMs = 400;      // after the last edit
        // Files from this size on are read in the background (ProgramLoader); open() returns at
        // once and fileChanged() follows when the program is there.
        uintmax_t backgroundLoadBytes = 1u << 20;
    };

    ProgramPanel(Settings settings, QWidget* parent = nullptr);
    ~ProgramPanel() override;

    // The machine's work-area check for "Check program", and where the workpiece origin is
    // (ProgramChecker::setWorkAreaCheck). Before the first check.
    void setWorkAreaCheck(task::MoveCheckFactory checkMoves, std::function<Pose()> origin);

    // False (and message()) if the file cannot be read; false too while the current program is
    // still being loaded or renumbered. While it is being saved, the file opens once the save
    // has succeeded (true: under way).
    bool open(const std::filesystem::path& path);
    bool loading() const;
    // Writes the file (atomically). A long program whose numbers are stale is renumbered first,
    // in slices between events; a large one is written by a worker with the editor read-only
    // meanwhile. message() reports the result; true then means "under way".
    bool save();
    const std::filesystem::path& path() const { return m_path; }
    bool modified() const;

    // An autosaved copy newer than the file was found when it was opened.
    bool recoveryAvailable() const { return m_recovered.has_value(); }
    void restoreRecovery();
    void discardRecovery();
    // The operator gives the edits up (the program is about to be replaced or closed): no
    // autosave copy is kept and the text counts as unmodified; the file stays as saved.
    void abandonEdits();
    // Writes the autosave copy now (the timer does this after each pause in typing).
    void autosave();

    // The static check of the text now (the editor makes it after each pause in typing).
    void checkNow();
    // "Check program": the check `kerf check` makes, which also runs the program dry, in the
    // background; its diagnostics replace the list and a message sums the result up.
    void checkProgram();
    bool checkingProgram() const { return m_runCheck != 0; }
    const DiagnosticList& diagnostics() const { return m_diagnostics; }

    // An FK element with several solutions, offered for FSELECT: the one at the cursor (its
    // block, the block after which FSELECT belongs, or its FSELECT), else the first not chosen.
    struct FkOffer {
        int solutions = 0;
        int shown = 1;            // the solution drawn highlighted, 1-based
        int chosen = 0;           // the n of the FSELECT already written; 0: none
        uint32_t afterLine = 0;   // FSELECT belongs after this block (1-based line)
        uint32_t selectLine = 0;  // the line of the FSELECT written; 0: none
    };
    std::optional<FkOffer> fkOffer() const;
    // The text changed since the offer was found: its lines may be out of date until the check
    // of the new text comes back.
    bool fkOfferStale() const { return m_sketchStale; }
    // Draws the next solution of the offer highlighted (after the last, the first).
    void showNextFkSolution();
    FkSketchView* fkSketch() const { return m_sketchView; }

    ProgramEditor* editor() const { return m_editor; }
    FindBar* findBar() const { return m_findBar; }
    ProgramChecker* checker() const { return m_checker; }

signals:
    void message(kerf::Severity severity, const QString& text);
    void diagnosticsChanged(const kerf::DiagnosticList& diagnostics);
    void fileChanged();
    // An FK offer appeared or went away (the softkeys to choose a solution follow it).
    void fkOfferChanged();

protected:
    void changeEvent(QEvent* event) override;

private:
    void onEdited();
    // Drops the diagnostics shown and any check under way (the text is being replaced).
    void forgetDiagnostics();
    void watchDocument();
    // `text`: the program as read, for the first check (copying a large document back out would
    // block the UI thread).
    void finishOpen(const std::filesystem::path& path, const QString& text);
    void refreshTitle();
    void reportProgramCheck();
    void showSketch(std::shared_ptr<const task::ProgramSketch> sketch);
    // Finds the offer for the cursor (after a new check: `newSketch`); fkOfferChanged() only
    // when an offer appears or goes, so that the softkeys do not jump after every edit.
    void refreshFkOffer(bool newSketch);
    bool write();
    bool finishWrite(const MaybeError& error);

    Settings m_settings;
    RecoveryStore m_recovery;
    std::filesystem::path m_path;
    ProgramText m_file;
    std::optional<QString> m_recovered;
    DiagnosticList m_diagnostics;
    uint64_t m_awaitedCheck = 0;  // the check whose result belongs to the text shown; 0: none
    uint64_t m_runCheck = 0;      // the awaited check is checkProgram()'s; 0: none under way
    QLabel* m_title = nullptr;
    ProgramEditor* m_editor = nullptr;
    FindBar* m_findBar = nullptr;
    ProgramChecker* m_checker = nullptr;
    FkSketchView* m_sketchView = nullptr;
    std::shared_ptr<const task::ProgramSketch> m_sketch;
    int m_offer = -1;  // index into the sketch's FK ambiguities; -1: none
    int m_shownSolution = 1;
    bool m_sketchStale = false;
    ProgramLoader* m_loader = nullptr;
    BackgroundWriter* m_writer = nullptr;
    QTimer* m_autosaveTimer = nullptr;
    QTimer* m_checkTimer = nullptr;
    bool m_loading = false;
    bool m_saveAfterRenumber = false;
    // A program asked for while the one shown was being saved (renumbered, then written by the
    // worker): opened once the edits are on disk, not when the save fails (they would be lost).
    std::optional<std::filesystem::path> m_openAfterSave;
    bool m_readOnlyBeforeWrite = false;
};

}  // namespace kerf::ui
