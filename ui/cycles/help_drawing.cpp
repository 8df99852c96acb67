#include "ui/cycles/help_drawing.h"

#include <QtMath>
#include <algorithm>
#include <cmath>
#include <vector>

#include "ui/cycles/help_shapes.h"

namespace kerf::ui {

namespace {

QPointF polar(QPointF centre, double radius, double degrees) {
    const double a = qDegreesToRadians(degrees);
    return {centre.x() + radius * std::cos(a), centre.y() - radius * std::sin(a)};
}

// Side section of a hole: surface at y 50, set-up clearance 40, 2nd set-up clearance 15,
// first infeed 62, bottom 85; the tool waits at the set-up clearance.
HelpDrawing drillingSection(bool thread) {
    HelpDrawing d;
    d.solid.addRect(8, 50, 37, 45);
    d.solid.addRect(55, 50, 37, 45);
    d.solid.addRect(45, 85, 10, 10);
    d.lines.addRect(46.5, 12, 7, 24);  // tool shank
    d.lines.moveTo(46.5, 36);
    d.lines.lineTo(50, 40);
    d.lines.lineTo(53.5, 36);
    d.lines.addPath(dashes({5, 40}, {95, 40}));
    d.lines.addPath(dashes({5, 15}, {95, 15}));
    if (thread) {
        for (double y = 56; y < 84; y += 6) {
            d.lines.moveTo(45, y);
            d.lines.lineTo(43, y + 3);
            d.lines.lineTo(45, y + 6);
            d.lines.moveTo(55, y);
            d.lines.lineTo(57, y + 3);
            d.lines.lineTo(55, y + 6);
        }
    }
    d.dimensions = {
        {{"Q200", "Q6"}, arrow({30, 50}, {30, 40}), {31, 44}},
        {{"Q204", "Q7"}, arrow({20, 50}, {20, 15}), {21, 30}},
        {{"Q201", "DEPTH", "Q1"}, arrow({66, 50}, {66, 85}), {67, 70}},
        {{"Q202", "Q334", "Q10"}, arrow({78, 50}, {78, 62}), {79, 57}},
        {{"Q203", "Q5"}, arrow({97, 97}, {97, 50}, true), {86, 99}},
        {{"Q206", "Q11", "Q253"}, arrow({38, 42}, {38, 64}, true), {26, 62}},
        {{"Q208"}, arrow({42, 80}, {42, 56}, true), {31, 78}},
        {{"Q210"}, ring({60, 40}, 2.5), {63, 37}},
        {{"Q211", "Q255"}, ring({50, 85}, 2.5), {57, 89}},
        {{"Q335", "Q344", "Q342"}, arrow({45, 47}, {55, 47}), {44, 45}},
        {{"Q239", "PITCH"}, arrow({59, 62}, {59, 68}), {60, 65}},
        {{"Q205", "Q212", "Q256", "Q257"}, arrow({86, 62}, {86, 70}), {84, 75}},
    };
    if (!thread) {
        std::erase_if(d.dimensions,
                      [](const HelpDimension& dim) { return dim.keys.contains("Q239"); });
    }
    return d;
}

// Face milling (232) and pockets: the face in top view with its start point, the side lengths
// and the meander path; start and end height in a small side view on the right.
HelpDrawing faceMilling() {
    HelpDrawing d;
    d.solid.addRect(20, 30, 55, 45);
    d.lines.moveTo(10, 90);
    d.lines.lineTo(10, 10);
    d.lines.moveTo(10, 90);
    d.lines.lineTo(90, 90);
    QPainterPath meander;
    meander.moveTo(20, 70);
    for (int i = 0; i < 4; ++i) {
        const double y = 70 - i * 12;
        meander.lineTo(i % 2 == 0 ? 75 : 20, y);
        if (i < 3) meander.lineTo(i % 2 == 0 ? 75 : 20, y - 12);
    }
    d.dimensions = {
        {{"Q225"}, arrow({10, 84}, {20, 84}), {11, 82}},
        {{"Q226"}, arrow({14, 90}, {14, 75}), {1, 73}},
        {{"Q218"}, arrow({20, 24}, {75, 24}), {42, 22}},
        {{"Q219"}, arrow({80, 30}, {80, 75}), {81, 52}},
        {{"Q389", "Q370"}, meander, {40, 82}},
        {{"Q227"}, arrow({92, 60}, {92, 40}, true), {84, 38}},
        {{"Q386", "Q202"}, arrow({96, 40}, {96, 52}, true), {88, 58}},
    };
    return d;
}

// Cycles 251-257: the outline of the pocket, stud or slot in plan with its sizes.
// SL cycles: the drilling section read as a pocket (its walls the contour) with the allowances
// of cycle 20 and the contour labels of cycle 14 on the walls.
HelpDrawing contourSection() {
    HelpDrawing d = drillingSection(false);
    QPainterPath walls;
    walls.moveTo(45, 50);
    walls.lineTo(45, 85);
    walls.lineTo(55, 85);
    walls.lineTo(55, 50);
    d.dimensions.push_back({{"CONTOUR LABEL"}, walls, {47, 92}});
    d.dimensions.push_back({{"Q3", "Q14"}, arrow({45, 75}, {48, 75}), {35, 75}});
    d.dimensions.push_back({{"Q4"}, arrow({50, 85}, {50, 82}), {51, 80}});
    return d;
}

// Cycle 270: the contour seen from above, the tool coming onto it on an arc of radius Q392 over
// the centre angle Q393 (or from an auxiliary point Q394 away).
HelpDrawing contourTrainApproach() {
    HelpDrawing d;
    d.lines.moveTo(10, 70);
    d.lines.lineTo(90, 70);
    const QPointF centre(50, 45);
    QPainterPath approach;
    approach.arcMoveTo(QRectF(25, 20, 50, 50), 180);
    approach.arcTo(QRectF(25, 20, 50, 50), 180, 90);
    d.lines.addPath(approach);
    d.solid.addEllipse(QPointF(25, 45), 3, 3);
    d.dimensions = {
        {{"Q392"}, arrow(centre, {50, 70}), {52, 58}},
        {{"Q393"}, angleArc(centre, 12, 180, 90), {34, 36}},
        {{"Q394"}, arrow({25, 45}, {25, 70}), {12, 58}},
        {{"Q390", "Q391"}, dashes({50, 70}, {90, 70}), {62, 80}},
    };
    return d;
}

HelpDrawing pocketPlan() {
    HelpDrawing d;
    d.solid.addRoundedRect(QRectF(25, 30, 55, 40), 8, 8);
    d.lines.moveTo(10, 90);
    d.lines.lineTo(10, 10);
    d.lines.moveTo(10, 90);
    d.lines.lineTo(90, 90);
    d.dimensions = {
        {{"Q218", "Q223", "Q424", "Q222"}, arrow({25, 24}, {80, 24}), {48, 22}},
        {{"Q219", "Q425"}, arrow({86, 30}, {86, 70}), {87, 50}},
        {{"Q220"}, arrow({80, 62}, {72, 70}), {82, 72}},
    };
    return d;
}

// Cycle 220: holes on a circle, centre (Q216, Q217), first hole at 30°, step 60°.
HelpDrawing polarPattern() {
    HelpDrawing d;
    const QPointF centre(55, 50);
    d.lines.addEllipse(centre, 30, 30);
    d.lines.moveTo(10, 92);
    d.lines.lineTo(10, 8);
    d.lines.moveTo(10, 92);
    d.lines.lineTo(95, 92);
    d.lines.addPath(dashes(centre, polar(centre, 38, 0)));
    for (double a = 30; a <= 210; a += 60)
        d.solid.addEllipse(polar(centre, 30, a), 3, 3);
    QPainterPath all;
    all.addRect(QRectF(centre.x() - 34, centre.y() - 34, 68, 68));
    d.dimensions = {
        {{"Q216"}, arrow({10, 96}, {55, 96}), {28, 94.5}},
        {{"Q217"}, arrow({15, 92}, {15, 50}), {2, 70}},
        {{"Q244"}, arrow(polar(centre, 30, 150), polar(centre, 30, -30)), {58, 58}},
        {{"Q245"}, angleArc(centre, 12, 0, 30), {68, 44}},
        {{"Q246"}, angleArc(centre, 18, 0, 210), {34, 66}},
        {{"Q247"}, angleArc(centre, 36, 30, 60), {74, 14}},
        {{"Q241"}, all, {20, 12}},
    };
    return d;
}

// Cycle 221: rows of holes from the start point (Q225, Q226), spacing Q237/Q238, rotated Q224.
HelpDrawing cartesianPattern() {
    HelpDrawing d;
    d.lines.moveTo(10, 92);
    d.lines.lineTo(10, 8);
    d.lines.moveTo(10, 92);
    d.lines.lineTo(95, 92);
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column)
            d.solid.addEllipse(QPointF(30 + 20 * column, 70 - 18 * row), 3, 3);
    }
    QPainterPath firstRow;
    firstRow.addRect(25, 65, 50, 10);
    QPainterPath firstColumn;
    firstColumn.addRect(25, 29, 10, 46);
    d.dimensions = {
        {{"Q225"}, arrow({10, 86}, {30, 86}), {14, 84}},
        {{"Q226"}, arrow({16, 92}, {16, 70}), {2, 80}},
        {{"Q237"}, arrow({30, 80}, {50, 80}), {36, 84}},
        {{"Q238"}, arrow({82, 70}, {82, 52}), {84, 62}},
        {{"Q242"}, firstRow, {60, 64}},
        {{"Q243"}, firstColumn, {36, 27}},
        {{"Q224"}, angleArc({30, 70}, 14, 0, 25), {45, 60}},
    };
    return d;
}

