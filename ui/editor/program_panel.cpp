#include "ui/editor/program_panel.h"

#include <QEvent>
#include <QLabel>
#include <QSplitter>
#include <QTextDocument>
#include <QTimer>
#include <QVBoxLayout>
#include <utility>

#include "ui/common/diagnostic_text.h"
#include "ui/editor/background_writer.h"
#include "ui/editor/find_bar.h"
#include "ui/editor/fk_sketch_view.h"
#include "ui/editor/program_checker.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_loader.h"

namespace kerf::ui {

namespace {

QString fileText(const std::filesystem::path& path) {
    return QString::fromStdString(path.string());
}

bool isLathe(const machine::MachineConfig& machine) {
    const machine::AxisConfig* x = machine.axis('X');
    return x != nullptr && x->diameterMode;
}

}  // namespace

ProgramPanel::ProgramPanel(Settings settings, QWidget* parent)
    : QWidget(parent), m_settings(std::move(settings)), m_recovery(m_settings.recoveryFolder) {
    setObjectName("programPanel");
    registerDiagnosticMetaTypes();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_title = new QLabel(this);
    m_title->setObjectName("programTitle");
    auto* split = new QSplitter(Qt::Horizontal, this);
    m_editor = new ProgramEditor(split);
    // Before a program is opened the lathe's editor speaks FAGOR: its rows offer the canned
    // cycles G66-G89, not the TNC's CYCL DEF and path keys.
    if (isLathe(m_settings.machine)) m_editor->setDialect(program::Dialect::Fagor);
    m_sketchView = new FkSketchView(split);
    m_sketchView->hide();  // until the program has FK blocks
    split->addWidget(m_editor);
    split->addWidget(m_sketchView);
    m_findBar = new FindBar(m_editor, this);
    layout->addWidget(m_title);
    layout->addWidget(split, 1);
    layout->addWidget(m_findBar);
    connect(m_editor, &QPlainTextEdit::cursorPositionChanged, this, [this] {
        m_sketchView->setCursorLine(m_editor->currentLine());
        refreshFkOffer(false);
    });

    m_checker = new ProgramChecker(m_settings.machine, m_settings.ncRoot, this);
    connect(m_checker, &ProgramChecker::sketched, this,
            [this](quint64 request, std::shared_ptr<const task::ProgramSketch> sketch) {
                if (request == m_awaitedCheck) showSketch(std::move(sketch));
            });
    connect(m_checker, &ProgramChecker::checked, this,
            [this](quint64 request, const DiagnosticList& diagnostics) {
                // A result of another text (an earlier edit, the program shown before) would
                // underline lines of a document it is not about.
                if (request != m_awaitedCheck) return;
                m_diagnostics.clear();
                // Only messages about this file point at editor lines; those about called programs
                // are listed without a line.
                const std::string self = m_path.string();
                for (Diagnostic d : diagnostics) {
                    if (!d.file.empty() && d.file != self) d.line = 0;
                    m_diagnostics.push_back(std::move(d));
                }
                m_editor->setDiagnostics(m_diagnostics);
                emit diagnosticsChanged(m_diagnostics);
                if (std::exchange(m_runCheck, 0) == request) reportProgramCheck();
            });
    m_autosaveTimer = new QTimer(this);
    m_autosaveTimer->setSingleShot(true);
    m_autosaveTimer->setInterval(m_settings.autosaveDelayMs);
    connect(m_autosaveTimer, &QTimer::timeout, this, &ProgramPanel::autosave);
    m_checkTimer = new QTimer(this);
    m_checkTimer->setSingleShot(true);
    m_checkTimer->setInterval(m_settings.checkDelayMs);
    connect(m_checkTimer, &QTimer::timeout, this, &ProgramPanel::checkNow);
    connect(m_editor, &ProgramEditor::renumbered, this, [this] {
        if (std::exchange(m_saveAfterRenumber, false)) write();
    });
    m_writer = new BackgroundWriter(this);
    m_loader = new ProgramLoader(this);
    connect(m_loader, &ProgramLoader::loaded, this,
            [this](QTextDocument* document, const ProgramText& format,
                   const std::filesystem::path& path) {
                m_file = format;
                m_editor->adoptDocument(document);
                m_editor->setReadOnly(false);
                watchDocument();
                finishOpen(path, std::exchange(m_file.text, {}));
            });
    connect(m_loader, &ProgramLoader::failed, this, [this](const Diagnostic& error) {
        m_editor->setReadOnly(false);
        checkNow();  // the program shown stays: its diagnostics come back
        emit message(Severity::Error, translatedMessage(error) + QStringLiteral(" (") +
                                          QString::fromStdString(error.file) + ')');
        refreshTitle();
    });
    watchDocument();
    refreshTitle();
}

void ProgramPanel::watchDocument() {
    // Connections to a replaced document go away with it.
    connect(m_editor->document(), &QTextDocument::contentsChanged, this, &ProgramPanel::onEdited);
    connect(m_editor->document(), &QTextDocument::modificationChanged, this,
            &ProgramPanel::refreshTitle);
}

bool ProgramPanel::loading() const {
    return m_loader->busy();
}

ProgramPanel::~ProgramPanel() = default;

void ProgramPanel::forgetDiagnostics() {
    m_checkTimer->stop();
    m_awaitedCheck = 0;
    if (std::exchange(m_runCheck, 0) != 0) refreshTitle();
    showSketch(nullptr);
    if (m_diagnostics.empty()) return;
    m_diagnostics.clear();
    m_editor->setDiagnostics(m_diagnostics);
    emit diagnosticsChanged(m_diagnostics);
}

bool ProgramPanel::open(const std::filesystem::path& path) {
    if (m_saveAfterRenumber || m_writer->busy()) {
        // "Save" before another program, for a long one: that one follows the save.
        m_openAfterSave = path;
        return true;
    }
    if (loading() || m_editor->renumbering()) return false;
    m_saveAfterRenumber = false;
    std::error_code sizeError;
    const uintmax_t size = std::filesystem::file_size(path, sizeError);
    m_editor->setDialect(program::dialectForFile(path.string(), isLathe(m_settings.machine)));
    if (!sizeError && size >= m_settings.backgroundLoadBytes) {
        m_editor->setReadOnly(true);
        // The diagnostics are about the text being replaced.
        forgetDiagnostics();
        m_title->setText(tr("Loading %1 ...").arg(fileText(path.filename())));
        m_loader->load(path, m_editor->font());
        return true;
    }
    auto file = readProgramFile(path);
    if (!file) {
        emit message(Severity::Error,
                     translatedMessage(file.error()) + QStringLiteral(" (") + fileText(path) + ')');
        return false;
    }
    forgetDiagnostics();
    m_file = std::move(*file);
    m_loading = true;
    m_editor->setPlainText(m_file.text);
    m_editor->document()->setModified(false);
    m_loading = false;
    // The document holds the text; no second copy of a large program.
    finishOpen(path, std::exchange(m_file.text, {}));
    return true;
}

void ProgramPanel::finishOpen(const std::filesystem::path& path, const QString& text) {
    m_path = path;
    m_recovered = m_recovery.recover(path);
    refreshTitle();
    emit fileChanged();
    m_checkTimer->stop();
    m_awaitedCheck = m_checker->check(text, m_path, m_editor->dialect());
}

bool ProgramPanel::save() {
    if (m_path.empty()) return false;
    if (m_writer->busy()) return true;  // the text shown is being written (read-only meanwhile)
    if (m_editor->numbersStale() || m_editor->renumbering()) {
        // A long program is renumbered in slices first; renumbered() then writes the file.
        m_saveAfterRenumber = true;
        m_editor->renumber();
        return true;
    }
    return write();
}

bool ProgramPanel::write() {
    ProgramText file = m_file;
    file.text = m_editor->toPlainText();
    if (file.text.size() < static_cast<qsizetype>(m_settings.backgroundLoadBytes)) {
        return finishWrite(writeProgramFile(program::NcRoot(m_settings.ncRoot), m_path, file));
    }
    // A large program is encoded and written by a worker; the editor is read-only meanwhile, so
    // that the file written is the text shown and "not modified" stays true.
    m_readOnlyBeforeWrite = m_editor->isReadOnly();
    m_editor->setReadOnly(true);
    m_writer->run([root = program::NcRoot(m_settings.ncRoot), path = m_path,
                   file = std::move(file)] { return writeProgramFile(root, path, file); },
                  [this](const MaybeError& error) {
                      m_editor->setReadOnly(m_readOnlyBeforeWrite);
                      finishWrite(error);
                  });
    return true;
}

bool ProgramPanel::finishWrite(const MaybeError& error) {
    const std::optional<std::filesystem::path> next = std::exchange(m_openAfterSave, std::nullopt);
    if (error) {
        emit message(Severity::Error,
                     translatedMessage(*error) + QStringLiteral(" (") + fileText(m_path) + ')');
        if (next) {
            emit message(Severity::Warning,
                         tr("%1 was not opened: %2 could not be saved")
                             .arg(fileText(next->filename()), fileText(m_path.filename())));
        }
        return false;
    }
    m_editor->document()->setModified(false);
    m_autosaveTimer->stop();
    m_recovery.discard(m_path);
    m_recovered.reset();
    emit message(Severity::Note, tr("Saved %1").arg(fileText(m_path.filename())));
    if (next) open(*next);
    return true;
}

bool ProgramPanel::modified() const {
    return m_editor->document()->isModified();
}

void ProgramPanel::restoreRecovery() {
    if (!m_recovered) return;
    // As one edit, so that undo returns to the saved file.
    QTextCursor cursor(m_editor->document());
    cursor.select(QTextCursor::Document);
    cursor.insertText(*m_recovered);
    m_recovered.reset();
}

void ProgramPanel::discardRecovery() {
    m_recovery.discard(m_path);
    m_recovered.reset();
}

void ProgramPanel::abandonEdits() {
    m_autosaveTimer->stop();
    discardRecovery();
    m_editor->document()->setModified(false);
}

void ProgramPanel::autosave() {
    if (m_path.empty() || !modified()) return;
    if (const MaybeError error = m_recovery.store(m_path, m_editor->toPlainText())) {
        emit message(Severity::Warning, tr("Autosave failed: %1").arg(translatedMessage(*error)));
    }
}

void ProgramPanel::checkNow() {
    m_checkTimer->stop();
    if (std::exchange(m_runCheck, 0) != 0) refreshTitle();
    if (!m_path.empty())
        m_awaitedCheck = m_checker->check(m_editor->toPlainText(), m_path, m_editor->dialect());
}

void ProgramPanel::setWorkAreaCheck(task::MoveCheckFactory checkMoves,
                                    std::function<Pose()> origin) {
    m_checker->setWorkAreaCheck(std::move(checkMoves), std::move(origin));
}

void ProgramPanel::checkProgram() {
    m_checkTimer->stop();
    if (m_path.empty() || loading()) return;
    m_awaitedCheck = m_checker->check(m_editor->toPlainText(), m_path, m_editor->dialect(),
                                      ProgramChecker::Depth::Run);
    m_runCheck = m_awaitedCheck;
    refreshTitle();
}

void ProgramPanel::reportProgramCheck() {
    refreshTitle();
    int errors = 0;
    for (const Diagnostic& d : m_diagnostics)
        errors += d.severity == Severity::Error ? 1 : 0;
    // A note: the errors themselves are in the list, and the message line shows the first.
    emit message(Severity::Note,
                 errors == 0
                     ? tr("Program check: no errors, the program runs to its end")
                     : tr("Program check: the program cannot run (errors: %1)").arg(errors));
}

void ProgramPanel::onEdited() {
    if (m_loading) return;
    m_sketchStale = true;
    if (std::exchange(m_runCheck, 0) != 0)  // its result is about the text before this edit
        refreshTitle();
    m_autosaveTimer->start();
    m_checkTimer->start();
}

void ProgramPanel::showSketch(std::shared_ptr<const task::ProgramSketch> sketch) {
    // While the check of a new text is under way, the graphics keep the last contour.
    m_sketch = std::move(sketch);
    m_sketchStale = false;
    m_sketchView->setSketch(m_sketch);
    m_sketchView->setVisible(m_sketch && !m_sketch->fk.elements.empty());
    refreshFkOffer(true);
}

void ProgramPanel::refreshFkOffer(bool newSketch) {
    const bool offered = m_offer >= 0;
    const int before = m_offer;
    m_offer = -1;
    if (m_sketch) {
        const auto& choices = m_sketch->fk.ambiguities;
        const auto cursor = static_cast<uint32_t>(m_editor->currentLine());
        for (size_t i = 0; i < choices.size() && m_offer < 0; ++i) {
            const auto& c = choices[i];
            if (c.at.line == cursor || c.after.line == cursor ||
                (c.selectAt && c.selectAt->line == cursor))
                m_offer = static_cast<int>(i);
        }
        for (size_t i = 0; i < choices.size() && m_offer < 0; ++i)
            if (choices[i].selected == 0) m_offer = static_cast<int>(i);
    }
    if (m_offer >= 0 && (newSketch || m_offer != before)) {
        // A new offer shows the solution written (or the first); the same one after an edit
        // keeps the solution the operator was looking at.
        const auto& choice = m_sketch->fk.ambiguities[static_cast<size_t>(m_offer)];
        const int count = static_cast<int>(choice.alternatives.size());
        if (choice.selected > 0)
            m_shownSolution = choice.selected;
        else if (m_offer != before || m_shownSolution > count)
            m_shownSolution = 1;
    }
    m_sketchView->setOffer(m_offer, m_shownSolution);
    if (offered != (m_offer >= 0)) emit fkOfferChanged();
}

std::optional<ProgramPanel::FkOffer> ProgramPanel::fkOffer() const {
    if (m_offer < 0 || !m_sketch) return std::nullopt;
    const auto& choice = m_sketch->fk.ambiguities[static_cast<size_t>(m_offer)];
    FkOffer offer;
    offer.solutions = static_cast<int>(choice.alternatives.size());
    offer.shown = m_shownSolution;
    offer.chosen = choice.selected;
    offer.afterLine = choice.after.line;
    offer.selectLine = choice.selectAt ? choice.selectAt->line : 0;
    return offer;
}

void ProgramPanel::showNextFkSolution() {
    const std::optional<FkOffer> offer = fkOffer();
    if (!offer) return;
    m_shownSolution = offer->shown % offer->solutions + 1;
    m_sketchView->setOffer(m_offer, m_shownSolution);
}

void ProgramPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange && !loading()) refreshTitle();
    QWidget::changeEvent(event);
}

void ProgramPanel::refreshTitle() {
    const QString name = m_path.empty() ? tr("No program") : fileText(m_path.filename());
    QString title = modified() ? name + QStringLiteral(" *") : name;
    if (checkingProgram())
        title +=
            QStringLiteral("   ") + tr("Checking the program: it runs without moving the machine");
    m_title->setText(title);
}

}  // namespace kerf::ui
