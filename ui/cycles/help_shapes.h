#pragma once

#include <QPainterPath>
#include <QPointF>

namespace kerf::ui {

// The strokes the help pictures are drawn with (TNC and FAGOR cycles), in the 100 x 100
// drawing space of HelpDrawing.

// A straight dimension with arrowheads at both ends (an arrow at `b` only if `oneWay`).
QPainterPath arrow(QPointF a, QPointF b, bool oneWay = false);
// An angle dimension: an arc around `centre` from `startDegrees` over `spanDegrees`
// (counter-clockwise on screen, as angles are in the plane).
QPainterPath angleArc(QPointF centre, double radius, double startDegrees, double spanDegrees);
QPainterPath ring(QPointF centre, double radius);
QPainterPath dashes(QPointF a, QPointF b);

}  // namespace kerf::ui
