// Rapids that take material of the blank: SimulatedWorkpiece::rapidTakesMaterial and the cut
// recorder's collisions. Expected answers from the geometry of a 100 x 60 x 40 block, top at 0.
#include <chrono>

#include <gtest/gtest.h>

#include "core/workpiece/cut_recorder.h"
#include "core/workpiece/simulated_workpiece.h"

namespace kerf::workpiece {
namespace {

const Cutter kD10{5.0, 0.0, 60.0};

SimulatedWorkpiece block(std::shared_ptr<const RemovedMaterial> removed = nullptr,
                         Placement placement = {}) {
    SimulatedWorkpiece part(placement);
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    part.setRemoved(std::move(removed));
    return part;
}

TEST(RapidCollision, PlungeIntoTheTopTakesMaterialStoppingOnItDoesNot) {
    const SimulatedWorkpiece part = block();
    EXPECT_TRUE(part.rapidTakesMaterial(kD10, Vec3(50, 30, 10), Vec3(50, 30, -1)));
    EXPECT_FALSE(part.rapidTakesMaterial(kD10, Vec3(50, 30, 10), Vec3(50, 30, 0)));
    // Less than kCollisionDepth (0.01) into it is grazing.
    EXPECT_FALSE(part.rapidTakesMaterial(kD10, Vec3(50, 30, 10), Vec3(50, 30, -0.005)));
    EXPECT_TRUE(part.rapidTakesMaterial(kD10, Vec3(50, 30, 10), Vec3(50, 30, -0.05)));
}

TEST(RapidCollision, SidewaysTheRimMeetsTheFaceBeforeTheAxis) {
    const SimulatedWorkpiece part = block();
    // Tip at z -5 towards the left face x = 0: the rim reaches x = 1 with the axis at -4.
    EXPECT_TRUE(part.rapidTakesMaterial(kD10, Vec3(-20, 30, -5), Vec3(-4, 30, -5)));
    EXPECT_FALSE(part.rapidTakesMaterial(kD10, Vec3(-20, 30, -5), Vec3(-5, 30, -5)));
    // Over the top 1 mm above it, across the whole block: free.
    EXPECT_FALSE(part.rapidTakesMaterial(kD10, Vec3(-20, 30, 1), Vec3(120, 30, 1)));
}

TEST(RapidCollision, TheRealPartCountsNotTheProgrammedOne) {
    // The blank really lies 1.5 further in +X (x 1.5 to 101.5): the rim stopping at x = 1
    // misses it; one coming from the right with its rim stopping at x = 100, on the programmed
    // right face, is 1.5 inside the real one.
    Placement placement;
    placement.shift = Vec3(1.5, 0.0, 0.0);
    const SimulatedWorkpiece part = block(nullptr, placement);
    EXPECT_FALSE(part.rapidTakesMaterial(kD10, Vec3(-20, 30, -5), Vec3(-4, 30, -5)));
    EXPECT_TRUE(part.rapidTakesMaterial(kD10, Vec3(120, 30, -5), Vec3(105, 30, -5)));
}

TEST(RapidCollision, RetractThroughADrilledHoleAndMovesInACutSlotAreFree) {
    auto removed = std::make_shared<RemovedMaterial>();
    removed->addLine(kD10, Vec3(30, 20, 2), Vec3(30, 20, -15));  // drilled D10, 15 deep
    removed->addLine(kD10, Vec3(50, 30, -5), Vec3(90, 30, -5));  // a slot 10 wide, 5 deep
    const SimulatedWorkpiece part = block(removed);
    EXPECT_FALSE(part.rapidTakesMaterial(kD10, Vec3(30, 20, -15), Vec3(30, 20, 50)));
    EXPECT_FALSE(part.rapidTakesMaterial(kD10, Vec3(90, 30, -5), Vec3(50, 30, -5)));
    // Below the hole's floor, and out of the slot sideways by 1: material.
    EXPECT_TRUE(part.rapidTakesMaterial(kD10, Vec3(30, 20, 5), Vec3(30, 20, -16)));
    EXPECT_TRUE(part.rapidTakesMaterial(kD10, Vec3(70, 30, -5), Vec3(70, 31, -5)));
}

TEST(RapidCollision, BallNoseTipCountsFromItsPoint) {
    // A ball-nose D10 plunging 1 into the top: its point goes 1 deep; 0.005 is grazing.
    const Cutter ball{5.0, 5.0, 60.0};
    const SimulatedWorkpiece part = block();
    EXPECT_TRUE(part.rapidTakesMaterial(ball, Vec3(50, 30, 10), Vec3(50, 30, -1)));
    EXPECT_FALSE(part.rapidTakesMaterial(ball, Vec3(50, 30, 10), Vec3(50, 30, -0.005)));
}

TEST(RapidCollision, AboveTheRealTopIsFreeBelowItIsNot) {
    // The blank really lies 0.2 lower (top at -0.2): across the whole block with the tip at
    // -0.15 the face (0.01 above it) stays 0.06 above the material; at -0.25 it is 0.04 in.
    Placement placement;
    placement.shift = Vec3(0.0, 0.0, -0.2);
    const SimulatedWorkpiece part = block(nullptr, placement);
    EXPECT_FALSE(part.rapidTakesMaterial(kD10, Vec3(-20, 30, -0.15), Vec3(120, 30, -0.15)));
    EXPECT_TRUE(part.rapidTakesMaterial(kD10, Vec3(-20, 30, -0.25), Vec3(120, 30, -0.25)));
}

TEST(RemovedMaterialDisc, ADiscInsideOneDrilledHoleAllTheWay) {
    // D10 drilled from z 2 to -15 at (30, 20): the hole is the cylinder of radius 5 about that
    // axis from -15 up (the cutter is 60 long).
    RemovedMaterial removed;
    removed.addLine(kD10, Vec3(30, 20, 2), Vec3(30, 20, -15));
    // A disc of 4.99 on the axis, from the floor to 40 above it: inside.
    EXPECT_TRUE(removed.containsMovingDisc(Vec3(30, 20, -15), Vec3(30, 20, 40), 4.99));
    // 0.02 off the axis its rim reaches 5.01 from it: out of the hole.
    EXPECT_FALSE(removed.containsMovingDisc(Vec3(30.02, 20, -15), Vec3(30.02, 20, 40), 4.99));
    // Wider than the hole, or reaching below its floor: not inside.
    EXPECT_FALSE(removed.containsMovingDisc(Vec3(30, 20, -10), Vec3(30, 20, 0), 5.01));
    EXPECT_FALSE(removed.containsMovingDisc(Vec3(30, 20, -15.1), Vec3(30, 20, 0), 1.0));
    // A ball-nose sweep (corner 5): thinned by 1 its core would need a corner wider than the
    // cutter, so it proves nothing (the disc may still be inside: the answer is "not proven").
    RemovedMaterial ball;
    ball.addLine(Cutter{5.0, 5.0, 60.0}, Vec3(30, 20, 2), Vec3(30, 20, -15));
    EXPECT_FALSE(ball.containsMovingDisc(Vec3(30, 20, -5), Vec3(30, 20, 0), 1.0));
    EXPECT_TRUE(ball.containsMovingDisc(Vec3(30, 20, -5), Vec3(30, 20, 0), 0.0));
}

TEST(RapidCollision, PeckDrillingRetractsAmongFourHundredHolesStayFast) {
    // Cycle 200's moves at 400 holes 10 apart (D10, pecks of 7 to 20 deep): each rapid retraces
    // a feed move of the same tool, its rim 0.01 inside that hole's wall all the way.
    SimulatedWorkpiece part;
    part.add({Box{Vec3(0, 0, -40), Vec3(210, 210, 0)}, true});
    auto removed = std::make_shared<RemovedMaterial>();
    part.setRemoved(removed);
    const auto start = std::chrono::steady_clock::now();
    int collisions = 0;
    for (int i = 0; i < 400; ++i) {
        const double x = 10.0 + 10.0 * (i % 20);
        const double y = 10.0 + 10.0 * (i / 20);
        double top = 2.0;
        for (double bottom : {-5.0, -10.0, -15.0, -20.0}) {
            collisions += part.rapidTakesMaterial(kD10, Vec3(x, y, 2), Vec3(x, y, top)) ? 1 : 0;
            removed->addLine(kD10, Vec3(x, y, top), Vec3(x, y, bottom));
            collisions += part.rapidTakesMaterial(kD10, Vec3(x, y, bottom), Vec3(x, y, 2)) ? 1 : 0;
            top = bottom + 2.0;
        }
        collisions += part.rapidTakesMaterial(kD10, Vec3(x, y, 2), Vec3(x, y, 20)) ? 1 : 0;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(collisions, 0);
    EXPECT_LT(seconds, 2.0);
}

TEST(CutRecorder, RapidIntoTheBlankIsACollisionAtItsBlock) {
    CutRecorder recorder;
    recorder.setPosition(Vec3(0, 0, 100));
    auto send = [&](int line, canon::CommandBody body) {
        recorder.consume({SourceLocation{0, static_cast<uint32_t>(line), 1, -1}, std::move(body)});
    };
    canon::ToolGeometry d10;
    d10.radiusMm = 5.0;
    d10.lengthMm = 60.0;
    Pose above;
    above.setXyz(Vec3(30, 20, 2));
    Pose deep;
    deep.setXyz(Vec3(30, 20, -15));
    send(1, canon::ToolChange{5, "MILL", d10, Axis::Z});
    send(2, canon::RapidMove{deep});  // no blank yet: nothing to collide with
    send(3, canon::RapidMove{above});
    EXPECT_TRUE(recorder.takeCollisions().empty());
    send(4, canon::StockDefinition{canon::StockBox{Vec3(0, 0, -40), Vec3(100, 60, 0)}});
    send(5, canon::LinearMove{deep, 100.0});  // drilled at feed
    send(6, canon::RapidMove{above});         // out of the hole: free
    Pose beside;
    beside.setXyz(Vec3(60, 20, -5));
    send(7, canon::RapidMove{beside});  // from above the hole down into the block
    const std::vector<SourceLocation> collisions = recorder.takeCollisions();
    ASSERT_EQ(collisions.size(), 1u);
    EXPECT_EQ(collisions[0].line, 7u);
    EXPECT_TRUE(recorder.takeCollisions().empty());
}

}  // namespace
}  // namespace kerf::workpiece
