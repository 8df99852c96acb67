#pragma once

#include <filesystem>
#include <vector>

#include "app/runner/run_options.h"
#include "core/base/diagnostic.h"

namespace kerf::app {

// The files a run writes (--trace, --samples, --report, --png, --can-trace) must not be a file it
// reads: `kerf run prog.H --trace prog.H` would otherwise truncate its own program. One diagnostic
// per output that names the same file (any path, link or hard link) as one of `inputs`.
DiagnosticList outputsOverwritingInputs(const RunOptions& options,
                                        const std::vector<std::filesystem::path>& inputs);

}  // namespace kerf::app