// Datum shift, rotation, scaling, mirroring, tilting and presetting: the original axes at the
// lower left and the transformed ones in the middle.
HelpDrawing transformation() {
    HelpDrawing d;
    const QPointF origin(15, 85);
    const QPointF moved(55, 50);
    d.lines.addPath(arrow(origin, {92, 85}, true));
    d.lines.addPath(arrow(origin, {15, 10}, true));
    d.lines.addPath(arrow(moved, polar(moved, 35, 30), true));
    d.lines.addPath(arrow(moved, polar(moved, 35, 120), true));
    d.solid.addEllipse(moved, 2, 2);
    QPainterPath small;
    small.addRect(62, 62, 12, 12);
    small.addRect(62, 62, 24, 24);
    d.dimensions = {
        {{"X"}, arrow({15, 92}, {55, 92}), {32, 98}},
        {{"Y"}, arrow({8, 85}, {8, 50}), {1, 64}},
        {{"Z"}, ring(moved, 5), {60, 46}},
        {{"ROT", "A", "B", "C"}, angleArc(moved, 20, 0, 30), {76, 40}},
        {{"SCL", "CCX", "CCY", "CCZ"}, small, {78, 94}},
        {{"X Y Z"}, dashes({55, 8}, {55, 96}), {57, 10}},
        {{"Q339"}, ring(origin, 4), {20, 80}},
    };
    return d;
}

