// FK blocks in running programs: mixed with conventional blocks, RND between FK elements,
// references to conventional blocks, inch programs and errors at the right line. Geometry by hand
// in the comments.
#include <filesystem>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class Moves : public canon::Sink {
public:
    void consume(const canon::Command& c) override {
        if (std::holds_alternative<canon::LinearMove>(c.body) ||
            std::holds_alternative<canon::ArcMove>(c.body)) {
            moves.push_back(c);
        }
    }
    std::vector<canon::Command> moves;
};

class FkInterpreterTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_fk_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        machine = *machine::loadMachine("mill");
    }
    void TearDown() override { fs::remove_all(dir); }

    interp::RunStatus run(const std::string& text) {
        KlartextSettings settings;
        settings.machine = &machine;
        settings.ncRoot = dir;
        interpreter = std::make_unique<KlartextInterpreter>(sources, settings);
        const fs::path path = dir / "FK.H";
        writeFileAtomically(path, text);
        if (!interpreter->load(path)) return interp::RunStatus::Failed;
        for (;;) {
            const auto status = interpreter->run(out, 1000);
            if (status != interp::RunStatus::BudgetUsed) return status;
        }
    }
    // The working-plane end point of move `i`.
    Vec2 end(size_t i) const {
        const canon::Command& c = out.moves.at(i);
        if (const auto* l = std::get_if<canon::LinearMove>(&c.body)) {
            return {l->target[Axis::X], l->target[Axis::Y]};
        }
        const auto& a = std::get<canon::ArcMove>(c.body);
        return {a.target[Axis::X], a.target[Axis::Y]};
    }
    const Pose& target(size_t i) const {
        const canon::Command& c = out.moves.at(i);
        if (const auto* l = std::get_if<canon::LinearMove>(&c.body)) return l->target;
        return std::get<canon::ArcMove>(c.body).target;
    }
    const canon::ArcMove& arc(size_t i) const {
        return std::get<canon::ArcMove>(out.moves.at(i).body);
    }

    fs::path dir;
    machine::MachineConfig machine;
    program::SourceRegistry sources;
    std::unique_ptr<KlartextInterpreter> interpreter;
    Moves out;
};

void expectPoint(const Vec2& p, double x, double y) {
    EXPECT_NEAR(p.x(), x, 1e-6);
    EXPECT_NEAR(p.y(), y, 1e-6);
}

// The corner (20,0) between the FK lines y = 0 and x = 20 is rounded with r5: the rounding runs
// from (15,0) to (20,5) about (15,5), though the first line's end was known only after the RND.
TEST_F(FkInterpreterTest, RoundingBetweenFkElements) {
    ASSERT_EQ(run("0 BEGIN PGM FK MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 FL AN+0 F100\n3 RND R5\n"
                  "4 FL X+20 Y+20 AN+90\n5 END PGM FK MM\n"),
              interp::RunStatus::Finished);
    ASSERT_EQ(out.moves.size(), 3u);
    expectPoint(end(0), 15.0, 0.0);
    expectPoint(end(1), 20.0, 5.0);
    EXPECT_NEAR(arc(1).center.x(), 15.0, 1e-6);
    EXPECT_NEAR(arc(1).center.y(), 5.0, 1e-6);
    expectPoint(end(2), 20.0, 20.0);
    EXPECT_EQ(out.moves[0].location.line, 3u);  // the first FL's own block
    EXPECT_EQ(out.moves[2].location.line, 5u);
}

// FCT after a conventional line takes its direction: from (10,0) along +X, counter-clockwise r10:
// centre (10,10); it ends where the vertical line x = 20 touches it: (20,10).
TEST_F(FkInterpreterTest, TangentArcAfterAConventionalLine) {
    ASSERT_EQ(run("0 BEGIN PGM FK MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 L X+10 F100\n3 FCT DR+ R10\n"
                  "4 FL X+20 Y+30 AN+90\n5 L X+0\n6 END PGM FK MM\n"),
              interp::RunStatus::Finished);
    ASSERT_EQ(out.moves.size(), 4u);
    expectPoint(end(1), 20.0, 10.0);
    EXPECT_NEAR(arc(1).center.y(), 10.0, 1e-6);
    EXPECT_NEAR(arc(1).sweepRad, kPi / 2.0, 1e-9);
    expectPoint(end(2), 20.0, 30.0);
    expectPoint(end(3), 0.0, 30.0);  // the conventional block continues from the FK end
}

