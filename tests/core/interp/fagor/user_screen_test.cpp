// The user channel: screen customisation instructions (spec part 2 §6.8) drive a UserScreen, the
// operator's keys and inputs come back through it. Expected values come from the manual's
// examples (seed 002 EX-12.13 to EX-12.19) worked by hand.
#include "core/interp/fagor/user_screen.h"

#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/interp/fagor/fagor_interpreter.h"
#include "core/interp/fagor/operator_inputs.h"
#include "core/machine/machine_loader.h"

namespace kerf::fagor {
namespace {

namespace fs = std::filesystem;

TEST(UserScreenModel, NumberFormatsOfDw) {
    EXPECT_EQ(decimalText(100), "100");
    EXPECT_EQ(decimalText(-2.25), "-2.25");
    EXPECT_EQ(decimalText(1.0 / 3.0), "0.33333");
    EXPECT_EQ(hexadecimalText(100), "64");
    EXPECT_EQ(hexadecimalText(64206), "FACE");
    EXPECT_EQ(hexadecimalText(-1), "FFFFFFFF");
    EXPECT_EQ(binaryText(100), "01100100");
    EXPECT_EQ(binaryText(255), "11111111");
    EXPECT_EQ(binaryText(256), "11111111");   // above 255
    EXPECT_EQ(binaryText(-128), "10000000");  // below -127
    EXPECT_EQ(binaryText(-1), "11111111");    // eight-bit two's complement
}

TEST(UserScreenModel, SoftkeyTextOnTwoLinesOfTen) {
    // Shorter than 10: centred on the upper line; longer: the programmer centres it.
    EXPECT_EQ(softkeyLines("HELP"), (std::pair<std::string, std::string>{"   HELP   ", ""}));
    EXPECT_EQ(softkeyLines("  MAXIMUN   POINT"),
              (std::pair<std::string, std::string>{"  MAXIMUN ", "  POINT"}));
}

TEST(UserScreenModel, SkOverTheStandardMenuReplacesAllOverAUserMenuOnlyThoseNamed) {
    UserScreen screen;
    screen.setSoftkeys({{1, "HELP"}, {2, "MAXIMUN POINT"}});
    EXPECT_EQ(screen.softkeys()[0], "HELP");
    EXPECT_EQ(screen.softkeys()[1], "MAXIMUN POINT");
    screen.setSoftkeys({{1, "FEED"}});
    EXPECT_EQ(screen.softkeys()[0], "FEED");
    EXPECT_EQ(screen.softkeys()[1], "MAXIMUN POINT");  // kept
    screen.leave();                                    // SYSTEM: the standard menu again
    EXPECT_FALSE(screen.userMenu());
    screen.setSoftkeys({{3, "X"}});
    EXPECT_EQ(screen.softkeys()[0], "");
    EXPECT_EQ(screen.softkeys()[2], "X");
}

TEST(UserScreenModel, InputMustFitItsFormat) {
    UserScreen screen;
    EXPECT_EQ(screen.enterNumber("1"), "no input is asked for");
    screen.askNumber(1, "Feed: ", InputFormat{false, 5, 4});
    EXPECT_EQ(screen.enterNumber("-5"), "only positive values are accepted here");
    EXPECT_EQ(screen.enterNumber("123456"), "the number does not fit the input format");
    EXPECT_EQ(screen.enterNumber("1.23456"), "the number does not fit the input format");
    EXPECT_EQ(screen.enterNumber("1a"), "a number is expected");
    EXPECT_EQ(screen.enterNumber(""), "a number is expected");
    EXPECT_EQ(screen.enterNumber(" 12345.6789 "), std::nullopt);
    EXPECT_EQ(screen.takeNumber(), 12345.6789);
    EXPECT_EQ(screen.input(1), 12345.6789);
    EXPECT_EQ(screen.waiting(), UserScreen::Waiting::Nothing);
    screen.askNumber(2, "A: ", InputFormat{true, 6, 5});
    EXPECT_EQ(screen.enterNumber("-2.25"), std::nullopt);
    EXPECT_EQ(screen.takeNumber(), -2.25);
}

TEST(UserScreenModel, KeysCountOnlyWhileWkeyWaits) {
    UserScreen screen;
    EXPECT_FALSE(screen.pressKey(0xFC00));
    screen.askKey();
    EXPECT_TRUE(screen.pressKey(0xFC00));
    EXPECT_EQ(screen.takeKey(), 0xFC00);
    screen.setKeySource(1);  // KEYSRC = 1: keys come from the PLC
    screen.askKey();
    EXPECT_FALSE(screen.pressKey(0xFC01));
    EXPECT_EQ(keyCode("F1"), 0xFC00);
    EXPECT_EQ(keyCode("F7"), 0xFC06);
    EXPECT_EQ(keyCode("$FC01"), 0xFC01);
    EXPECT_EQ(keyCode("A"), 65);
    EXPECT_EQ(keyCode("F8"), std::nullopt);
    EXPECT_EQ(keyName(0xFC06), "F7");
    EXPECT_EQ(keyName(65), "A");
}

TEST(UserScreenModel, APageReplacesTheScreen) {
    UserScreen screen;
    screen.defineWindow(1, 10, 60);
    screen.drawSymbol({3, 100, 200});
    EXPECT_TRUE(screen.showInWindow(1, "2"));
    screen.showPage(11);
    EXPECT_FALSE(screen.windows()[1].has_value());
    EXPECT_TRUE(screen.symbols().empty());
    EXPECT_FALSE(screen.showInWindow(1, "2"));
}

class UserChannel : public testing::Test {
protected:
    void SetUp() override {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        root = fs::temp_directory_path() /
               ("kerf_user_screen_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(root);
        fs::create_directories(root);
        auto loaded = machine::loadMachine("lathe");
        ASSERT_TRUE(static_cast<bool>(loaded));
        lathe = std::move(*loaded);
        settings.machine = &lathe;
        settings.ncRoot = root;
    }
    void TearDown() override { fs::remove_all(root); }

    // Loads a program as the customisation program of `mode` (or an ordinary one without).
    bool load(const fs::path& program, std::optional<UserMode> mode) {
        if (mode) {
            screen = std::make_unique<UserScreen>(*mode);
            settings.userScreen = screen.get();
        }
        interpreter = std::make_unique<FagorInterpreter>(sources, settings);
        return interpreter->load(program);
    }
    bool loadText(const std::string& text, std::optional<UserMode> mode) {
        std::ofstream(root / "P000001.PIM", std::ios::binary) << text;
        return load(root / "P000001.PIM", mode);
    }
    // Runs until the program waits for the operator, ends, fails or used `budget` blocks.
    interp::RunStatus runUntilOperator(uint64_t budget = 1000) {
        interp::RunStatus status = interpreter->run(sink, budget);
        return status;
    }
    // Gives the operator's answer and runs on.
    interp::RunStatus answerKey(const char* key) {
        EXPECT_EQ(screen->waiting(), UserScreen::Waiting::Key);
        EXPECT_TRUE(screen->pressKey(*keyCode(key)));
        interpreter->resume(interp::WorldSnapshot{});
        return runUntilOperator();
    }
    interp::RunStatus answerNumber(const char* number) {
        EXPECT_EQ(screen->waiting(), UserScreen::Waiting::Number);
        EXPECT_EQ(screen->enterNumber(number), std::nullopt);
        interpreter->resume(interp::WorldSnapshot{});
        return runUntilOperator();
    }
    std::string diagnostics() const {
        std::string out;
        for (const Diagnostic& d : interpreter->diagnostics())
            out += d.format() + "\n";
        return out;
    }
    static fs::path example(const char* name) {
        return fs::path(KERF_SOURCE_DIR) / "examples/fagor_user_screen" / name;
    }

    class NullSink final : public canon::Sink {
    public:
        void consume(const canon::Command&) override {}
    } sink;
    fs::path root;
    machine::MachineConfig lathe;
    FagorSettings settings;
    program::SourceRegistry sources;
    std::unique_ptr<UserScreen> screen;
    std::unique_ptr<FagorInterpreter> interpreter;
};

int today() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    return (local.tm_year % 100) * 10000 + (local.tm_mon + 1) * 100 + local.tm_mday;
}

TEST_F(UserChannel, Ex12_13ShowsTheDateAndTheTimeInTwoWindows) {
    ASSERT_TRUE(load(example("P000013.PIM"), UserMode::Execution)) << diagnostics();
    const int before = today();
    // The loop refreshes the windows for as long as the screen is open.
    EXPECT_EQ(runUntilOperator(500), interp::RunStatus::BudgetUsed) << diagnostics();
    const int after = today();
    const auto& windows = screen->windows();
    ASSERT_TRUE(windows[1] && windows[2]);
    EXPECT_EQ(windows[1]->row, 6);
    EXPECT_EQ(windows[1]->column, 33);
    EXPECT_EQ(windows[2]->row, 14);
    const int date = std::stoi(windows[1]->text);
    EXPECT_TRUE(date == before || date == after) << windows[1]->text;
    const int time = std::stoi(windows[2]->text);  // hhmmss
    EXPECT_LT(time / 10000, 24);
    EXPECT_LT(time / 100 % 100, 60);
    EXPECT_LT(time % 100, 60);
}

TEST_F(UserChannel, Ex12_15WaitsForAFeedThatFitsFiveDotFour) {
    ASSERT_TRUE(load(example("P000015.PIM"), UserMode::Execution)) << diagnostics();
    EXPECT_EQ(runUntilOperator(), interp::RunStatus::NeedsSync);
    EXPECT_EQ(screen->waiting(), UserScreen::Waiting::Number);
    EXPECT_EQ(screen->prompt(), "Avanço dos eixos: ");
    EXPECT_EQ(screen->pendingInput(), 1);
    EXPECT_EQ(screen->windows()[3]->text, "");
    // A resume without an answer asks again.
    interpreter->resume(interp::WorldSnapshot{});
    EXPECT_EQ(runUntilOperator(), interp::RunStatus::NeedsSync);
    EXPECT_EQ(screen->enterNumber("-1500"), "only positive values are accepted here");
    EXPECT_EQ(answerNumber("1500.25"), interp::RunStatus::Finished) << diagnostics();
    EXPECT_EQ(screen->windows()[3]->text, "1500.25");
    EXPECT_EQ(screen->input(1), 1500.25);
}

TEST_F(UserChannel, Ex12_19WritesTheCyclesCallsIntoTheEditedProgram) {
    ASSERT_TRUE(load(example("P000019.PIM"), UserMode::Edit)) << diagnostics();
    EXPECT_EQ(runUntilOperator(), interp::RunStatus::NeedsSync);
    EXPECT_EQ(screen->page(), 10);
    EXPECT_EQ(screen->softkeys()[0], "CICLO 1");
    EXPECT_EQ(screen->softkeys()[1], "CICLO 2");
    EXPECT_EQ(screen->softkeys()[6], "SALIR");
    EXPECT_EQ(screen->waiting(), UserScreen::Waiting::Key);
    // F3 is no option: WKEY asks again.
    EXPECT_EQ(answerKey("F3"), interp::RunStatus::NeedsSync);
    EXPECT_EQ(screen->waiting(), UserScreen::Waiting::Key);
    EXPECT_EQ(answerKey("F1"), interp::RunStatus::NeedsSync);
    EXPECT_EQ(screen->page(), 11);
    EXPECT_EQ(screen->prompt(), "X:");
    EXPECT_EQ(answerNumber("2"), interp::RunStatus::NeedsSync);
    EXPECT_EQ(screen->windows()[1]->text, "2");
    EXPECT_EQ(screen->editBuffer(), "( PCALL 1,X2,");
    EXPECT_EQ(answerNumber("-3.5"), interp::RunStatus::NeedsSync);
    EXPECT_EQ(screen->input(2), -3.5);
    EXPECT_EQ(screen->page(), 10);  // back at N0: page 10 replaced page 11 and its windows
    EXPECT_FALSE(screen->windows()[2].has_value());
    EXPECT_EQ(screen->insertedBlocks(), std::vector<std::string>{"( PCALL 1,X2,Y-3.5)"});
    EXPECT_EQ(screen->editBuffer(), "");
    EXPECT_EQ(answerKey("F2"), interp::RunStatus::NeedsSync);
    EXPECT_EQ(screen->page(), 12);
    EXPECT_TRUE(screen->windows()[3].has_value());
    EXPECT_EQ(answerNumber("3"), interp::RunStatus::NeedsSync);
    EXPECT_EQ(answerNumber("1"), interp::RunStatus::NeedsSync);
    EXPECT_EQ(answerNumber("3"), interp::RunStatus::NeedsSync);
    EXPECT_EQ(screen->insertedBlocks().back(), "( PCALL 2,A3,B1,C3)");
    EXPECT_EQ(answerKey("F7"), interp::RunStatus::Finished) << diagnostics();
    EXPECT_TRUE(screen->left());
    EXPECT_TRUE(screen->softkeys()[0].empty());  // the standard menu again
    EXPECT_EQ(screen->takeInsertedBlocks().size(), 2u);
    EXPECT_TRUE(screen->takeInsertedBlocks().empty());
}

TEST_F(UserChannel, KeyHoldsTheLastKeyRead) {
    ASSERT_TRUE(loadText("(WKEY)\n(P100=KEY)\n(KEY=65)\n(P101=KEY)\n", UserMode::Manual))
        << diagnostics();
    EXPECT_EQ(runUntilOperator(), interp::RunStatus::NeedsSync);
    EXPECT_EQ(answerKey("F2"), interp::RunStatus::Finished) << diagnostics();
    double value = 0.0;
    Problem problem;
    ASSERT_TRUE(interpreter->parameters().get(100, value, problem));
    EXPECT_EQ(value, 0xFC01);
    ASSERT_TRUE(interpreter->parameters().get(101, value, problem));
    EXPECT_EQ(value, 65.0);
}

TEST_F(UserChannel, WbufOnlyInTheEditModeProgram) {
    ASSERT_TRUE(loadText("(WBUF \"X\")\n", UserMode::Execution));
    EXPECT_EQ(runUntilOperator(), interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(),
              (root / "P000001.PIM").string() +
                  ":1:2: error: WBUF runs only in the customisation program of the edit mode "
                  "(USEREDIT)\n");
}

TEST_F(UserChannel, DwNeedsAWindowDefinedByOdw) {
    ASSERT_TRUE(loadText("(ODW 1, 2, 3)\n(DW1=5, DW2=6)\n", UserMode::Execution));
    EXPECT_EQ(runUntilOperator(), interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(), (root / "P000001.PIM").string() +
                                 ":2:2: error: data window 2 is not defined (ODW)\n");
    EXPECT_EQ(screen->windows()[1]->text, "5");
}

TEST_F(UserChannel, KeysFromThePlcCannotBeWaitedFor) {
    ASSERT_TRUE(loadText("(KEYSRC=1)\n(WKEY)\n", UserMode::Execution));
    EXPECT_EQ(runUntilOperator(), interp::RunStatus::Failed);
    EXPECT_EQ(screen->keySource(), 1);
}

TEST_F(UserChannel, ACustomisationProgramHasNoIsoBlocks) {
    EXPECT_FALSE(loadText("(PAGE 1)\nN10\nG1 X10 Z5 F100\n", UserMode::Execution));
    EXPECT_EQ(diagnostics(), (root / "P000001.PIM").string() +
                                 ":3:1: error: a customisation program runs in the user channel: "
                                 "it has no ISO blocks (no motion, no M, S, T)\n");
}

TEST_F(UserChannel, AnOrdinaryProgramReadsIbButCannotDrawTheScreen) {
    settings.inputValues[1] = 42.5;
    ASSERT_TRUE(loadText("(P1=IB1)\n(P100=P1*2)\n", std::nullopt)) << diagnostics();
    EXPECT_EQ(runUntilOperator(), interp::RunStatus::Finished) << diagnostics();
    double value = 0.0;
    Problem problem;
    ASSERT_TRUE(interpreter->parameters().get(100, value, problem));
    EXPECT_EQ(value, 85.0);

    EXPECT_FALSE(loadText("(ODW 1, 6, 33)\n", std::nullopt));
    EXPECT_EQ(diagnostics(), (root / "P000001.PIM").string() +
                                 ":1:2: error: ODW is a screen customisation instruction: it runs "
                                 "only in a user customisation program (the user screen)\n");
}

}  // namespace
}  // namespace kerf::fagor

namespace kerf::fagor {
namespace {

TEST(OperatorInputsRead, NamesEachIbAProgramReadsOnceInOrder) {
    // IB25 is the last input; IB26, IBX, PIB1 and the IB in a comment or a text are no reads.
    EXPECT_EQ(operatorInputsRead("(P1=IB12+ib3)\n(P2=IB3*IB25) ; IB4\n(MSG \"IB5\")\n"
                                 "(P3=IB26)\n(P4=PIB1+IBX)\nG0 XP1\n"),
              (std::vector<int>{3, 12, 25}));
    EXPECT_TRUE(operatorInputsRead("G0 X10\nM30\n").empty());
}

}  // namespace
}  // namespace kerf::fagor
