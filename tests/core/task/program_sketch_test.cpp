#include "core/task/program_sketch.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "test_paths.h"

// The editor's dry run for FK programs: the geometry the solver offers and its errors at their
// blocks, checked against circles and lines worked out by hand.
namespace kerf::task {
namespace {

constexpr double kPi = std::numbers::pi;

ProgramSketch sketchOf(const std::string& text) {
    ProgramRequest request;
    request.path = "FK.H";
    request.text = text;
    return sketchProgram(*machine::loadMachine("mill"), request);
}

// From (0,0) an arc DR+ R10 to (10,10): the chord's perpendicular bisector x + y = 10 meets the
// circle of radius 10 about either end at (0,10) and (10,0). About (0,10) the start lies at -90°
// and the end at 0°: a quarter turn counter-clockwise; about (10,0) from 180° to 90°
// counter-clockwise is three quarters.
const char* kAmbiguous =
    "0 BEGIN PGM FK MM\n"
    "1 L X+0 Y+0 R0 FMAX\n"
    "2 L Z-2 F200\n"
    "3 FC DR+ R10 X+10 Y+10\n"
    "%s"
    "4 FL X+30 Y+10\n"
    "5 END PGM FK MM\n";

std::string withSelect(const std::string& select) {
    std::string text = kAmbiguous;
    text.replace(text.find("%s"), 2, select);
    return text;
}

bool near(const Vec2& a, const Vec2& b) {
    return (a - b).norm() < 1e-9;
}

const Diagnostic* fkError(const ProgramSketch& sketch) {
    for (const Diagnostic& d : sketch.diagnostics)
        if (d.code == "fk" && d.severity == Severity::Error) return &d;
    return nullptr;
}

TEST(ProgramSketch, AnArcByRadiusAndEndOffersBothCentresAndWantsFselectAtItsBlock) {
    const ProgramSketch sketch = sketchOf(withSelect(""));
    ASSERT_EQ(sketch.fk.ambiguities.size(), 1u);
    const auto& choice = sketch.fk.ambiguities[0];
    EXPECT_EQ(choice.at.line, 4u);
    EXPECT_EQ(choice.after.line, 4u);  // its own data made it ambiguous: FSELECT follows it
    EXPECT_EQ(choice.selected, 0);
    ASSERT_EQ(choice.alternatives.size(), 2u);
    int quarter = 0, threeQuarters = 0;
    for (const PlanarSegment& s : choice.alternatives) {
        ASSERT_EQ(s.kind, PlanarSegment::Kind::Arc);
        EXPECT_TRUE(near(s.start, {0.0, 0.0}));
        EXPECT_TRUE(near(s.end, {10.0, 10.0}));
        if (near(s.center, {0.0, 10.0}) && std::fabs(s.sweep - kPi / 2) < 1e-9) ++quarter;
        if (near(s.center, {10.0, 0.0}) && std::fabs(s.sweep - 3 * kPi / 2) < 1e-9) ++threeQuarters;
    }
    EXPECT_EQ(quarter, 1);
    EXPECT_EQ(threeQuarters, 1);
    // Without FSELECT the next FK block cannot go on: an error at the ambiguous block.
    const Diagnostic* error = fkError(sketch);
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->line, 4u);
    EXPECT_EQ(error->file, "FK.H");
    EXPECT_EQ(std::count_if(sketch.diagnostics.begin(), sketch.diagnostics.end(),
                            [](const Diagnostic& d) { return d.code == "fk"; }),
              1);
    // The graphics go on with solution 1, drawn as an assumption, and so does the element after
    // it: the line from (10,10) to (30,10).
    ASSERT_EQ(sketch.fk.elements.size(), 2u);
    const auto& assumed = sketch.fk.elements[0];
    EXPECT_EQ(assumed.at.line, 4u);
    ASSERT_TRUE(assumed.segment.has_value());
    EXPECT_TRUE(assumed.tentative);
    EXPECT_TRUE(near(assumed.segment->center, choice.alternatives[0].center));
    EXPECT_NEAR(assumed.segment->sweep, choice.alternatives[0].sweep, 1e-9);
    ASSERT_TRUE(assumed.sequenceStart.has_value());
    EXPECT_TRUE(near(*assumed.sequenceStart, {0.0, 0.0}));
    ASSERT_TRUE(assumed.givenEnd.has_value());
    EXPECT_TRUE(near(*assumed.givenEnd, {10.0, 10.0}));
    const auto& after = sketch.fk.elements[1];
    EXPECT_EQ(after.at.line, 5u);
    ASSERT_TRUE(after.segment.has_value());
    EXPECT_TRUE(after.tentative);
    EXPECT_TRUE(near(after.segment->start, {10.0, 10.0}));
    EXPECT_TRUE(near(after.segment->end, {30.0, 10.0}));
}

TEST(ProgramSketch, TheSolutionFselectChoosesIsTheElementAndTheContourGoesOn) {
    const ProgramSketch offered = sketchOf(withSelect(""));
    ASSERT_EQ(offered.fk.ambiguities.size(), 1u);
    for (int n = 1; n <= 2; ++n) {
        const ProgramSketch sketch = sketchOf(withSelect("4 FSELECT " + std::to_string(n) + "\n"));
        EXPECT_EQ(fkError(sketch), nullptr) << n;
        ASSERT_EQ(sketch.fk.ambiguities.size(), 1u);
        EXPECT_EQ(sketch.fk.ambiguities[0].selected, n);
        ASSERT_TRUE(sketch.fk.ambiguities[0].selectAt.has_value());
        EXPECT_EQ(sketch.fk.ambiguities[0].selectAt->line, 5u);
        ASSERT_EQ(sketch.fk.elements.size(), 2u);
        ASSERT_TRUE(sketch.fk.elements[0].segment.has_value());
        const PlanarSegment& chosen = offered.fk.ambiguities[0].alternatives[size_t(n - 1)];
        EXPECT_TRUE(near(sketch.fk.elements[0].segment->center, chosen.center)) << n;
        EXPECT_DOUBLE_EQ(sketch.fk.elements[0].segment->sweep, chosen.sweep);
        EXPECT_FALSE(sketch.fk.elements[0].tentative);  // chosen, not assumed
        // FL X+30 Y+10 from the arc's end (10,10).
        ASSERT_TRUE(sketch.fk.elements[1].segment.has_value());
        EXPECT_EQ(sketch.fk.elements[1].at.line, 6u);
        EXPECT_TRUE(near(sketch.fk.elements[1].segment->start, {10.0, 10.0}));
        EXPECT_TRUE(near(sketch.fk.elements[1].segment->end, {30.0, 10.0}));
    }
}

TEST(ProgramSketch, AContradictionIsAnErrorAtTheBlockThatAddsIt) {
    // From (0,0) to (10,0) runs along 0°: AN+45 contradicts it.
    const ProgramSketch sketch = sketchOf(
        "0 BEGIN PGM FK MM\n1 L X+0 Y+0 R0 FMAX\n2 L Z-2 F200\n3 FL X+10 Y+0\n"
        "4 FL X+20 Y+0 AN+45\n5 END PGM FK MM\n");
    const Diagnostic* error = fkError(sketch);
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->line, 5u);
    EXPECT_GE(error->column, 1u);
}

