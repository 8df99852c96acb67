#pragma once

#include <array>

#include "core/canon/commands.h"

namespace kerf::canon {

// Sums up a canonical stream for reports and the test-run display: move counts and true geometric
// path lengths, the bounding box of the feed path (start points and arc extremes included) and
// tool changes. The machining time comes from motion (task::MachiningClock).
class PathStatistics final : public Sink {
public:
    struct Bounds {
        std::array<double, kAxisCount> min{};
        std::array<double, kAxisCount> max{};
        bool empty = true;
    };

    // Position before the first command (the tool's position when the program starts).
    void setStart(const Pose& start) {
        m_position = start;
        m_positionCounted = false;
    }
    void consume(const Command& command) override;

    int rapidCount() const { return m_rapidCount; }
    double rapidLengthMm() const { return m_rapidLength; }
    int feedCount() const { return m_feedCount; }
    double feedLengthMm() const { return m_feedLength; }
    const Bounds& feedBounds() const { return m_feedBounds; }
    const Pose& position() const { return m_position; }
    int toolChanges() const { return m_toolChanges; }

private:
    void addFeedPoint(const Pose& pose);
    // A feed move from m_position to `target`; the start is skipped when the last feed move
    // ended there (it is in the bounds already).
    void addFeedMove(const Pose& target);
    Pose m_position{};
    bool m_positionCounted = false;
    int m_rapidCount = 0;
    int m_feedCount = 0;
    double m_rapidLength = 0.0;
    double m_feedLength = 0.0;
    Bounds m_feedBounds{};
    int m_toolChanges = 0;
};

// True length of a helical or circular move starting at `start`.
double arcLengthMm(const Pose& start, const ArcMove& arc);

}  // namespace kerf::canon
