#pragma once

#include <QPainterPath>
#include <QPointF>
#include <QString>
#include <QStringList>
#include <vector>

#include "core/cycles/cycle_descriptor.h"

namespace kerf::ui {

// One dimension of a help picture: what it measures (the field labels it stands for, "Q200",
// "ROT", ...), its lines and arrows, and where its label goes.
struct HelpDimension {
    QStringList keys;
    QPainterPath path;
    QPointF labelAt;
};

// A help picture in a 100 x 100 drawing space (y down): the part and tool outlines and the
// dimensions. The picture follows the cycle's group: a drilling/thread section, a face-milling
// top view, a polar or Cartesian pattern, a coordinate transformation, engraving or the
// special cycles' symbols.
struct HelpDrawing {
    QPainterPath solid;  // workpiece, filled
    QPainterPath lines;  // tool, axes and auxiliary lines
    std::vector<HelpDimension> dimensions;

    const HelpDimension* find(const QString& key) const;
};

HelpDrawing helpDrawing(const cycles::CycleDescriptor& cycle);

}  // namespace kerf::ui