// RX 5 makes IX relative to block 5's end (10,0), not to the start (10,10): X = 30.
TEST_F(FkInterpreterTest, RelativeDataReferToAConventionalBlock) {
    ASSERT_EQ(run("0 BEGIN PGM FK MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n5 L X+10 Y+0 F100\n6 L Y+10\n"
                  "7 FL IX+20 RX 5 Y+10\n8 END PGM FK MM\n"),
              interp::RunStatus::Finished);
    ASSERT_EQ(out.moves.size(), 3u);
    expectPoint(end(2), 30.0, 10.0);
}

TEST_F(FkInterpreterTest, InchProgramsGiveMillimetres) {
    ASSERT_EQ(run("0 BEGIN PGM FK INCH\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 FPOL X+1 Y+0\n"
                  "3 FL PR+1 PA+90 F10\n4 END PGM FK INCH\n"),
              interp::RunStatus::Finished);
    ASSERT_EQ(out.moves.size(), 1u);
    expectPoint(end(0), 25.4, 25.4);  // 1 inch above the pole at X 1 inch
}

TEST_F(FkInterpreterTest, FselectErrorsAtTheFselectBlock) {
    EXPECT_EQ(run("0 BEGIN PGM FK MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 FC X+20 Y+0 DR+ R20 F100\n"
                  "3 FSELECT 5\n4 END PGM FK MM\n"),
              interp::RunStatus::Failed);
    const auto& diagnostics = interpreter->diagnostics();
    ASSERT_FALSE(diagnostics.empty());
    EXPECT_EQ(diagnostics.back().line, 4u);
    EXPECT_EQ(diagnostics.back().code, "fk");
    EXPECT_TRUE(out.moves.empty());
}

// FSELECT 2: the short way (60 degrees) about (10, 17.32).
TEST_F(FkInterpreterTest, FselectPicksTheSecondCentre) {
    ASSERT_EQ(run("0 BEGIN PGM FK MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 FC X+20 Y+0 DR+ R20 F100\n"
                  "3 FSELECT 2\n4 END PGM FK MM\n"),
              interp::RunStatus::Finished);
    ASSERT_EQ(out.moves.size(), 1u);
    EXPECT_NEAR(arc(0).center.y(), std::sqrt(300.0), 1e-6);
    EXPECT_NEAR(arc(0).sweepRad, kPi / 3.0, 1e-9);
}

// The manual: a CC before an FK arc is no longer valid after it.
TEST_F(FkInterpreterTest, AnFkArcInvalidatesTheCircleCentre) {
    EXPECT_EQ(run("0 BEGIN PGM FK MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 CC X+0 Y+10\n"
                  "3 FC X+20 Y+0 DR+ R20 F100\n4 FSELECT 2\n5 C X+0 Y+0 DR+\n6 END PGM FK MM\n"),
              interp::RunStatus::Failed);
    ASSERT_FALSE(interpreter->diagnostics().empty());
    EXPECT_EQ(interpreter->diagnostics().back().line, 6u);
    EXPECT_EQ(out.moves.size(), 1u);  // the FK arc ran
}

// FK data are values like any other: Q parameters and formulas.
TEST_F(FkInterpreterTest, QParametersInFkData) {
    ASSERT_EQ(run("0 BEGIN PGM FK MM\n1 Q1 = 12\n2 L X+0 Y+0 Z+0 R0 FMAX\n"
                  "3 FL X+Q1 Y+(Q1/4) F100\n4 END PGM FK MM\n"),
              interp::RunStatus::Finished);
    ASSERT_EQ(out.moves.size(), 1u);
    expectPoint(end(0), 12.0, 3.0);
}

