#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/canon/commands.h"
#include "core/interp/program_status.h"
#include "core/machine/machine_config.h"
#include "core/program/dialect.h"
#include "core/task/machining_clock.h"
#include "core/task/move_check.h"
#include "graphics/stock/stock_simulation.h"
#include "graphics/toolpath/toolpath_data.h"
#include "graphics/toolpath/toolpath_lod.h"

namespace kerf::ui {

// What the test run interprets: the editor's text (saved or not) with its file name, dialect and
// the machine it is written for.
struct TestRunInput {
    std::string text;
    std::filesystem::path path;
    program::Dialect dialect = program::Dialect::Klartext;
    machine::MachineConfig machine;
    std::filesystem::path ncRoot;  // called programs, tables; TOOL.T when it exists
    uint64_t maxBlocks = 20'000'000;
    // Times the program as the machine runs it (app wires motion's simulated clock); without
    // one every command ends at time 0.
    task::MachiningClockFactory clock;
    // The workpiece origin in machine coordinates, as Program run would use it (the machine
    // file's preset, PRESET.PR row 0, an entry; a FAGOR program's zero offset takes precedence).
    Pose presetInMachine{};
    // Where the tool tip stands at the start (workpiece coordinates): the machine's position for
    // Program run's graphics; the test run starts at the workpiece origin.
    Pose startPosition{};
    // Checks the moves as the machine would (soft limits, planner rules); none: not checked.
    task::MoveCheckFactory checkMoves;
};

// A point of a run: the command being executed and how far along it (0..1; a move: of its
// drawn points, which are evenly spaced; other commands: of their time).
struct RunPoint {
    size_t command = 0;
    double fraction = 0.0;
};

// How much of the toolpath a run point has passed: its points [0, pointsDone), then `tip`.
struct PathPlace {
    size_t pointsDone = 0;
    Vec3 tip{0.0, 0.0, 0.0};
};

// A program interpreted for the test run: its canonical stream with the machining time at the
// end of each command (the planner and the servo cycle in simulated time, as the program runs on
// the machine), the toolpath to draw and how to simulate its stock. Immutable once built; shared
// between threads.
struct TestRunProgram {
    std::vector<canon::Command> commands;
    std::vector<double> endTimeS;  // per command: machining time when it is done
    // Per command: the part of endTimeS spent in rapids and in feed moves (lines, arcs, probing),
    // the two the overrides change (setOverrideTimes()).
    std::vector<double> rapidEndTimeS;
    std::vector<double> feedEndTimeS;
    std::vector<uint32_t> movesBefore;  // per command: toolpath moves before it
    Pose start{};                       // tool position before the first command
    std::shared_ptr<const graphics::ToolpathData> toolpath;
    std::shared_ptr<const graphics::ToolpathGeometry> geometry;
    graphics::StockOptions stockOptions;
    // The interpreter's status after each block (after slices of blocks in long programs), with
    // the number of commands emitted up to then.
    struct StatusSnapshot {
        size_t commandsEnd = 0;
        interp::ProgramStatus status;
    };
    std::vector<StatusSnapshot> statuses;
    DiagnosticList diagnostics;
    bool ran = false;  // the program ran to its end (false: an error stopped it or it never began)
    // The block the machine would refuse (a move beyond a soft limit ...): the commands end
    // before it, and the diagnostics say why.
    std::optional<SourceLocation> refusedAt;
    bool cancelled = false;
    uint64_t blocks = 0;

    double machiningTimeS() const { return endTimeS.empty() ? 0.0 : endTimeS.back(); }
    // The index of the first command that ends after `timeS` (commands.size() when none does).
    size_t commandAt(double timeS) const;
    // The tool tip at a playback time, interpolated along the drawn toolpath.
    Vec3 toolPositionAt(double timeS) const;
    // The tool's direction on the workpiece there (+Z unless a rotary table tilts it).
    Vec3 toolAxisAt(double timeS) const;
    RunPoint runPointAt(double timeS) const;
    // Machining time at a run point (the whole time past the last command).
    double timeAt(const RunPoint& point) const;
    PathPlace placeAt(const RunPoint& point) const;
    // Fills rapidEndTimeS and feedEndTimeS from the commands and endTimeS.
    void setOverrideTimes();
    // Machining time from a run point to the end with the feed and rapid overrides (fractions)
    // applied to the feed moves and the rapids; dwells, threads and waits keep their time.
    // Infinite when an override that matters is 0.
    double remainingTimeS(const RunPoint& point, double feedOverride, double rapidOverride) const;
    // The command moves the tool (it has points of its own in the toolpath).
    bool isMove(size_t command) const;
    // The tool in the spindle at a playback time (null before the first tool change).
    const canon::ToolChange* toolAt(double timeS) const;
    // The status of the block being played at a playback time (null without any).
    const StatusSnapshot* statusAt(double timeS) const;
    // The status of the block of a command (null without any).
    const StatusSnapshot* statusOfCommand(size_t index) const;
};

// Interprets the program with the dialect's interpreter (Klartext or Fagor; TNC ISO is refused
// with a diagnostic) and collects everything the test run needs. With `checkMoves` every command
// passes the machine's check first, from the workpiece origin Program run would use: the
// program ends at the first block the machine would refuse. Synchronisation points are
// answered with the position the program commanded, as on a machine that follows it exactly.
// Any thread; `cancel` is polled between slices of blocks.
TestRunProgram interpretForTestRun(const TestRunInput& input,
                                   const std::atomic<bool>* cancel = nullptr);

}  // namespace kerf::ui
