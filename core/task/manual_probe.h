#pragma once

#include <filesystem>

#include "core/base/expected.h"
#include "core/canon/commands.h"
#include "core/machine/machine_config.h"
#include "core/workpiece/simulated_workpiece.h"

// What Manual operation's probing functions need besides the touches' geometry
// (cycles/probing/manual_probing.h): the probe in the spindle and the simulated part it touches.
namespace kerf::task {

struct ManualProbe {
    double ballRadius = 0.0;   // TOOL.T R + DR of the tool in the spindle
    double probingFeed = 0.0;  // F of its touch-probe table row, mm/min
    double maxPath = 0.0;      // DIST of that row
};

// The probe `toolNumber` of the NC root's TOOL.T and the row of tchprobe.tp its TP_NO column
// names (row 1 without the column; a new row's values without the table), as the probing cycles
// take them. Errors: no tool in the spindle, a table that cannot be read, a missing row.
Expected<ManualProbe> manualProbe(const std::filesystem::path& ncRoot, int toolNumber);

// The part clamped for a program: its blank (BLK FORM) and the calibration sphere, placed with
// [simulation.setup], less what the program cut (`removed`, may be null), in the blank's
// programmed frame: the part the probing cycles of that run touched.
workpiece::SimulatedWorkpiece manualProbingPart(
    const machine::MachineConfig& machine, const canon::StockDefinition& blank,
    std::shared_ptr<const workpiece::RemovedMaterial> removed);

}  // namespace kerf::task