// Engraving (225): text on a line from the start point, character height, rotation.
HelpDrawing engraving() {
    HelpDrawing d;
    d.lines.moveTo(10, 92);
    d.lines.lineTo(10, 8);
    d.lines.moveTo(10, 92);
    d.lines.lineTo(95, 92);
    // "KERF" in strokes: the letters themselves are the workpiece marks.
    QPainterPath text;
    const std::vector<std::vector<QPointF>> strokes = {
        {{25, 60}, {25, 40}},
        {{33, 40}, {25, 50}, {33, 60}},  // K
        {{45, 40}, {37, 40}, {37, 60}, {45, 60}},
        {{37, 50}, {43, 50}},                                          // E
        {{49, 60}, {49, 40}, {57, 40}, {57, 50}, {49, 50}, {57, 60}},  // R
        {{61, 60}, {61, 40}, {69, 40}},
        {{61, 50}, {67, 50}},  // F
    };
    for (const auto& stroke : strokes) {
        text.moveTo(stroke.front());
        for (size_t i = 1; i < stroke.size(); ++i)
            text.lineTo(stroke[i]);
    }
    d.lines.addPath(text);
    QPainterPath textBox;
    textBox.addRect(22, 37, 50, 26);
    d.dimensions = {
        {{"Q500"}, textBox, {30, 34}},
        {{"Q513"}, arrow({78, 60}, {78, 40}), {80, 50}},
        {{"Q225"}, arrow({10, 86}, {25, 86}), {13, 84}},
        {{"Q226"}, arrow({16, 92}, {16, 60}), {2, 76}},
        {{"Q374"}, angleArc({25, 60}, 50, 0, 12), {77, 70}},
        {{"Q514"}, arrow({33, 66}, {37, 66}), {30, 72}},
        {{"Q517"}, arrow({50, 92}, {50, 62}), {52, 80}},
    };
    return d;
}

