#pragma once

#include "core/cycles/cycle_descriptor.h"

// Every implemented cycle's descriptor, each defined in its own file; cycle_registry.cpp lists
// them in one table.
namespace kerf::cycles {

extern const CycleDescriptor kCycle7, kCycle8, kCycle9, kCycle10, kCycle11, kCycle12, kCycle13,
    kCycle14, kCycle18, kCycle20, kCycle21, kCycle22, kCycle23, kCycle24, kCycle19, kCycle26,
    kCycle32;
extern const CycleDescriptor kCycle200, kCycle201, kCycle202, kCycle203, kCycle204, kCycle205,
    kCycle206, kCycle207, kCycle208, kCycle209, kCycle220, kCycle221, kCycle225, kCycle232,
    kCycle240, kCycle241, kCycle247, kCycle251, kCycle252, kCycle253, kCycle254, kCycle256,
    kCycle257, kCycle258, kCycle262, kCycle263, kCycle264, kCycle265, kCycle267;
extern const CycleDescriptor kCycle25, kCycle270, kCycle275,
    kCycle276;                           // contour train, trochoidal slot
extern const CycleDescriptor kCycle233;  // face milling with side walls
extern const CycleDescriptor kCycle27, kCycle28, kCycle29, kCycle39;  // cylinder surface
// Obsolete cycles that old programs still contain (core/cycles/legacy): they run, but the
// cycle menus (allCycles) do not offer them.
extern const CycleDescriptor kCycle210, kCycle211, kCycle212, kCycle213, kCycle214, kCycle215,
    kCycle230, kCycle231;

}  // namespace kerf::cycles
