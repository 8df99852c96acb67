#pragma once

#include <cstddef>
#include <optional>

#include "core/base/source_location.h"
#include "ui/testrun/test_run_program.h"

namespace kerf::ui {

// Follows the machine along a program prepared for the graphics (the same text the machine
// runs): from the block the machine executes and the tool tip it commands, the run point it has
// reached. The block is looked for from the point reached on (a block run again in a loop is
// its next run); within a block of several moves (a cycle) the move nearest the commanded
// position is taken, and of moves that pass there alike the one that goes the way the tool
// moves (a drill's retract over its plunge). It never goes back. Any one thread.
class MachineFollower {
public:
    explicit MachineFollower(const TestRunProgram& program) : m_program(program) {}

    // One look at the machine: the block it executes and where it commands the tool tip
    // (workpiece coordinates). A block the program does not have (yet) changes nothing.
    void observe(const SourceLocation& block, const Vec3& nominal);
    // The program ran to its end.
    void finish();

    // The first point matched (a run started at a block begins there); none before.
    const std::optional<RunPoint>& startPoint() const { return m_start; }
    const RunPoint& point() const { return m_point; }

private:
    std::optional<size_t> findBlock(const SourceLocation& block, size_t from);
    void advanceWithinBlock(const SourceLocation& block, const Vec3& nominal);

    const TestRunProgram& m_program;
    std::optional<RunPoint> m_start;
    RunPoint m_point;
    std::optional<Vec3> m_lastNominal;
    // A block searched for to the end of the program in vain (not searched that far again).
    std::optional<SourceLocation> m_missing;
};

}  // namespace kerf::ui