TEST(ProgramSketch, AnElementStillOpenAtTheEndIsAnErrorAndDrawnAsOpen) {
    // An arc known by its radius alone: nothing after it fixes its end.
    const ProgramSketch sketch = sketchOf(
        "0 BEGIN PGM FK MM\n1 L X+0 Y+0 R0 FMAX\n2 L Z-2 F200\n3 FC DR+ R10\n"
        "4 L Z+50 FMAX\n5 END PGM FK MM\n");
    const Diagnostic* error = fkError(sketch);
    ASSERT_NE(error, nullptr);
    EXPECT_EQ(error->line, 4u);
    ASSERT_EQ(sketch.fk.elements.size(), 1u);
    EXPECT_FALSE(sketch.fk.elements[0].segment.has_value());
    EXPECT_FALSE(sketch.fk.elements[0].givenEnd.has_value());
}

// Tool axis Y: FK works in the ZX plane (first axis Z, second X) and the moves around it are
// drawn in the same coordinates. Block 3 goes from Z0 X0 to Z10; the FCT R10 DR+ turns to
// Z20 X10 about Z10 X10 (tangent to the line, ending tangent to the FL AN+90 up X); block 6
// goes from Z20 X30 back to Z0. Projected on XY both lines would have no length at all.
TEST(ProgramSketch, FkInTheZxPlaneIsDrawnWithItsContourInZAndX) {
    const ProgramSketch sketch = sketchOf(
        "0 BEGIN PGM FK MM\n1 TOOL CALL 0 Y\n2 L X+0 Y+0 Z+0 R0 FMAX\n"
        "3 L Z+10 F100\n4 FCT DR+ R10\n5 FL Z+20 X+30 AN+90\n6 L Z+0\n"
        "7 END PGM FK MM\n");
    ASSERT_EQ(fkError(sketch), nullptr);
    EXPECT_EQ(sketch.fk.plane, Plane::ZX);
    ASSERT_FALSE(sketch.fk.elements.empty());
    ASSERT_TRUE(sketch.fk.elements[0].segment.has_value());
    EXPECT_TRUE(near(sketch.fk.elements[0].segment->start, {10.0, 0.0}));
    EXPECT_TRUE(near(sketch.fk.elements[0].segment->end, {20.0, 10.0}));
    auto moveOf = [&](int64_t block) -> const SketchMove* {
        for (const SketchMove& m : sketch.moves)
            if (m.at.blockNumber == block) return &m;
        return nullptr;
    };
    const SketchMove* three = moveOf(3);
    const SketchMove* six = moveOf(6);
    ASSERT_NE(three, nullptr);
    ASSERT_NE(six, nullptr);
    EXPECT_TRUE(near(three->segment.start, {0.0, 0.0}));
    EXPECT_TRUE(near(three->segment.end, {10.0, 0.0}));
    EXPECT_TRUE(near(six->segment.start, {20.0, 30.0}));
    EXPECT_TRUE(near(six->segment.end, {0.0, 30.0}));
}

