#pragma once

#include <vector>

#include "core/canon/commands.h"

namespace kerf::graphics::test {

// Builds canonical streams by hand for the graphics tests (one source line per command).
class CanonBuilder {
public:
    std::vector<canon::Command> commands;

    CanonBuilder& rapid(double x, double y, double z) {
        return add(canon::RapidMove{pose(x, y, z)});
    }
    CanonBuilder& line(double x, double y, double z, double feed = 100.0) {
        return add(canon::LinearMove{pose(x, y, z), feed});
    }
    CanonBuilder& arc(double x, double y, double z, double cx, double cy, double sweepRad,
                      Plane plane = Plane::XY) {
        canon::ArcMove move;
        move.target = pose(x, y, z);
        move.center = Vec3(cx, cy, 0.0);
        if (plane == Plane::ZX) move.center = Vec3(cy, 0.0, cx);  // (first, second) = (Z, X)
        move.plane = plane;
        move.sweepRad = sweepRad;
        move.feed = 100.0;
        return add(move);
    }
    CanonBuilder& tool(int number, double radius, double radius2 = 0.0) {
        canon::ToolChange change;
        change.number = number;
        change.geometry.radiusMm = radius;
        change.geometry.radius2Mm = radius2;
        return add(change);
    }
    CanonBuilder& box(const Vec3& min, const Vec3& max) {
        return add(canon::StockDefinition{canon::StockBox{min, max}});
    }
    template <typename T>
    CanonBuilder& add(T body) {
        canon::Command command;
        ++m_line;
        command.location.line = m_line;
        command.location.column = 1;
        command.location.blockNumber = m_line - 1;
        command.body = std::move(body);
        commands.push_back(std::move(command));
        return *this;
    }
    void feed(canon::Sink& sink) const {
        for (const auto& command : commands)
            sink.consume(command);
    }
    static Pose pose(double x, double y, double z) {
        Pose p;
        p[Axis::X] = x;
        p[Axis::Y] = y;
        p[Axis::Z] = z;
        return p;
    }

private:
    uint32_t m_line = 0;
};

}  // namespace kerf::graphics::test
