#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

#include <gtest/gtest.h>

#include "core/base/diagnostic.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/common/diagnostic_text.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"
#include "ui/shell/ui_language.h"
#include "ui/status/position_display.h"
#include "ui/status/status_tabs.h"

// German and Spanish: the window's texts and core's diagnostics change with the language. The
// expected words are the TNC's own terms (HEIDENHAIN's German and Spanish manuals).
namespace kerf::ui {
namespace {

HmiContext contextIn(const std::filesystem::path& dir) {
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    return context;
}

QString labelText(const MainWindow& window, const char* name) {
    return window.findChild<QLabel*>(name)->text();
}

Diagnostic pitchIsZero() {
    return Diagnostic::make(Severity::Error, "test", "T.H", 1, 1,
                            KERF_TR_NOOP("cycle {1}: the thread pitch Q{2} is 0"), "262", "239");
}

TEST(Language, GermanAndSpanishTranslateTheWindow) {
    test::testApp();
    MainWindow window(contextIn(kerf::test::uniqueTempDir("hmi_language_de_es")));
    window.show();
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);

    ASSERT_TRUE(window.setLanguage("de"));
    QCoreApplication::processEvents();  // LanguageChange is posted to each window
    EXPECT_EQ(labelText(window, "machineMode"), QStringLiteral("Manueller Betrieb"));
    EXPECT_EQ(labelText(window, "programmingMode"), QStringLiteral("Programmieren"));
    EXPECT_EQ(window.softkeys()->keyButton(0)->text(), QStringLiteral("Speichern"));
    EXPECT_EQ(window.messages()->line()->text(), QStringLiteral("Keine Meldungen"));
    EXPECT_EQ(window.findChild<QLabel*>("programTitle")->text(), QStringLiteral("Kein Programm"));
    EXPECT_EQ(translatedMessage(pitchIsZero()),
              QStringLiteral("Zyklus 262: die Gewindesteigung Q239 ist 0"));
    EXPECT_EQ(severityText(Severity::Warning), QStringLiteral("Warnung"));

    ASSERT_TRUE(window.setLanguage("es"));
    QCoreApplication::processEvents();
    EXPECT_EQ(labelText(window, "machineMode"), QStringLiteral("Funcionamiento manual"));
    EXPECT_EQ(labelText(window, "programmingMode"), QStringLiteral("Programaci\u00f3n"));
    EXPECT_EQ(window.softkeys()->keyButton(0)->text(), QStringLiteral("Guardar"));
    EXPECT_EQ(window.messages()->line()->text(), QStringLiteral("Sin mensajes"));
    EXPECT_EQ(window.findChild<QLabel*>("programTitle")->text(),
              QStringLiteral("Ning\u00fan programa"));
    EXPECT_EQ(translatedMessage(pitchIsZero()),
              QStringLiteral("ciclo 262: el paso de rosca Q239 es 0"));

