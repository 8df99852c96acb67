#include "ui/cycles/help_shapes.h"

#include <QLineF>
#include <QtMath>
#include <algorithm>
#include <cmath>

namespace kerf::ui {

// A straight dimension with arrowheads at both ends (an arrow at `b` only if `oneWay`).
QPainterPath arrow(QPointF a, QPointF b, bool oneWay) {
    QPainterPath path;
    path.moveTo(a);
    path.lineTo(b);
    const QLineF line(a, b);
    const auto head = [&path](QPointF tip, double angleDegrees) {
        QLineF side(tip, tip + QPointF(3.0, 0.0));
        side.setAngle(angleDegrees + 25.0);
        path.moveTo(side.p2());
        path.lineTo(tip);
        side.setAngle(angleDegrees - 25.0);
        path.lineTo(side.p2());
    };
    head(b, line.angle() + 180.0);
    if (!oneWay) head(a, line.angle());
    return path;
}

// An angle dimension: an arc around `centre` from `startDegrees` over `spanDegrees`
// (counter-clockwise on screen, as angles are in the plane).
QPainterPath angleArc(QPointF centre, double radius, double startDegrees, double spanDegrees) {
    QPainterPath path;
    const QRectF box(centre.x() - radius, centre.y() - radius, 2 * radius, 2 * radius);
    path.arcMoveTo(box, startDegrees);
    path.arcTo(box, startDegrees, spanDegrees);
    const double end = qDegreesToRadians(startDegrees + spanDegrees);
    const QPointF tip(centre.x() + radius * std::cos(end), centre.y() - radius * std::sin(end));
    QPainterPath head =
        arrow(tip + QPointF(std::sin(end), std::cos(end)) * (spanDegrees > 0 ? 2 : -2), tip, true);
    path.addPath(head);
    return path;
}

QPainterPath ring(QPointF centre, double radius) {
    QPainterPath path;
    path.addEllipse(centre, radius, radius);
    return path;
}

QPainterPath dashes(QPointF a, QPointF b) {
    QPainterPath path;
    const QLineF line(a, b);
    const int pieces = std::max(1, static_cast<int>(line.length() / 4.0));
    for (int i = 0; i < pieces; i += 2) {
        path.moveTo(line.pointAt(static_cast<double>(i) / pieces));
        path.lineTo(line.pointAt(static_cast<double>(i + 1) / pieces));
    }
    return path;
}

}  // namespace kerf::ui
