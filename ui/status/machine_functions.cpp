#include "ui/status/machine_functions.h"

#include <algorithm>

namespace kerf::ui {

namespace {

bool has(const std::vector<int>& list, int number) {
    return std::find(list.begin(), list.end(), number) != list.end();
}

}  // namespace

interp::ProgramStatus withMachineSpindleAndCoolant(interp::ProgramStatus status,
                                                   const task::MachineStatus& machine) {
    std::vector<int>& m = status.activeM;
    const bool mist = has(m, 7);
    std::erase_if(m, [](int number) { return number >= 3 && number <= 9 && number != 6; });
    const bool turning = machine.programmedSpindleRpm > 0.0;
    m.push_back(!turning ? 5 : machine.actualSpindleRpm < 0.0 ? 4 : 3);
    m.push_back(!machine.coolant ? 9 : mist ? 7 : 8);
    std::sort(m.begin(), m.end());
    // A spindle turning at a speed in rpm shows it (the operator's S in Manual operation); a
    // stopped one keeps the S last programmed, as on the control, and a constant surface speed
    // stays as programmed.
    if (turning && !status.motion.surfaceMPerMin)
        status.motion.spindleRpm = machine.programmedSpindleRpm;
    return status;
}

}  // namespace kerf::ui
