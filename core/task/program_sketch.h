#pragma once

#include <atomic>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/geometry/offset_contour.h"
#include "core/interp/klartext/fk_trace.h"
#include "core/machine/machine_config.h"
#include "core/task/program_loader.h"

// The editor's view of a program: its check, and for a Klartext program with FK blocks a dry run
// that finds the FK solver's errors and records the contour for the programming graphics
// (docs/hmi.md, "FK programming graphics"). Qt-free; any thread.
namespace kerf::task {

// A move of the main program in the FK elements' working plane (its first and second axes: X Y,
// Z X or Y Z), the contour around them.
struct SketchMove {
    SourceLocation at;
    PlanarSegment segment;
    bool rapid = false;
};

struct ProgramSketch {
    // The check's diagnostics, then the FK errors of the dry run.
    DiagnosticList diagnostics;
    klartext::FkTrace fk;           // elements and choices of the main program
    std::vector<SketchMove> moves;  // every other move of the main program
    bool cancelled = false;
};

// Whether the text may contain FK blocks (a block starting with FL, FLT, FC, FCT, FPOL or
// FSELECT): only then is the dry run worth its time.
bool mayUseFk(std::string_view text);

// Loads the program as `kerf check` does; when it is a Klartext program without errors that may
// use FK, runs it (at most `maxBlocks` blocks, synchronisation answered with the commanded
// position) and keeps what the FK solver did. `cancel` is polled between slices of blocks.
ProgramSketch sketchProgram(const machine::MachineConfig& machine, const ProgramRequest& request,
                            const std::atomic<bool>* cancel = nullptr,
                            uint64_t maxBlocks = 200'000);

}  // namespace kerf::task
