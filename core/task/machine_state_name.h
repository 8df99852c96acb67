#pragma once

// machineStateName (core/task/machine_status.h) marks each name for translation with this
// disambiguation: the machine's words agree with "machine", feminine in Portuguese, Spanish and
// Polish, where the program's run states with the same English words agree with "program".
namespace kerf::task {

inline constexpr const char* kMachineStateDisambiguation = "machine state";

}  // namespace kerf::task
