#pragma once

#include <optional>
#include <span>

#include "core/cycles/cycle_context.h"
#include "core/cycles/cycle_parameter.h"
#include "core/cycles/cycle_path.h"

namespace kerf::cycles {

// DEF-active cycles act when their definition is read; CALL-active ones are stored as the "last
// defined machining cycle" and run by CYCL CALL, CYCL CALL PAT/POS, M99 and M89.
enum class Activation : uint8_t { Def, Call };

enum class CycleGroup : uint8_t {
    Drilling,
    Tapping,
    ThreadMilling,
    Pattern,
    Transformation,
    Special,
    PocketsStudsSlots,
    Contours,        // SL cycles 14, 20-25, 270, 275, 276
    CylinderSurface  // 27, 28, 29, 39: on the development of a cylinder (software option 1)
};

struct PatternPlan;

// Expands a CALL-active cycle at ctx.start into moves. Pure: same values, same moves.
using ExpandFunction = std::optional<CycleError> (*)(const CycleValues&, const CycleContext&,
                                                     CyclePath&);
// Computes the points of a pattern cycle (220, 221).
using PatternFunction = std::optional<CycleError> (*)(const CycleValues&, PatternPlan&);

struct CycleDescriptor {
    int number = 0;
    const char* name = nullptr;  // English, KERF_TR_NOOP
    Activation activation = Activation::Call;
    CycleGroup group = CycleGroup::Drilling;
    bool oldStyle = false;  // "CYCL DEF n.0" with sub-blocks instead of Q parameters
    std::span<const ParameterDescriptor> parameters;
    ExpandFunction expand = nullptr;
    PatternFunction pattern = nullptr;
    // Pattern cycles 220/221 overwrite Q200, Q203 and Q204 of machining cycles that have them.
    bool takesPatternClearances = false;
    // Obsolete cycles (210-215, 230, 231) run in old programs but can no longer be inserted.
    bool obsolete = false;

    const ParameterDescriptor* parameter(uint16_t q) const;
};

}  // namespace kerf::cycles
