#pragma once

#include <span>

#include "core/cycles/cycle_parameter.h"

namespace kerf::cycles {

// A GLOBAL DEF group: program-wide values that cycle parameters written as PREDEF take.
struct GlobalDefGroup {
    int number = 0;
    const char* name = nullptr;  // English, KERF_TR_NOOP
    std::span<const ParameterDescriptor> parameters;
};

std::span<const GlobalDefGroup> globalDefGroups();
const GlobalDefGroup* findGlobalDefGroup(int number);

}  // namespace kerf::cycles
