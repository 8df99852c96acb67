#pragma once

#include <QString>
#include <vector>

#include "core/cycles/cycle_descriptor.h"

namespace kerf::ui {

// The softkey groups of the TNC's CYCL DEF key, in the order of its softkey row.
enum class CatalogueGroup {
    DrillingThread,
    PocketsStudsSlots,
    Patterns,
    ContourSl,
    CoordinateTransformations,
    SpecialCycles,
};

struct CatalogueSection {
    CatalogueGroup group;
    QString title;  // softkey text in the UI language
    std::vector<const cycles::CycleDescriptor*> cycles;
};

// The groups that hold at least one cycle of the registry, each listing its cycles in number
// order; groups without implemented cycles (pockets, SL) appear when their cycles land.
std::vector<CatalogueSection> cycleCatalogue();

CatalogueGroup catalogueGroup(const cycles::CycleDescriptor& cycle);
QString groupTitle(CatalogueGroup group);

// "DRILLING" in the UI language, and "200 DRILLING" for lists and softkeys.
QString cycleName(const cycles::CycleDescriptor& cycle);
QString cycleTitle(const cycles::CycleDescriptor& cycle);
// The long description of a parameter in the UI language.
QString parameterDescription(const cycles::ParameterDescriptor& parameter);
// "mm", "inch", "mm/min", "s", "°" ...; empty for plain numbers.
QString unitText(cycles::Unit unit, bool inch);

}  // namespace kerf::ui
