#include "ui/cycles/cycle_catalogue.h"

#include <QCoreApplication>

#include "core/cycles/cycle_registry.h"

namespace kerf::ui {

namespace {

constexpr CatalogueGroup kGroupOrder[] = {
    CatalogueGroup::DrillingThread,
    CatalogueGroup::PocketsStudsSlots,
    CatalogueGroup::Patterns,
    CatalogueGroup::ContourSl,
    CatalogueGroup::CoordinateTransformations,
    CatalogueGroup::SpecialCycles,
};

}  // namespace

CatalogueGroup catalogueGroup(const cycles::CycleDescriptor& cycle) {
    using cycles::CycleGroup;
    // Cycle 18 is a tapping cycle in the registry; the TNC lists it with the special cycles.
    if (cycle.number == 18) return CatalogueGroup::SpecialCycles;
    // Face milling 232 and 233 sit with the pockets on the TNC softkeys.
    if (cycle.number == 232 || cycle.number == 233) return CatalogueGroup::PocketsStudsSlots;
    switch (cycle.group) {
        case CycleGroup::Drilling:
        case CycleGroup::Tapping:
        case CycleGroup::ThreadMilling:
            return CatalogueGroup::DrillingThread;
        case CycleGroup::Pattern:
            return CatalogueGroup::Patterns;
        case CycleGroup::Transformation:
            return CatalogueGroup::CoordinateTransformations;
        case CycleGroup::Special:
            return CatalogueGroup::SpecialCycles;
        case CycleGroup::PocketsStudsSlots:
        case CycleGroup::Contours:  // SL cycles: no group of their own in the catalogue yet
        case CycleGroup::CylinderSurface:
            return CatalogueGroup::PocketsStudsSlots;
    }
    return CatalogueGroup::SpecialCycles;
}

QString groupTitle(CatalogueGroup group) {
    switch (group) {
        case CatalogueGroup::DrillingThread:
            return QCoreApplication::translate("kerf", "Drilling/\nthread");
        case CatalogueGroup::PocketsStudsSlots:
            return QCoreApplication::translate("kerf", "Pockets/\nstuds/slots");
        case CatalogueGroup::Patterns:
            return QCoreApplication::translate("kerf", "Patterns");
        case CatalogueGroup::ContourSl:
            return QCoreApplication::translate("kerf", "SL cycles");
        case CatalogueGroup::CoordinateTransformations:
            return QCoreApplication::translate("kerf", "Coordinate\ntransform.");
        case CatalogueGroup::SpecialCycles:
            return QCoreApplication::translate("kerf", "Special\ncycles");
    }
    return {};
}

std::vector<CatalogueSection> cycleCatalogue() {
    std::vector<CatalogueSection> sections;
    for (CatalogueGroup group : kGroupOrder) {
        CatalogueSection section{group, groupTitle(group), {}};
        for (const cycles::CycleDescriptor* cycle : cycles::allCycles()) {
            if (catalogueGroup(*cycle) == group) section.cycles.push_back(cycle);
        }
        if (!section.cycles.empty()) sections.push_back(std::move(section));
    }
    return sections;
}

QString cycleName(const cycles::CycleDescriptor& cycle) {
    return QCoreApplication::translate("kerf", cycle.name);
}

QString cycleTitle(const cycles::CycleDescriptor& cycle) {
    return QStringLiteral("%1 %2").arg(cycle.number).arg(cycleName(cycle));
}

QString parameterDescription(const cycles::ParameterDescriptor& parameter) {
    return QCoreApplication::translate("kerf", parameter.description);
}

QString unitText(cycles::Unit unit, bool inch) {
    using cycles::Unit;
    switch (unit) {
        case Unit::Millimetre:
            return inch ? QStringLiteral("inch") : QStringLiteral("mm");
        case Unit::FeedPerMinute:
            return inch ? QStringLiteral("inch/min") : QStringLiteral("mm/min");
        case Unit::Seconds:
            return QStringLiteral("s");
        case Unit::Degrees:
            return QStringLiteral("°");
        case Unit::Rpm:
            return QStringLiteral("1/min");
        case Unit::Percent:
            return QStringLiteral("%");
        case Unit::None:
        case Unit::Factor:
        case Unit::Count:
        case Unit::Text:
            return {};
    }
    return {};
}

}  // namespace kerf::ui
