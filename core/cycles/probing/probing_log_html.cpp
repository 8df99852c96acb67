#include "core/cycles/probing/probing_log_html.h"

#include <cstdio>

namespace kerf::cycles::probing {

namespace {

std::string fixed(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4f", value);
    return text;
}

// Names come from the program and the tables: nothing in them may become markup.
std::string escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '&':
                out += "&amp;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string row(std::initializer_list<std::string> cells, const char* tag = "td") {
    std::string out = "<tr>";
    for (const std::string& cell : cells)
        out += std::string("<") + tag + ">" + cell + "</" + tag + ">";
    return out + "</tr>\n";
}

std::string page(const std::string& title, const std::string& body) {
    return "<!DOCTYPE html>\n<html>\n<head><meta charset=\"utf-8\"><title>" + title +
           "</title></head>\n<body>\n<h1>" + title + "</h1>\n" + body + "</body>\n</html>\n";
}

const char* functionName(ManualProbingFunction function) {
    switch (function) {
        case ManualProbingFunction::Rotation:
            return "PROBING ROT";
        case ManualProbingFunction::Position:
            return "PROBING POS";
        case ManualProbingFunction::Corner:
            return "PROBING P";
        case ManualProbingFunction::Circle:
            return "PROBING CC";
        case ManualProbingFunction::Plane:
            return "PROBING PL";
    }
    return "";
}

std::string point(const Vec3& p) {
    return "X " + fixed(p.x()) + "  Y " + fixed(p.y()) + "  Z " + fixed(p.z());
}

}  // namespace

std::string calibrationLogHtml(const std::string& program,
                               std::span<const CalibrationLogEntry> entries) {
    std::string body = "<p>Program: " + escaped(program) + "</p>\n";
    for (const CalibrationLogEntry& entry : entries) {
        body += "<h2>Cycle " + std::to_string(entry.cycle) + " " + escaped(entry.cycleName) +
                "</h2>\n<p>Tool " + std::to_string(entry.tool) + ", touch probe " +
                std::to_string(entry.probe) + "</p>\n<table>\n";
        body += row({"", "before", "after"}, "th");
        for (const CalibratedValue& value : entry.values)
            body += row({value.name, fixed(value.before), fixed(value.after)});
        body += "</table>\n";
    }
    return page("Touch probe calibration log", body);
}

std::string manualProbingLogHtml(ManualProbingFunction function,
                                 std::span<const ManualTouch> touches, double ballRadius,
                                 const std::optional<ManualProbingResult>& result) {
    std::string body = std::string("<h2>") + functionName(function) + "</h2>\n<p>Ball radius " +
                       fixed(ballRadius) + "</p>\n<table>\n";
    body += row({"Touch", "Direction", "Surface point"}, "th");
    for (size_t i = 0; i < touches.size(); ++i) {
        const ManualTouch& touch = touches[i];
        body += row({std::to_string(i + 1), point(touch.direction),
                     point(touch.ball + ballRadius * touch.direction)});
    }
    body += "</table>\n<table>\n";
    if (!result) {
        body += row({"Result", "none: the touches give no result"});
    } else {
        static constexpr const char* kAxes[] = {"X", "Y", "Z"};
        for (size_t i = 0; i < 3; ++i)
            if (result->point[i]) body += row({kAxes[i], fixed(*result->point[i])});
        if (result->basicRotationDeg)
            body += row({"Basic rotation", fixed(*result->basicRotationDeg)});
        if (result->diameter) body += row({"Diameter", fixed(*result->diameter)});
        if (result->planeADeg) body += row({"A", fixed(*result->planeADeg)});
        if (result->planeBDeg) body += row({"B", fixed(*result->planeBDeg)});
    }
    body += "</table>\n";
    return page("Manual probing log", body);
}

}  // namespace kerf::cycles::probing
