#include "ui/cycles/cycle_help_picture.h"

#include <QPainter>
#include <algorithm>
#include <utility>

#include "ui/cycles/cycle_fields.h"

namespace kerf::ui {

namespace {

constexpr double kDrawingSize = 100.0;
constexpr double kMargin = 8.0;
// The parameter being entered is drawn in orange, the others in blue.
const QColor kHighlight(230, 110, 0);
const QColor kDimension(60, 90, 140);

}  // namespace

CycleHelpPicture::CycleHelpPicture(QWidget* parent) : QWidget(parent) {
    setObjectName("cycleHelpPicture");
    setMinimumSize(240, 240);
}

void CycleHelpPicture::setCycle(const cycles::CycleDescriptor& cycle) {
    m_drawing = helpDrawing(cycle);
    // The group's picture names only the dimensions this cycle asks for.
    QStringList labels;
    for (const CycleField& field : cycleFields(cycle))
        labels << field.label;
    std::erase_if(m_drawing.dimensions, [&labels](const HelpDimension& dimension) {
        return std::none_of(dimension.keys.begin(), dimension.keys.end(),
                            [&labels](const QString& key) { return labels.contains(key); });
    });
    // Each dimension is labelled with the name this cycle gives it (DEPTH of cycle 18: Q201).
    for (HelpDimension& dimension : m_drawing.dimensions) {
        for (int i = 0; i < dimension.keys.size(); ++i) {
            if (labels.contains(dimension.keys[i])) {
                dimension.keys.move(i, 0);
                break;
            }
        }
    }
    update();
}

void CycleHelpPicture::setDrawing(HelpDrawing drawing) {
    m_drawing = std::move(drawing);
    update();
}

void CycleHelpPicture::setField(const QString& label) {
    m_field = label;
    update();
}

QTransform CycleHelpPicture::toWidget() const {
    const double side = std::max(1.0, std::min(width(), height()) - 2 * kMargin);
    const double scale = side / kDrawingSize;
    QTransform transform;
    transform.translate((width() - side) / 2.0, (height() - side) / 2.0);
    transform.scale(scale, scale);
    return transform;
}

QRectF CycleHelpPicture::highlightRect() const {
    const HelpDimension* dimension = m_drawing.find(m_field);
    if (!dimension) return {};
    return toWidget().mapRect(dimension->path.boundingRect().adjusted(-1, -1, 1, 1));
}

void CycleHelpPicture::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(rect(), Qt::white);
    const QTransform transform = toWidget();
    const double scale = transform.m11();
    painter.setTransform(transform);
    painter.setPen(QPen(QColor(90, 90, 90), 0.6));
    painter.setBrush(QColor(200, 205, 215));
    painter.drawPath(m_drawing.solid);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(40, 40, 40), 0.8));
    painter.drawPath(m_drawing.lines);

    QFont font = painter.font();
    font.setPixelSize(std::max(9, static_cast<int>(3.6 * scale)));
    font.setBold(true);
    for (const HelpDimension& dimension : m_drawing.dimensions) {
        const bool active = dimension.keys.contains(m_field);
        const QColor colour = active ? kHighlight : kDimension;
        painter.setTransform(transform);
        painter.setPen(QPen(colour, active ? 1.6 : 0.5));
        painter.drawPath(dimension.path);
        // Labels in widget pixels, so that text stays readable at any size.
        painter.resetTransform();
        painter.setFont(font);
        painter.setPen(colour);
        const QString label = active ? m_field : dimension.keys.first();
        painter.drawText(transform.map(dimension.labelAt), label);
    }
}

}  // namespace kerf::ui
