#include <QImage>
#include <QPixmap>
#include <QSignalSpy>
#include <QTreeWidget>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/editor/program_panel.h"
#include "ui/files/file_manager.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/workspace.h"

namespace kerf::ui {
namespace {

// Saves a picture of every main screen into the test's working folder (the build tree), so that
// a person can look at them after each change; the test checks each picture was written whole.
TEST(Screens, SaveEveryMainScreen) {
    test::testApp();
    const auto dir = kerf::test::uniqueTempDir("hmi_screens");
    ASSERT_FALSE(writeFileAtomically(dir / "PART.H",
                                     "0 BEGIN PGM PART MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
                                     "2 BLK FORM 0.2 X+100 Y+100 Z+0\n3 TOOL CALL 1 Z S3000\n"
                                     "4 L Z+50 R0 FMAX M3\n5 L X-10 Y-10 R0 FMAX\n6 L Z-5 R0 F500\n"
                                     "7 L X+110 RL F800 ; contour\n8 BOGUS WORD\n9 L Y+110\n"
                                     "10 L Z+50 R0 FMAX M30\n11 END PGM PART MM\n")
                     .has_value());
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    MainWindow window(std::move(context));
    window.resize(1280, 800);
    window.show();
    QSignalSpy checked(window.program(), &ProgramPanel::diagnosticsChanged);
    ASSERT_TRUE(window.openProgram(dir / "PART.H"));
    ASSERT_TRUE(checked.wait(10000));

    auto shoot = [&window](const char* name) {
        for (int i = 0; i < 5; ++i)
            QCoreApplication::processEvents();
        const QString file = QStringLiteral("hmi_%1.png").arg(name);
        ASSERT_TRUE(window.grab().save(file)) << name;
        const QImage image(file);
        EXPECT_EQ(image.size(), QSize(1280, 800)) << name;
    };
    shoot("manual");
    window.modes().requestProgrammingMode(task::ProgrammingMode::Programming);
    window.messages()->setListVisible(true);
    window.messages()->activate(0);
    shoot("programming");
    window.messages()->setListVisible(false);
    window.workspace()->setLayoutKind(WorkspaceLayout::ProgramGraphics);
    window.modes().requestProgrammingMode(task::ProgrammingMode::TestRun);
    shoot("testrun");
    window.showFiles();
    window.files()->selectPath(dir / "PART.H");
    shoot("files");
    ASSERT_TRUE(window.showTable(dir / "TOOL.T"));
    shoot("tooltable");
    ASSERT_TRUE(window.showTable(dir / "PRESET.PR"));
    shoot("presettable");
    window.showPanels();
    window.workspace()->setLayoutKind(WorkspaceLayout::PositionsStatus);
    window.modes().requestMachineMode(task::MachineMode::FullSequence);
    shoot("fullsequence");
}

}  // namespace
}  // namespace kerf::ui
