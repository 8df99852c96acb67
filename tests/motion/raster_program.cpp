#include "tests/motion/raster_program.h"

#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf::motion::test {

namespace {

constexpr int kRowMoves = 99;
constexpr double kStep = 0.5;
constexpr int kBand = 100;

Pose pose(double x, double y, double z) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

}  // namespace

double rasterZ(double x, double y) {
    return -1.0 + 0.5 * std::sin(x / 7.0) * std::cos(y / 11.0);
}

Pose rasterStart() {
    return pose(0.0, 0.0, rasterZ(0.0, 0.0));
}

void emitRaster(const RasterOptions& options, canon::Sink& sink) {
    uint32_t line = 1;
    auto send = [&](canon::CommandBody body) {
        canon::Command command;
        command.location.line = line++;
        command.body = std::move(body);
        sink.consume(command);
    };
    if (options.leadIn) {
        send(canon::RapidMove{pose(0.0, 0.0, 5.0)});
        send(canon::RapidMove{pose(0.0, 0.0, 5.0)});
        send(canon::LinearMove{rasterStart(), options.feedMmPerMin});
    }
    double x = 0.0;
    double y = 0.0;
    int n = 0;
    for (int row = 0; n < options.blocks; ++row) {
        int xdir = row % 2 == 0 ? 1 : -1;
        int ydir = (row / kBand) % 2 == 0 ? 1 : -1;
        for (int i = 0; i < kRowMoves && n < options.blocks; ++i, ++n) {
            x = xdir > 0 ? (i + 1) * options.segMm : (kRowMoves - 1 - i) * options.segMm;
            send(canon::LinearMove{pose(x, y, rasterZ(x, y)), options.feedMmPerMin});
        }
        if (n >= options.blocks) break;
        int k = (row + 1) % (2 * kBand);
        double y2 = (k <= kBand ? k : 2 * kBand - k) * kStep;
        bool ccw = xdir * ydir > 0;
        canon::ArcMove arc;
        arc.target = pose(x, y2, rasterZ(x, y));
        arc.center = Vec3(x, y + kStep / 2.0 * ydir, 0.0);
        arc.plane = Plane::XY;
        arc.sweepRad = ccw ? kPi : -kPi;
        arc.feed = options.feedMmPerMin;
        send(arc);
        y = y2;
        ++n;
    }
    if (options.leadIn) send(canon::ProgramStop{canon::StopKind::End, 2});
}

}  // namespace kerf::motion::test
