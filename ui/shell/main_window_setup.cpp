// The MainWindow's tables chooser, machine-parameter screen and MOD page (docs/hmi.md): their
// creation, wiring and softkey rows, kept apart from the window's frame.
#include <QStandardPaths>

#include "core/machine/builtin_machines.h"
#include "ui/settings/mod_page.h"
#include "ui/settings/settings_page.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/ui_language.h"
#include "ui/shell/workspace.h"
#include "ui/status/position_display.h"
#include "ui/tables/table_chooser.h"
#include "ui/tables/table_editor.h"

namespace kerf::ui {

namespace {

// The machine TOML the settings screen writes: the file Kerf was started with, or for a
// built-in machine a new file in the user's configuration folder.
std::filesystem::path settingsFile(const HmiContext& context, bool* builtIn) {
    std::string source = context.machineSource;
    if (source.empty())
        source = context.machine.kind == machine::MachineKind::Lathe ? "lathe" : "mill";
    *builtIn = !machine::builtinMachineToml(source).empty();
    if (!*builtIn) return source;
    const std::filesystem::path folder =
        QStandardPaths::writableLocation(QStandardPaths::AppConfigLocation).toStdString();
    return folder / (source + ".toml");
}

}  // namespace

void MainWindow::createSetupPages(QWidget* central) {
    const bool lathe = m_context.machine.kind == machine::MachineKind::Lathe;
    m_tableChooser = new TableChooser(m_context.ncRoot, lathe, central);
    bool builtIn = false;
    const std::filesystem::path file = settingsFile(m_context, &builtIn);
    m_settingsPage = new SettingsPage(m_context.machine, file, builtIn, central);
    m_modPage = new ModPage(m_context.machine, {}, central);
    for (QWidget* page : {static_cast<QWidget*>(m_tableChooser),
                          static_cast<QWidget*>(m_settingsPage), static_cast<QWidget*>(m_modPage)})
        page->hide();
    m_tables->setAxisLetters(m_context.machine.enabledAxisLetters());
    connect(m_tableChooser, &TableChooser::openRequested, this,
            [this](const std::filesystem::path& path) { showTable(path); });
    connect(
        m_settingsPage, &SettingsPage::message, m_messages,
        [this](Severity severity, const QString& text) { m_messages->addMessage(severity, text); });
    connect(m_modPage, &ModPage::languageRequested, this,
            [this](const QString& code) { setLanguage(code); });
    // The position display follows the MOD choices, from the last session's on.
    m_positions->setDisplaySettings(m_modPage->displaySettings());
    connect(m_modPage, &ModPage::displaySettingsChanged, m_positions,
            &PositionDisplay::setDisplaySettings);
}

void MainWindow::showSetupPage(Page page) {
    m_page = page;
    if (page == Page::TableChooser) m_workspace->showPage(m_tableChooser);
    if (page == Page::Settings) m_workspace->showPage(m_settingsPage);
    if (page == Page::Mod) {
        m_modPage->setLanguages(availableLanguages(), currentLanguage());
        m_workspace->showPage(m_modPage);
    }
    refreshSoftkeys();
}

std::vector<SoftkeyRow> MainWindow::setupRows() {
    const Softkey back{"back", tr("Back"), [this] { showPanels(); }};
    if (m_page == Page::TableChooser) {
        SoftkeyRow row;
        for (TableKind kind : m_tableChooser->kinds()) {
            row.push_back({QStringLiteral("table_%1").arg(static_cast<int>(kind)),
                           TableChooser::kindName(kind),
                           [this, kind] { m_tableChooser->choose(kind); }});
        }
        row.resize(SoftkeyBar::kKeys - 1);
        row.push_back(back);
        return {row};
    }
    if (m_page == Page::Settings) {
        return {{
            {"settingsSave", tr("Save"), [this] { m_settingsPage->save(); }},
            {"settingsUndo", tr("Undo"), [this] { m_settingsPage->undo(); }},
            {},
            {},
            {},
            {},
            {},
            back,
        }};
    }
    return {{
        {"modSettings", tr("Machine\nparameters"), [this] { showSetupPage(Page::Settings); }},
        {},
        {},
        {},
        {},
        {},
        {},
        back,
    }};
}

}  // namespace kerf::ui