// The XY example of TangentArcAfterAConventionalLine in the ZX plane (tool axis Y), whose first
// axis is Z and second X: from Z10 X0 along +Z, DR+ r10 turns about Z10 X10 to Z20 X10, where the
// line Z = 20 going +X touches it; the line ends at Z20 X30, the conventional block at Z0 X30.
TEST_F(FkInterpreterTest, InTheZxPlane) {
    ASSERT_EQ(run("0 BEGIN PGM FK MM\n1 TOOL CALL 0 Y\n2 L X+0 Y+0 Z+0 R0 FMAX\n"
                  "3 L Z+10 F100\n4 FCT DR+ R10\n5 FL Z+20 X+30 AN+90\n6 L Z+0\n"
                  "7 END PGM FK MM\n"),
              interp::RunStatus::Finished);
    ASSERT_EQ(out.moves.size(), 4u);
    const canon::ArcMove& a = arc(1);
    EXPECT_EQ(a.plane, Plane::ZX);
    EXPECT_NEAR(a.target[Axis::Z], 20.0, 1e-6);
    EXPECT_NEAR(a.target[Axis::X], 10.0, 1e-6);
    EXPECT_NEAR(a.target[Axis::Y], 0.0, 1e-9);
    EXPECT_NEAR(a.center.z(), 10.0, 1e-6);
    EXPECT_NEAR(a.center.x(), 10.0, 1e-6);
    EXPECT_NEAR(a.sweepRad, kPi / 2.0, 1e-9);
    EXPECT_NEAR(target(2)[Axis::Z], 20.0, 1e-6);
    EXPECT_NEAR(target(2)[Axis::X], 30.0, 1e-6);
    EXPECT_NEAR(target(3)[Axis::Z], 0.0, 1e-6);
    EXPECT_NEAR(target(3)[Axis::X], 30.0, 1e-6);
}

// The YZ plane (tool axis X), first axis Y, second Z: the pole Y10 Z0, PR10 PA+90 (from +Y
// towards +Z) is Y10 Z10; IY+5 relative to block 4 ends at Y15, at Z10.
TEST_F(FkInterpreterTest, InTheYzPlaneWithPolarAndRelativeData) {
    ASSERT_EQ(run("0 BEGIN PGM FK MM\n1 TOOL CALL 0 X\n2 L X+0 Y+0 Z+0 R0 FMAX\n"
                  "3 FPOL Y+10 Z+0\n4 FL PR+10 PA+90 F100\n5 FL IY+5 RY 4 Z+10\n"
                  "6 END PGM FK MM\n"),
              interp::RunStatus::Finished);
    ASSERT_EQ(out.moves.size(), 2u);
    EXPECT_NEAR(target(0)[Axis::Y], 10.0, 1e-6);
    EXPECT_NEAR(target(0)[Axis::Z], 10.0, 1e-6);
    EXPECT_NEAR(target(0)[Axis::X], 0.0, 1e-9);
    EXPECT_NEAR(target(1)[Axis::Y], 15.0, 1e-6);
    EXPECT_NEAR(target(1)[Axis::Z], 10.0, 1e-6);
}

// A coordinate of the tool axis is no FK datum: Y in the ZX plane, at the block.
TEST_F(FkInterpreterTest, ToolAxisDataAreAnError) {
    EXPECT_EQ(run("0 BEGIN PGM FK MM\n1 TOOL CALL 0 Y\n2 L X+0 Y+0 Z+0 R0 FMAX\n"
                  "3 FL X+10 Y+0 F100\n4 END PGM FK MM\n"),
              interp::RunStatus::Failed);
    ASSERT_FALSE(interpreter->diagnostics().empty());
    EXPECT_EQ(interpreter->diagnostics().back().line, 4u);
    EXPECT_EQ(interpreter->diagnostics().back().args.at(0), "Y");
    EXPECT_TRUE(out.moves.empty());
}

}  // namespace
}  // namespace kerf::klartext