// Dwell (9), PGM CALL (12), oriented spindle stop (13), tolerance (32).
HelpDrawing specialSymbols(int cycle) {
    HelpDrawing d;
    const QPointF centre(50, 50);
    switch (cycle) {
        case 9:
            d.lines.addEllipse(centre, 30, 30);
            d.dimensions = {{{"DWELL"}, angleArc(centre, 24, 90, -120), {62, 30}}};
            break;
        case 13:
            d.lines.addEllipse(centre, 30, 30);
            d.lines.addPath(dashes(centre, polar(centre, 40, 0)));
            d.solid.addEllipse(polar(centre, 30, 180), 4, 4);
            d.dimensions = {{{"ANGLE"}, angleArc(centre, 18, 0, 180), {44, 24}}};
            break;
        case 12: {
            d.lines.addRect(30, 15, 40, 70);
            QPainterPath name;
            name.addRect(34, 20, 32, 10);
            d.dimensions = {{{"PGM"}, name, {36, 40}}};
            break;
        }
        default: {
            // A contour with the tolerance band of cycle 32 around it.
            QPainterPath contour;
            contour.moveTo(10, 70);
            contour.cubicTo(30, 20, 60, 90, 90, 30);
            d.lines.addPath(contour);
            QPainterPath band = contour.translated(0, -5);
            band.addPath(contour.translated(0, 5));
            d.dimensions = {
                {{"T"}, band, {40, 30}},
                {{"HSC-MODE"}, arrow({60, 80}, {80, 80}, true), {58, 88}},
                {{"TA"}, angleArc({85, 80}, 8, 90, 60), {74, 70}},
            };
            break;
        }
    }
    return d;
}

}  // namespace

const HelpDimension* HelpDrawing::find(const QString& key) const {
    for (const HelpDimension& dimension : dimensions) {
        if (dimension.keys.contains(key)) return &dimension;
    }
    return nullptr;
}

HelpDrawing helpDrawing(const cycles::CycleDescriptor& cycle) {
    using cycles::CycleGroup;
    if (cycle.number == 232 || cycle.number == 233) return faceMilling();
    if (cycle.number == 225) return engraving();
    switch (cycle.group) {
        case CycleGroup::Drilling:
            return drillingSection(false);
        case CycleGroup::Tapping:
        case CycleGroup::ThreadMilling:
            return drillingSection(true);
        case CycleGroup::Pattern:
            return cycle.number == 220 ? polarPattern() : cartesianPattern();
        case CycleGroup::Transformation:
            return transformation();
        case CycleGroup::Special:
            return specialSymbols(cycle.number);
        case CycleGroup::PocketsStudsSlots:
            return pocketPlan();
        case CycleGroup::CylinderSurface:
            return contourSection();
        case CycleGroup::Contours:
            return cycle.number == 270 ? contourTrainApproach() : contourSection();
    }
    return drillingSection(false);
}

}  // namespace kerf::ui
