#pragma once

#include <memory>

#include "app/runner/picture_output.h"

namespace kerf::app {

// The picture of `kerf run --png`, rendered off screen with VTK (starting Xvfb when there is no
// display). A PictureOutputFactory for runProgramCommand.
std::unique_ptr<PictureOutput> makePngPicture(const RunOptions& options, const Session& session);

}  // namespace kerf::app
