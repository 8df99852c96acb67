#pragma once

#include <iosfwd>

#include "app/runner/picture_output.h"
#include "app/runner/run_options.h"

namespace kerf::app {

// `kerf check`: loads the program and reports its diagnostics. Returns the exit code (0 clean or
// warnings only, 1 errors).
int checkProgramCommand(const RunOptions& options, std::ostream& diagnostics);

// `kerf run`: interprets the whole program without a window, writes the trace and the JSON
// report as requested and prints diagnostics. Returns the exit code (0 ok, 1 errors).
// `makePicture` draws --png (app/runner/png_picture.h); without it --png is an error.
int runProgramCommand(const RunOptions& options, std::ostream& diagnostics,
                      PictureOutputFactory makePicture = nullptr);

}  // namespace kerf::app
