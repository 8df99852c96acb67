#pragma once

#include <QString>
#include <QStringList>
#include <optional>
#include <vector>

namespace kerf::ui {

// The Klartext path functions and TOOL CALL the programming softkeys write through a dialog.
enum class PathFunction {
    Line,
    CircleCentre,
    Circle,
    CircleRadius,
    CircleTangential,
    Rounding,
    Chamfer,
    ToolCall
};

enum class PathFieldKind {
    Coordinate,    // X+10, IX-5, X+Q3 (an I before the value: incremental)
    Radius,        // signed arc radius of CR
    Length,        // positive length (RND R, CHF)
    Direction,     // DR+ / DR-
    Compensation,  // R0 / RL / RR or none
    Feed,          // F100, FMAX, FAUTO
    Misc,          // M functions: "3 8" or "M3 M8"
    Tool,          // tool number or name
    ToolAxis,      // Z, X, Y
    Speed,         // S
    Oversize,      // DL, DR of TOOL CALL
};

struct PathField {
    QString word;  // "X", "R", "DR", "F", "M", "S", "DL" ...
    PathFieldKind kind;
    bool required = false;
    QStringList choices;  // Direction, Compensation, ToolAxis: what the combo box offers
};

// The block's first word ("L", "CC", "C", "CR", "CT", "RND", "CHF", "TOOL CALL").
QString pathFunctionKeyword(PathFunction function);
std::vector<PathField> pathFields(PathFunction function);
// The meaning of a field in the UI language ("Radius compensation", ...).
QString pathFieldDescription(const PathField& field);

// Checks one entry; the message is in the UI language.
std::optional<QString> checkPathField(const PathField& field, const QString& text);
// Checks all entries, including the rules across fields (an L or CC needs a coordinate).
std::optional<QString> checkPathFunction(PathFunction function, const QStringList& values);
// The block without its number, e.g. "L X+10 Y+5 RL F200 M3"; values must have passed the
// checks.
QString writePathFunction(PathFunction function, const QStringList& values);

}  // namespace kerf::ui