TEST(ProgramSketch, OnlyProgramsThatMayUseFkAreRun) {
    EXPECT_TRUE(mayUseFk("0 BEGIN PGM A MM\n3 FLT AN+0\n"));
    EXPECT_TRUE(mayUseFk("  12 FPOL X+0 Y+0\n"));
    EXPECT_TRUE(mayUseFk("FSELECT 2\n"));
    EXPECT_FALSE(mayUseFk("1 FN 0: Q1 = +2\n2 L X+10 F100\n3 FUNCTION RESET TCPM\n"));
    const ProgramSketch plain =
        sketchOf("0 BEGIN PGM A MM\n1 L X+10 Y+0 R0 F200\n2 END PGM A MM\n");
    EXPECT_TRUE(plain.diagnostics.empty());
    EXPECT_TRUE(plain.moves.empty());  // not run
    // With FK the other moves come along, for the graphics.
    const ProgramSketch fk = sketchOf(
        "0 BEGIN PGM A MM\n1 L X+10 Y+0 R0 F200\n2 FL X+20 Y+0\n3 L X+20 Y+5\n"
        "4 END PGM A MM\n");
    EXPECT_EQ(fkError(fk), nullptr);
    ASSERT_EQ(fk.fk.elements.size(), 1u);
    ASSERT_TRUE(fk.fk.elements[0].sequenceStart.has_value());
    EXPECT_TRUE(near(*fk.fk.elements[0].sequenceStart, {10.0, 0.0}));
    ASSERT_EQ(fk.moves.size(), 3u);
    EXPECT_EQ(fk.moves[0].at.line, 2u);
    EXPECT_EQ(fk.moves[2].at.line, 4u);
    EXPECT_TRUE(near(fk.moves[2].segment.end, {20.0, 5.0}));
}

// The editor checks as the operator types: its dry run must not write the NC root. The same
// program run for real writes OUT.TXT (InterpreterTest.FPrintWritesInsideTheNcRoot).
TEST(ProgramSketch, TheDryRunWritesNoFile) {
    const auto dir = kerf::test::uniqueTempDir("sketch_no_writes");
    ASSERT_FALSE(writeFileAtomically(dir / "MASK.A", "\"R = %5.2F\", Q1;\n").has_value());
    ProgramRequest request;
    request.path = dir / "FK.H";
    request.ncRoot = dir;
    request.text =
        "0 BEGIN PGM FK MM\n1 Q1 = 2.5\n2 FN 16: F-PRINT MASK.A / OUT.TXT\n"
        "3 L X+0 Y+0 R0 F200\n4 FL X+10 Y+0\n5 END PGM FK MM\n";
    const ProgramSketch sketch = sketchProgram(*machine::loadMachine("mill"), request);
    EXPECT_EQ(fkError(sketch), nullptr);
    ASSERT_EQ(sketch.fk.elements.size(), 1u);  // it ran past FN 16
    EXPECT_TRUE(sketch.fk.elements[0].segment.has_value());
    EXPECT_FALSE(std::filesystem::exists(dir / "OUT.TXT"));
}

}  // namespace
}  // namespace kerf::task
