#include "ui/cycles/fagor_help_drawing.h"

#include <QPolygonF>

#include "ui/cycles/help_shapes.h"

namespace kerf::ui {

namespace {

// Everything is drawn over the spindle axis at y 88 and the part zero W at its left end.
constexpr double kAxis = 88;
constexpr double kZero = 8;

QPainterPath polygon(std::initializer_list<QPointF> points) {
    QPainterPath path;
    path.addPolygon(QPolygonF(QVector<QPointF>(points)));
    path.closeSubpath();
    return path;
}

QPainterPath polyline(std::initializer_list<QPointF> points) {
    QPainterPath path;
    path.addPolygon(QPolygonF(QVector<QPointF>(points)));
    return path;
}

void axisAndZero(HelpDrawing& d) {
    d.lines.addPath(dashes({2, kAxis}, {98, kAxis}));
    d.lines.addPath(ring({kZero, kAxis}, 1.5));
}

// A turning insert with its tip at `tip`, coming from the upper right.
QPainterPath insert(QPointF tip) {
    return polygon({tip, tip + QPointF(6, -3), tip + QPointF(2, -8)});
}

// The stepped shaft of the turning cycles as the passes meet it: the call point and the tool at
// the upper right, the start point (X, Z) at the right end of the low step, the profile rising
// away from the call point to the high step on the chuck side. The raw stock above it, the
// finishing allowance (dashed, 4 outside the profile) and two roughing passes that stop at it.
HelpDrawing turningProfile(bool curved, bool facing) {
    HelpDrawing d;
    d.solid = polygon({{kZero, kAxis}, {kZero, 38}, {52, 38}, {52, 55}, {88, 55}, {88, kAxis}});
    axisAndZero(d);
    d.lines.addPath(dashes({kZero, 20}, {88, 20}));
    d.lines.addPath(dashes({88, 20}, {88, 55}));
    d.lines.addPath(dashes({88, 51}, {56, 51}));
    d.lines.addPath(dashes({56, 51}, {56, 34}));
    d.lines.addPath(dashes({56, 34}, {kZero, 34}));
    d.lines.addPath(ring({88, 55}, 1.5));
    // G69, G82 and G85 face: their passes go down along X and step along Z.
    if (facing) {
        d.lines.addPath(polyline({{69, 14}, {69, 51}}));
        d.lines.addPath(polyline({{62, 14}, {62, 51}}));
    } else {
        d.lines.addPath(polyline({{93, 40}, {56, 40}}));
        d.lines.addPath(polyline({{93, 47}, {56, 47}}));
    }
    d.lines.addPath(insert({93, 16}));
    d.lines.addPath(ring({93, 16}, 1.5));
    d.dimensions = {
        {{"X"}, arrow({96, kAxis}, {96, 55}), {97, 72}},
        {{"Z"}, arrow({kZero, 8}, {88, 8}), {48, 6}},
        {{"L"}, arrow({76, 55}, {76, 51}), {73, 50}},
        {{"M"}, arrow({52, 49}, {56, 49}), {50, 47}},
    };
    if (facing) {
        d.dimensions.push_back({{"C"}, arrow({62, 17}, {69, 17}), {64, 15}});
        d.dimensions.push_back({{"D"}, arrow({62, 51}, {66, 47}, true), {66, 45}});
    } else {
        d.dimensions.push_back({{"C"}, arrow({84, 40}, {84, 47}), {85, 39}});
        d.dimensions.push_back({{"D"}, arrow({56, 40}, {60, 36}, true), {61, 35}});
    }
    d.dimensions.push_back({{"Q"}, arrow({56, kAxis}, {56, 55}), {57, 72}});
    d.dimensions.push_back({{"R"}, arrow({kZero, 62}, {52, 62}), {28, 61}});
    if (curved) {
        d.lines.addPath(ring({64, 72}, 1.5));
        d.dimensions.push_back({{"I"}, arrow({84, 55}, {84, 72}), {85, 66}});
        d.dimensions.push_back({{"K"}, arrow({84, 76}, {64, 76}), {72, 82}});
    }
    return d;
}

// G66 follows the profile: a forged or cast part whose raw outline is the profile I further out,
// every pass a copy of the profile C closer to it, down to the allowance L/M (no retract D: each
// pass returns to the call point).
HelpDrawing patternRepeatProfile() {
    HelpDrawing d;
    d.solid = polygon({{kZero, kAxis}, {kZero, 38}, {52, 38}, {52, 55}, {88, 55}, {88, kAxis}});
    axisAndZero(d);
    // Copies of the profile 16 (raw part), 12 and 8 (passes) and 4 (allowance) further out: the
    // shoulder moves towards the call point, the steps up.
    d.lines.addPath(dashes({88, 39}, {68, 39}));
    d.lines.addPath(dashes({68, 39}, {68, 22}));
    d.lines.addPath(dashes({68, 22}, {kZero, 22}));
    d.lines.addPath(dashes({88, 51}, {56, 51}));
    d.lines.addPath(dashes({56, 51}, {56, 34}));
    d.lines.addPath(dashes({56, 34}, {kZero, 34}));
    d.lines.addPath(ring({88, 55}, 1.5));
    d.lines.addPath(polyline({{93, 43}, {64, 43}, {64, 26}, {kZero, 26}}));
    d.lines.addPath(polyline({{93, 47}, {60, 47}, {60, 30}, {kZero, 30}}));
    d.lines.addPath(insert({93, 16}));
    d.lines.addPath(ring({93, 16}, 1.5));
    d.dimensions = {
        {{"X"}, arrow({96, kAxis}, {96, 55}), {97, 72}},
        {{"Z"}, arrow({kZero, 8}, {88, 8}), {48, 6}},
        {{"I"}, arrow({30, 22}, {30, 38}), {26, 20}},
        {{"C"}, arrow({84, 43}, {84, 47}), {85, 41}},
        {{"L"}, arrow({76, 55}, {76, 51}), {73, 50}},
        {{"M"}, arrow({52, 49}, {56, 49}), {50, 47}},
    };
    return d;
}

// Profile cycles G66, G68 and G69 name the profile by the labels of its first block (from the
// start point) and its last block (to the end on the high step).
void profileLabels(HelpDrawing& d) {
    d.dimensions.push_back({{"S"}, ring({66, 55}, 2.5), {64, 61}});
    d.dimensions.push_back({{"E"}, ring({26, 38}, 2.5), {24, 44}});
}

// A thread on the shaft from the start point (X, Z, right) to the end point (Q, R, left): depth
// I, the first pass B, pitch C, infeed angle A, the approach D above the start point and the
// run-out J.
HelpDrawing thread() {
    HelpDrawing d;
    d.solid = polygon({{kZero, kAxis}, {kZero, 40}, {88, 40}, {88, kAxis}});
    axisAndZero(d);
    for (double z = 24; z < 84; z += 10) {
        d.lines.moveTo(z, 40);
        d.lines.lineTo(z + 5, 50);
        d.lines.lineTo(z + 10, 40);
    }
    d.lines.addPath(insert({88, 34}));
    d.lines.addPath(ring({88, 40}, 1.5));
    d.lines.addPath(ring({24, 40}, 1.5));
    d.dimensions = {
        {{"X"}, arrow({96, kAxis}, {96, 40}), {97, 64}},
        {{"Z"}, arrow({kZero, 10}, {88, 10}), {50, 8}},
        {{"Q"}, arrow({16, kAxis}, {16, 40}), {17, 66}},
        {{"R"}, arrow({kZero, 16}, {24, 16}), {12, 14}},
        {{"I"}, arrow({49, 40}, {49, 50}), {42, 56}},
        {{"B"}, arrow({59, 40}, {59, 45}), {56, 56}},
        {{"C"}, arrow({34, 30}, {44, 30}), {37, 28}},
        {{"D"}, arrow({92, 40}, {92, 34}), {86, 30}},
        {{"J"}, arrow({24, 24}, {34, 24}), {27, 22}},
        {{"A"}, angleArc({69, 50}, 8, 90, -27), {72, 38}},
    };
    return d;
}

// A thread on the face from the start point (X, Z) at its outer edge down to the end point (Q,
// R): depth I and the first pass B along -Z, pitch C along X, the approach D in front of the
// face, the run-out J and the infeed angle A from Z.
HelpDrawing faceThread() {
    HelpDrawing d;
    d.solid = polygon({{kZero, kAxis}, {kZero, 30}, {88, 30}, {88, kAxis}});
    axisAndZero(d);
    for (double x = 30; x < 70; x += 10) {
        d.lines.moveTo(88, x);
        d.lines.lineTo(78, x + 5);
        d.lines.lineTo(88, x + 10);
    }
    const QPointF tip(94, 30);
    d.lines.addPath(polygon({tip, tip + QPointF(6, -3), tip + QPointF(6, 3)}));
    d.lines.addPath(ring({88, 30}, 1.5));
    d.lines.addPath(ring({88, 70}, 1.5));
    d.dimensions = {
        {{"X"}, arrow({4, kAxis}, {4, 30}), {1, 60}},
        {{"Z"}, arrow({kZero, 10}, {88, 10}), {50, 8}},
        {{"Q"}, arrow({60, kAxis}, {60, 70}), {61, 80}},
        {{"R"}, arrow({kZero, 18}, {88, 18}), {30, 16}},
        {{"I"}, arrow({78, 45}, {88, 45}), {71, 44}},
        {{"B"}, arrow({83, 55}, {88, 55}), {77, 58}},
        {{"C"}, arrow({94, 40}, {94, 50}), {95, 46}},
        {{"D"}, arrow({88, 26}, {94, 26}), {90, 23}},
        {{"J"}, arrow({92, 70}, {92, 60}), {94, 66}},
        {{"A"}, angleArc({78, 65}, 8, 0, 27), {87, 62}},
    };
    return d;
}

// A groove from the start point (X, Z) to the bottom (Q) and the far wall (R), cut by
// plunges at most C apart.
HelpDrawing groove() {
    HelpDrawing d;
    d.solid = polygon({{kZero, kAxis},
                       {kZero, 35},
                       {40, 35},
                       {40, 60},
                       {65, 60},
                       {65, 35},
                       {88, 35},
                       {88, kAxis}});
    axisAndZero(d);
    d.lines.addRect(40, 12, 8, 20);  // the grooving blade over the start point
    d.lines.addPath(ring({40, 35}, 1.5));
    d.dimensions = {
        {{"X"}, arrow({94, kAxis}, {94, 35}), {95, 60}},
        {{"Z"}, arrow({kZero, 8}, {40, 8}), {22, 6}},
        {{"Q"}, arrow({52, kAxis}, {52, 60}), {53, 76}},
        {{"R"}, arrow({kZero, 4}, {65, 4}), {50, 3}},
        {{"C"}, arrow({42, 56}, {50, 56}), {43, 54}},
        {{"D"}, arrow({36, 35}, {36, 29}), {30, 30}},
        {{"K"}, ring({42, 60}, 2.5), {44, 66}},
    };
    return d;
}

// A hole drilled toward -Z from the start point at the face: depth I, peck B, the approach D,
// the rapid return C before each peck and the retract H.
HelpDrawing hole() {
    HelpDrawing d;
    constexpr double axis = 50;
    d.solid = polygon(
        {{kZero, 20}, {60, 20}, {60, 44}, {30, 44}, {30, 56}, {60, 56}, {60, 80}, {kZero, 80}});
    d.lines.addPath(dashes({2, axis}, {98, axis}));
    d.lines.addPath(polygon({{68, 46}, {95, 46}, {95, 54}, {68, 54}, {64, axis}}));
    d.lines.addPath(dashes({44, 44}, {44, 56}));
    d.dimensions = {
        {{"X", "Z"}, ring({60, axis}, 2), {62, 60}},
        {{"I"}, arrow({60, 88}, {30, 88}), {44, 94}},
        {{"B"}, arrow({60, 40}, {44, 40}), {50, 38}},
        {{"D"}, arrow({60, 28}, {68, 28}), {62, 26}},
        {{"C"}, arrow({48, 62}, {44, 62}), {44, 68}},
        {{"H"}, arrow({44, 34}, {52, 34}, true), {40, 33}},
        {{"K"}, ring({30, axis}, 2.5), {22, 60}},
    };
    return d;
}

}  // namespace

HelpDrawing fagorHelpDrawing(int g) {
    switch (g) {
        case 66: {
            HelpDrawing d = patternRepeatProfile();
            profileLabels(d);
            return d;
        }
        case 68:
        case 69: {
            HelpDrawing d = turningProfile(false, g == 69);
            std::erase_if(d.dimensions, [](const HelpDimension& dim) {
                return dim.keys.contains("Q") || dim.keys.contains("R");
            });
            profileLabels(d);
            return d;
        }
        case 81:
        case 82:
            return turningProfile(false, g == 82);
        case 84:
        case 85:
            return turningProfile(true, g == 85);
        case 83:
            return hole();
        case 86:
            return thread();
        case 87:
            return faceThread();
        case 88:
        case 89:
            return groove();
        default:
            return {};
    }
}

}  // namespace kerf::ui
