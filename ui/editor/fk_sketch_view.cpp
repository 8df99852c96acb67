#include "ui/editor/fk_sketch_view.h"

#include <QPainter>
#include <QPainterPath>
#include <cmath>
#include <numbers>
#include <optional>

namespace kerf::ui {

namespace {

const QColor kContour(150, 150, 150);
const QColor kDetermined(20, 80, 200);
const QColor kOpen(210, 40, 40);
const QColor kSolution(190, 0, 170);

constexpr double kArcStepRad = std::numbers::pi / 90.0;  // 2° per drawn chord

std::vector<Vec2> pointsOf(const PlanarSegment& s) {
    if (s.kind == PlanarSegment::Kind::Line) return {s.start, s.end};
    const int steps = std::max(2, static_cast<int>(std::ceil(std::fabs(s.sweep) / kArcStepRad)));
    std::vector<Vec2> points;
    const Vec2 r = s.start - s.center;
    for (int i = 0; i <= steps; ++i) {
        const double a = s.sweep * i / steps;
        points.emplace_back(s.center.x() + r.x() * std::cos(a) - r.y() * std::sin(a),
                            s.center.y() + r.x() * std::sin(a) + r.y() * std::cos(a));
    }
    return points;
}

// Fits the drawing's extent into the widget, Y up, with a margin.
class Frame {
public:
    void include(const Vec2& p) {
        m_min = m_min.cwiseMin(p);
        m_max = m_max.cwiseMax(p);
        m_empty = false;
    }
    void include(const PlanarSegment& s) {
        for (const Vec2& p : pointsOf(s))
            include(p);
    }
    bool empty() const { return m_empty; }
    void fit(const QRectF& area) {
        const Vec2 size = (m_max - m_min).cwiseMax(Vec2(1.0, 1.0));
        m_scale = std::min(area.width() / size.x(), area.height() / size.y());
        const Vec2 middle = (m_min + m_max) / 2.0;
        m_offset = QPointF(area.center().x() - middle.x() * m_scale,
                           area.center().y() + middle.y() * m_scale);
    }
    QPointF map(const Vec2& p) const {
        return {m_offset.x() + p.x() * m_scale, m_offset.y() - p.y() * m_scale};
    }
    QPainterPath path(const PlanarSegment& s) const {
        const std::vector<Vec2> points = pointsOf(s);
        QPainterPath path(map(points.front()));
        for (size_t i = 1; i < points.size(); ++i)
            path.lineTo(map(points[i]));
        return path;
    }

private:
    Vec2 m_min{1e300, 1e300}, m_max{-1e300, -1e300};
    bool m_empty = true;
    double m_scale = 1.0;
    QPointF m_offset;
};

QPen pen(const QColor& colour, double width, Qt::PenStyle style = Qt::SolidLine) {
    QPen p(colour, width, style);
    p.setCapStyle(Qt::RoundCap);
    return p;
}

}  // namespace

FkSketchView::FkSketchView(QWidget* parent) : QWidget(parent) {
    setObjectName("fkSketch");
    setMinimumSize(200, 200);
    setAutoFillBackground(true);
    QPalette p = palette();
    p.setColor(QPalette::Window, Qt::white);
    setPalette(p);
}

void FkSketchView::setSketch(std::shared_ptr<const task::ProgramSketch> sketch) {
    m_sketch = std::move(sketch);
    update();
}

void FkSketchView::setCursorLine(int line) {
    if (line == m_cursorLine) return;
    m_cursorLine = line;
    update();
}

void FkSketchView::setOffer(int ambiguity, int solution) {
    m_ambiguity = ambiguity;
    m_solution = solution;
    update();
}

void FkSketchView::paintEvent(QPaintEvent*) {
    if (!m_sketch) return;
    const auto& fk = m_sketch->fk;
    const auto& ambiguities = fk.ambiguities;
    const bool offering = m_ambiguity >= 0 && m_ambiguity < static_cast<int>(ambiguities.size());

    Frame frame;
    for (const auto& move : m_sketch->moves)
        frame.include(move.segment);
    for (const auto& element : fk.elements) {
        if (element.segment) frame.include(*element.segment);
        if (element.givenEnd) frame.include(*element.givenEnd);
        if (element.sequenceStart) frame.include(*element.sequenceStart);
    }
    if (offering)
        for (const auto& s : ambiguities[static_cast<size_t>(m_ambiguity)].alternatives)
            frame.include(s);
    if (frame.empty()) return;
    frame.fit(QRectF(rect()).adjusted(24, 24, -24, -24));

    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    auto wide = [this](uint32_t line) {
        return static_cast<int>(line) == m_cursorLine ? 2.0 : 1.0;
    };
    // The moves an FK element emitted are drawn from the FK element (without compensation).
    auto isFkLine = [&fk](uint32_t line) {
        return std::any_of(fk.elements.begin(), fk.elements.end(),
                           [line](const auto& e) { return e.at.line == line; });
    };
    std::optional<Vec2> lastEnd;
    for (const auto& move : m_sketch->moves) {
        if (isFkLine(move.at.line)) continue;
        painter.setPen(pen(kContour, (move.rapid ? 1.0 : 2.0) * wide(move.at.line),
                           move.rapid ? Qt::DashLine : Qt::SolidLine));
        painter.drawPath(frame.path(move.segment));
    }
    int open = 0;
    int tentative = 0;
    for (const auto& element : fk.elements) {
        if (element.sequenceStart) lastEnd = element.sequenceStart;
        if (element.segment) {
            // Elements that follow from solution 1 of a missing FSELECT are dashed.
            tentative += element.tentative ? 1 : 0;
            painter.setPen(pen(kDetermined, 2.5 * wide(element.at.line),
                               element.tentative ? Qt::DashLine : Qt::SolidLine));
            painter.drawPath(frame.path(*element.segment));
            lastEnd = element.segment->end;
            continue;
        }
        ++open;
        painter.setPen(pen(kOpen, 2.0 * wide(element.at.line), Qt::DashLine));
        if (element.givenEnd && lastEnd) {
            painter.drawLine(frame.map(*lastEnd), frame.map(*element.givenEnd));
        } else if (lastEnd) {
            painter.drawEllipse(frame.map(*lastEnd), 8.0 + 4.0 * open, 8.0 + 4.0 * open);
        }
        if (element.givenEnd) lastEnd = element.givenEnd;
    }
    if (offering) {
        const auto& offer = ambiguities[static_cast<size_t>(m_ambiguity)];
        for (size_t i = 0; i < offer.alternatives.size(); ++i) {
            const bool shown = static_cast<int>(i) + 1 == m_solution;
            painter.setPen(pen(kSolution, shown ? 4.0 : 1.0, shown ? Qt::SolidLine : Qt::DotLine));
            painter.drawPath(frame.path(offer.alternatives[i]));
        }
    }

    // The legend, top left.
    struct Entry {
        QColor colour;
        double width;
        Qt::PenStyle style;
        QString text;
    };
    std::vector<Entry> legend{{kContour, 2.0, Qt::SolidLine, tr("Contour")},
                              {kDetermined, 2.5, Qt::SolidLine, tr("FK element determined")}};
    if (tentative > 0) {
        legend.push_back({kDetermined, 2.5, Qt::DashLine,
                          tr("FK element with solution 1 assumed (no FSELECT)")});
    }
    if (open > 0) legend.push_back({kOpen, 2.0, Qt::DashLine, tr("FK element not determined")});
    if (offering) {
        const auto count =
            static_cast<int>(ambiguities[static_cast<size_t>(m_ambiguity)].alternatives.size());
        legend.push_back(
            {kSolution, 4.0, Qt::SolidLine, tr("Solution %1 of %2").arg(m_solution).arg(count)});
        legend.push_back({kSolution, 1.0, Qt::DotLine, tr("Other solutions")});
    }
    const QFontMetrics metrics(font());
    const int rowHeight = metrics.height() + 4;
    int width = 0;
    for (const Entry& e : legend)
        width = std::max(width, metrics.horizontalAdvance(e.text));
    const QRect box(6, 6, width + 48, rowHeight * static_cast<int>(legend.size()) + 6);
    painter.setPen(QPen(QColor(200, 200, 200)));
    painter.setBrush(QColor(255, 255, 255, 220));
    painter.drawRect(box);
    for (size_t i = 0; i < legend.size(); ++i) {
        const int y = box.top() + 3 + rowHeight * static_cast<int>(i) + rowHeight / 2;
        painter.setPen(pen(legend[i].colour, legend[i].width, legend[i].style));
        painter.drawLine(box.left() + 6, y, box.left() + 34, y);
        painter.setPen(Qt::black);
        painter.drawText(box.left() + 40, y + metrics.ascent() / 2 - 1, legend[i].text);
    }
}

}  // namespace kerf::ui