    ASSERT_TRUE(window.setLanguage("en"));
    QCoreApplication::processEvents();
    EXPECT_EQ(labelText(window, "machineMode"), QStringLiteral("Manual operation"));
    EXPECT_EQ(translatedMessage(pitchIsZero()),
              QStringLiteral("cycle 262: the thread pitch Q239 is 0"));
}

TEST(Language, QtsOwnDialogButtonsSpeakTheLanguage) {
    // The standard buttons of the prompts (unsaved program, table, quit) come from Qt's own
    // translations: Cancel in every language of the HMI, and back in English.
    test::testApp();
    const auto cancelText = [] {
        QDialogButtonBox box(QDialogButtonBox::Cancel);
        return box.button(QDialogButtonBox::Cancel)->text().remove(QLatin1Char('&'));
    };
    ASSERT_TRUE(switchLanguage(QStringLiteral("de")));
    EXPECT_EQ(cancelText(), QStringLiteral("Abbrechen"));
    ASSERT_TRUE(switchLanguage(QStringLiteral("es")));
    EXPECT_EQ(cancelText(), QStringLiteral("Cancelar"));
    ASSERT_TRUE(switchLanguage(QStringLiteral("pl")));
    EXPECT_EQ(cancelText(), QStringLiteral("Anuluj"));
    ASSERT_TRUE(switchLanguage(QStringLiteral("pt")));  // Debian ships Brazilian Portuguese
    EXPECT_EQ(cancelText(), QStringLiteral("Cancelar"));
    ASSERT_TRUE(switchLanguage(QStringLiteral("en")));
    EXPECT_EQ(cancelText(), QStringLiteral("Cancel"));
}

TEST(Language, CoreDiagnosticsAreTranslatedInPortugueseAndPolish) {
    test::testApp();
    ASSERT_TRUE(switchLanguage("pt"));
    EXPECT_EQ(translatedMessage(pitchIsZero()),
              QStringLiteral("ciclo 262: o passo de rosca Q239 \u00e9 0"));
    ASSERT_TRUE(switchLanguage("pl"));
    EXPECT_EQ(translatedMessage(pitchIsZero()),
              QStringLiteral("cykl 262: skok gwintu Q239 wynosi 0"));
    ASSERT_TRUE(switchLanguage("en"));
}

// "None" agrees with the noun of its row: Portuguese and Spanish "Ferramenta"/"Herramienta" and
// "Funções M"/"Funciones M" are feminine, "Ciclo" and "Programa" masculine; German "Werkzeug"
// is neuter, "Zyklus" masculine. The machine's state agrees with "Máquina" (feminine) while
// the program's agrees with "Programa" (masculine). Expected words from each grammar.
TEST(Language, NoneAndStatesAgreeWithTheirLabel) {
    test::testApp();
    StatusTabs tabs('Q');
    interp::ProgramStatus nothing;  // no program, cycle, M function, tool, mirroring
    nothing.tool.number = -1;
    tabs.setProgramStatus(nothing);
    PositionDisplay positions(*machine::loadMachine("mill"));
    task::MachineStatus stopped;
    stopped.state = task::MachineState::Stopped;
    positions.setStatus(stopped);
    auto value = [&](StatusTabs::Tab tab, const char* english) {
        return tabs.valueOf(tab, QCoreApplication::translate("kerf::ui::StatusTabs", english));
    };
    auto machineState = [&] {
        positions.setRunState(QCoreApplication::translate("kerf", "stopped"));
        return positions.findChild<QLabel*>("runState")->text();
    };
    using Tab = StatusTabs::Tab;
    ASSERT_TRUE(switchLanguage("pt"));
    QCoreApplication::processEvents();  // LanguageChange is posted to each widget
    EXPECT_EQ(value(Tab::Program, "Program"), QStringLiteral("nenhum"));
    EXPECT_EQ(value(Tab::Program, "Cycle"), QStringLiteral("nenhum"));
    EXPECT_EQ(value(Tab::Program, "M functions"), QStringLiteral("nenhuma"));
    EXPECT_EQ(value(Tab::Tool, "Tool"), QStringLiteral("nenhuma"));
    EXPECT_EQ(value(Tab::Transformations, "Mirrored axes"), QStringLiteral("nenhum"));
    EXPECT_EQ(machineState(), QStringLiteral("Programa: parado   M\u00e1quina: parada"));
    ASSERT_TRUE(switchLanguage("es"));
    QCoreApplication::processEvents();  // LanguageChange is posted to each widget
    EXPECT_EQ(value(Tab::Program, "Cycle"), QStringLiteral("ninguno"));
    EXPECT_EQ(value(Tab::Program, "M functions"), QStringLiteral("ninguna"));
    EXPECT_EQ(value(Tab::Tool, "Tool"), QStringLiteral("ninguna"));
    EXPECT_EQ(machineState(), QStringLiteral("Programa: parado   M\u00e1quina: parada"));
    ASSERT_TRUE(switchLanguage("de"));
    QCoreApplication::processEvents();  // LanguageChange is posted to each widget
    EXPECT_EQ(value(Tab::Program, "Cycle"), QStringLiteral("keiner"));
    EXPECT_EQ(value(Tab::Program, "M functions"), QStringLiteral("keine"));
    EXPECT_EQ(value(Tab::Tool, "Tool"), QStringLiteral("keines"));
    ASSERT_TRUE(switchLanguage("pl"));
    QCoreApplication::processEvents();  // LanguageChange is posted to each widget
    EXPECT_EQ(value(Tab::Tool, "Tool"), QStringLiteral("brak"));
    EXPECT_EQ(machineState(), QStringLiteral("Program: zatrzymany   Maszyna: zatrzymana"));
    ASSERT_TRUE(switchLanguage("en"));
    QCoreApplication::processEvents();  // LanguageChange is posted to each widget
    EXPECT_EQ(value(Tab::Tool, "Tool"), QStringLiteral("none"));
}

}  // namespace
}  // namespace kerf::ui
