#include <algorithm>

#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

const ProbingCycleDescriptor* const kAll[] = {
    &kProbe400, &kProbe401, &kProbe402, &kProbe403, &kProbe404,  &kProbe405, &kProbe408,
    &kProbe409, &kProbe410, &kProbe411, &kProbe412, &kProbe413,  &kProbe414, &kProbe415,
    &kProbe416, &kProbe417, &kProbe418, &kProbe419, &kProbe420,  &kProbe421, &kProbe422,
    &kProbe423, &kProbe424, &kProbe425, &kProbe426, &kProbe427,  &kProbe430, &kProbe431,
    &kProbe441, &kProbe444, &kProbe460, &kProbe461, &kProbe462,  &kProbe463, &kProbe480,
    &kProbe481, &kProbe482, &kProbe483, &kProbe484, &kProbe1416, &kProbe1493};

}  // namespace

std::span<const ProbingCycleDescriptor* const> allProbingCycles() {
    return kAll;
}

const ProbingCycleDescriptor* findProbingCycle(int number) {
    auto it =
        std::find_if(std::begin(kAll), std::end(kAll),
                     [number](const ProbingCycleDescriptor* d) { return d->number == number; });
    return it == std::end(kAll) ? nullptr : *it;
}

const ProbingCycleDescriptor* findOldToolProbeCycle(int number) {
    return number >= 30 && number <= 33 ? findProbingCycle(number + 450) : nullptr;
}

}  // namespace kerf::cycles::probing
