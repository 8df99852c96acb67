#pragma once

#include "core/cycles/probing/probing_cycle.h"

// The descriptors of the probing cycles, one per file group, collected by probing_registry.cpp.
namespace kerf::cycles::probing {

extern const ProbingCycleDescriptor kProbe400;
extern const ProbingCycleDescriptor kProbe401;
extern const ProbingCycleDescriptor kProbe402;
extern const ProbingCycleDescriptor kProbe403;
extern const ProbingCycleDescriptor kProbe404;
extern const ProbingCycleDescriptor kProbe405;
extern const ProbingCycleDescriptor kProbe408;
extern const ProbingCycleDescriptor kProbe409;
extern const ProbingCycleDescriptor kProbe410;
extern const ProbingCycleDescriptor kProbe411;
extern const ProbingCycleDescriptor kProbe412;
extern const ProbingCycleDescriptor kProbe413;
extern const ProbingCycleDescriptor kProbe414;
extern const ProbingCycleDescriptor kProbe415;
extern const ProbingCycleDescriptor kProbe416;
extern const ProbingCycleDescriptor kProbe417;
extern const ProbingCycleDescriptor kProbe418;
extern const ProbingCycleDescriptor kProbe419;
extern const ProbingCycleDescriptor kProbe420;
extern const ProbingCycleDescriptor kProbe421;
extern const ProbingCycleDescriptor kProbe422;
extern const ProbingCycleDescriptor kProbe425;
extern const ProbingCycleDescriptor kProbe423;
extern const ProbingCycleDescriptor kProbe424;
extern const ProbingCycleDescriptor kProbe426;
extern const ProbingCycleDescriptor kProbe427;
extern const ProbingCycleDescriptor kProbe1416;
extern const ProbingCycleDescriptor kProbe1493;
extern const ProbingCycleDescriptor kProbe430;
extern const ProbingCycleDescriptor kProbe431;
extern const ProbingCycleDescriptor kProbe441;
extern const ProbingCycleDescriptor kProbe444;
extern const ProbingCycleDescriptor kProbe460;
extern const ProbingCycleDescriptor kProbe461;
extern const ProbingCycleDescriptor kProbe462;
extern const ProbingCycleDescriptor kProbe463;
extern const ProbingCycleDescriptor kProbe480;
extern const ProbingCycleDescriptor kProbe481;
extern const ProbingCycleDescriptor kProbe482;
extern const ProbingCycleDescriptor kProbe483;
extern const ProbingCycleDescriptor kProbe484;

}  // namespace kerf::cycles::probing
