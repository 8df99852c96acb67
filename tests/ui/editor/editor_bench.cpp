// Opening and scrolling a million-block program in the editor: a manual benchmark, not a ctest
// test (it takes seconds). Prints one line per step with its wall time.
//   editor_bench [blocks]   (default 1000000)

#include <QApplication>
#include <QElapsedTimer>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextDocument>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "ui/editor/program_checker.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_file.h"
#include "ui/editor/program_panel.h"
#include "ui/editor/visible_highlighter.h"

namespace {

std::string makeProgram(int blocks) {
    std::string text = "0 BEGIN PGM BIG MM\n1 TOOL CALL 1 Z S3000\n2 L Z+50 R0 FMAX M3\n";
    for (int i = 3; i < blocks - 2; ++i) {
        text += std::to_string(i) + " L X+" + std::to_string(i % 100) + ".5 Y-" +
                std::to_string(i % 37) + ".25 F800 ; pass\n";
    }
    text += std::to_string(blocks - 2) + " L Z+50 R0 FMAX M30\n" + std::to_string(blocks - 1) +
            " END PGM BIG MM\n";
    return text;
}

void report(const char* step, const QElapsedTimer& timer) {
    std::printf("%-44s %8.1f ms\n", step, static_cast<double>(timer.nsecsElapsed()) / 1e6);
}

}  // namespace

int main(int argc, char** argv) {
    const int blocks = argc > 1 ? std::atoi(argv[1]) : 1000000;
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / "kerf_editor_bench.H";
    if (kerf::writeFileAtomically(file, makeProgram(blocks))) return 1;
    std::printf("%d blocks, %.1f MB\n", blocks,
                static_cast<double>(std::filesystem::file_size(file)) / 1e6);

    kerf::ui::ProgramEditor editor;
    editor.resize(1000, 700);
    QElapsedTimer timer;
    timer.start();
    auto program = kerf::ui::readProgramFile(file);
    report("read and decode the file", timer);
    {
        timer.restart();
        QTextDocument bare;
        bare.setUndoRedoEnabled(false);
        bare.setPlainText(program->text);
        report("QTextDocument::setPlainText, no editor", timer);
    }
    timer.restart();
    editor.setPlainText(program->text);
    report("ProgramEditor::setPlainText", timer);
    timer.restart();
    editor.show();
    QCoreApplication::processEvents();
    editor.grab();
    report("first paint (visible lines coloured)", timer);

    // Scrolling: 200 jumps to random lines and 200 page-downs, each painted.
    std::mt19937 random(42);
    std::uniform_int_distribution<int> line(1, blocks);
    timer.restart();
    for (int i = 0; i < 200; ++i) {
        editor.goToLine(line(random));
        editor.grab();
    }
    report("200 random jumps, each painted (total)", timer);
    timer.restart();
    QScrollBar* bar = editor.verticalScrollBar();
    for (int i = 0; i < 200; ++i) {
        bar->triggerAction(QAbstractSlider::SliderPageStepAdd);
        editor.grab();
    }
    report("200 page-downs, each painted (total)", timer);

    timer.restart();
    editor.goToLine(blocks / 2);
    editor.moveCursor(QTextCursor::EndOfBlock);
    editor.insertBlock();
    report("Enter in the middle (numbers renumbered on save)", timer);
    timer.restart();
    editor.renumberNow();
    report("renumber all blocks at once (renumberNow)", timer);

    auto machine = kerf::machine::loadMachine("mill");
    kerf::ui::ProgramChecker checker(*machine, file.parent_path());
    bool done = false;
    QObject::connect(&checker, &kerf::ui::ProgramChecker::checked,
                     [&done](quint64, const kerf::DiagnosticList&) { done = true; });
    timer.restart();
    checker.check(editor.toPlainText(), file, kerf::program::Dialect::Klartext);
    report("hand the text to the checker (UI thread)", timer);
    while (!done)
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    report("background check until diagnostics arrive", timer);

    // The panel reads a large program in the background and renumbers it in slices on save: the
    // longest time the UI thread spends in one event is what the operator feels.
    kerf::ui::ProgramPanel::Settings settings;
    settings.machine = *machine;
    settings.ncRoot = file.parent_path();
    settings.recoveryFolder = file.parent_path() / "kerf_editor_bench_recovery";
    kerf::ui::ProgramPanel panel(settings);
    panel.resize(1000, 700);
    panel.show();
    bool opened = false;
    bool saved = false;
    QObject::connect(&panel, &kerf::ui::ProgramPanel::fileChanged, [&opened] { opened = true; });
    QObject::connect(&panel, &kerf::ui::ProgramPanel::message,
                     [&saved](kerf::Severity, const QString&) { saved = true; });
    // Until `flag` is set and 300 ms more (the events that follow a step count for it).
    const auto longestStallUntil = [](const bool& flag) {
        QElapsedTimer stall;
        QElapsedTimer after;
        qint64 longest = 0;
        while (!flag || !after.isValid() || after.elapsed() < 300) {
            if (flag && !after.isValid()) after.start();
            stall.start();
            QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
            longest = std::max(longest, stall.elapsed());
        }
        return longest;
    };
    const auto reportStall = [](const char* step, qint64 ms) {
        std::printf("%-44s %8lld ms\n", step, static_cast<long long>(ms));
    };
    timer.restart();
    panel.open(file);
    report("ProgramPanel::open returns (UI thread)", timer);
    qint64 stall = longestStallUntil(opened);
    report("program shown in the panel", timer);
    reportStall("longest UI-thread stall while loading", stall);

    panel.editor()->goToLine(blocks / 2);
    panel.editor()->moveCursor(QTextCursor::EndOfBlock);
    panel.editor()->insertBlock();
    timer.restart();
    panel.save();
    report("ProgramPanel::save returns (UI thread)", timer);
    stall = longestStallUntil(saved);
    report("renumbered in slices and written", timer);
    reportStall("longest UI-thread stall while saving", stall);

    opened = false;
    timer.restart();
    panel.open(file);
    stall = longestStallUntil(opened);
    report("open again (the old document is replaced)", timer);
    reportStall("longest UI-thread stall while reopening", stall);
    std::filesystem::remove(file);
    return 0;
}
