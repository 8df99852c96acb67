#pragma once

#include <array>
#include <filesystem>
#include <string>

#include "core/machine/machine_config.h"

namespace kerf::ui {

// What the operator gives for a new program, as the TNC's and the FAGOR's "new program" ask it:
// the name, the unit and (TNC) the blank as a box in workpiece coordinates.
struct NewProgramSpec {
    std::string name;  // file name; the dialect's extension is added when it has none
    bool inch = false;
    std::array<double, 3> blankMin{0.0, 0.0, -40.0};  // X Y Z
    std::array<double, 3> blankMax{100.0, 100.0, 0.0};
};

// The file name of the new program: `name` with `.H` (mill, Klartext) or `.PIM` (lathe, FAGOR)
// when it has no extension of its own. On a lathe a leading `%` (the FAGOR header's mark, typed
// as "%PART") is dropped.
std::string newProgramFileName(const machine::MachineConfig& machine, const std::string& name);

// The new program's text. Mill (Klartext, as the TNC writes it):
//   0 BEGIN PGM NAME MM
//   1 BLK FORM 0.1 Z X+0 Y+0 Z-40
//   2 BLK FORM 0.2 X+100 Y+100 Z+0
//   3 END PGM NAME MM
// A mill program named `.I` is TNC ISO (docs/tnciso.md), the same blank in its ISO form:
//   %NAME G71 *
//   N10 G30 G17 X+0 Y+0 Z-40 *
//   N20 G31 G90 X+100 Y+100 Z+0 *
//   N99999999 %NAME G71 *
// Lathe (FAGOR): the `%NAME,MX,` header, the unit (G71 mm, G70 inch) and M30.
std::string newProgramText(const machine::MachineConfig& machine, const NewProgramSpec& spec);

}  // namespace kerf::ui
