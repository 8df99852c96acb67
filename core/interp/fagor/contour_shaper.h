#pragma once

#include <optional>
#include <vector>

#include "core/interp/fagor/nose_compensation.h"

namespace kerf::fagor {

// The programmed contour's corner functions (spec part 1 §9.7-9.10), applied before compensation:
// G36 rounds and G39 chamfers the corner at the end of their block with the next element; G37
// replaces the approach line by a line and an arc that enters the next element tangentially; G38
// leaves the last element along an arc and turns the following line into a tangent to it. A move
// with such a request waits for the next move; everything else passes straight through.
class ContourShaper {
public:
    explicit ContourShaper(NoseCompensation& next) : m_next(next) {}

    void reset() {
        m_held.reset();
        m_after.clear();
    }
    std::optional<interp::PathError> add(const Move& move);
    void addCommand(canon::Command command);
    // The end of the contour (preparation stop, program end): a request still waiting is an error.
    std::optional<interp::PathError> flush();
    bool pending() const { return m_held.has_value(); }

private:
    std::optional<interp::PathError> resolve(Move first, Move next);
    std::optional<interp::PathError> forward(const Move& move);

    NoseCompensation& m_next;
    std::optional<Move> m_held;
    std::vector<canon::Command> m_after;
};

}  // namespace kerf::fagor
