#pragma once

#include <vector>

namespace kerf::fagor {

// One entry of the M function table (spec part 1 §8.9).
struct MFunctionEntry {
    int number = 0;
    int subroutine = 0;             // associated subroutine (0: none)
    bool beforeMotion = false;      // executed before the block's motion, else after it
    bool stopsPreparation = false;  // breaks radius compensation like G04
    bool afterSubroutine = false;   // the M itself is output after its subroutine
};

// The table the manual recommends: M03, M04, M41-M44 before the motion; M00, M01, M02, M05, M06,
// M19, M30 after it. An M without an entry acts at the start of its block.
std::vector<MFunctionEntry> defaultMFunctionTable();

const MFunctionEntry* findMFunction(const std::vector<MFunctionEntry>& table, int number);

}  // namespace kerf::fagor
