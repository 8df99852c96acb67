#pragma once

#include <optional>
#include <vector>

#include "core/canon/commands.h"
#include "core/interp/path/offset_junction.h"
#include "core/interp/path/path_move.h"
#include "core/interp/path/path_space.h"

namespace kerf::interp {

// Turns programmed moves into tool-centre moves on the canonical stream. Two look-ahead stages of
// one element each: the first applies roundings and chamfers to the programmed contour, the second
// applies tool-radius compensation with the TNC/Fagor rules:
//   - the block that switches compensation on ends perpendicular to the next element; the last
//     compensated element ends perpendicular to itself before R0/G40 or a departure;
//   - outside corners get a transition arc around the corner point with the tool radius;
//   - inside corners end at the intersection of the offset elements, and an element that the
//     offset swallows is the "tool radius too large" error;
//   - moves along the tool axis only keep the compensation and wait for the next contour element.
// With look-ahead (TNC M120 LA n) the second stage holds up to n more elements: an element whose
// offset would cut into the contour (the "tool radius too large" cases) is left out, and the
// offsets before and after it are joined, up to n such elements in a row.
// Non-motion commands keep their place in the stream.
class PathBuilder {
public:
    explicit PathBuilder(canon::Sink& sink) : m_sink(sink) {}

    // Where the tool is at the start (no look-ahead pending), in the space's coordinates; and
    // the same given on the machine's axes.
    void reset(const Pose& toolPosition);
    void resetToMachine(const Pose& machine) {
        reset(m_space ? m_space->toPath(machine) : machine);
    }
    // A straight move of the machine's axes, past the space (retractions, positioning of the
    // rotary axes), with nothing pending.
    void addMachineLine(const Pose& target, bool rapid, double feed,
                        const SourceLocation& location);
    // Effective tool radius used by compensation (R + DR); set it with nothing pending.
    void setToolRadius(double radius) { m_radius = radius; }
    // M120 LA n: how many compensated elements are calculated in advance (0: none). Resolves the
    // elements held for the previous count. Compensation switched off ends the look-ahead.
    std::optional<PathError> setLookAhead(int blocks);
    int lookAhead() const { return m_lookAhead; }
    // Work in `space` (nullptr: the machine's axes), set with nothing pending: moves, approaches
    // and reset() are then in its coordinates and every line and arc leaves as straight pieces
    // of the axes within `toleranceMm` (path_space.h). The space must outlive its use.
    void setSpace(const PathSpace* space, double toleranceMm);
    const PathSpace* space() const { return m_space; }
    // An element the space could not split within the tolerance, once.
    std::optional<PathError> takeSpaceError();

    std::optional<PathError> addMove(const PathMove& move);
    std::optional<PathError> addRounding(double radius, std::optional<double> feed,
                                         const SourceLocation& location);
    std::optional<PathError> addChamfer(double length, std::optional<double> feed,
                                        const SourceLocation& location);
    std::optional<PathError> addApproach(const ApproachSpec& spec);
    // Departs from the compensated contour; compensation is off afterwards.
    std::optional<PathError> addDeparture(const ApproachSpec& spec);
    void addCommand(canon::Command command);
    // Resolves everything pending (program end, synchronisation, tool change).
    std::optional<PathError> flush();

    // The tool-centre position after every move emitted so far (in the space's coordinates).
    const Pose& toolPosition() const { return m_tool; }
    // The same on the machine's axes.
    Pose machinePosition() const { return m_space ? m_space->toMachine(m_tool) : m_tool; }
    CompSide activeSide() const { return m_side; }
    bool pending() const { return m_held.has_value() || m_comp.has_value(); }

private:
    struct Corner {
        bool chamfer = false;
        double size = 0.0;
        std::optional<double> feed;
        SourceLocation location;
    };
    struct Compensated {
        PathMove move;        // as programmed
        ContourElement tool;  // tool-centre path; its end is provisional until resolved
        bool activation = false;
    };
    struct Queued {
        std::optional<canon::Command> command;
        std::optional<PathMove> axialMove;
    };
    // Contour elements left out in a row by the look-ahead.
    struct LeftOut {
        int count = 0;
        SourceLocation first;
    };
    // A compensated element held for look-ahead, with what came between it and the one before.
    struct Ahead {
        PathMove move;
        std::vector<Queued> before;
        LeftOut leftOut;  // the elements left out just before it
    };

    // A held straight move without compensation, with nothing pending in either stage: stage 2
    // would emit it as it is.
    bool passesStraightOn(const PathMove& held) const;
    // Stage 1 (corners) hands its output to stage 2 through these.
    std::optional<PathError> forwardHeld();
    std::optional<PathError> compMove(const PathMove& move);
    void compCommand(canon::Command command);
    std::optional<PathError> compResolveApproach(const PathMove& move);
    std::optional<PathError> compFinishHeld();
    std::optional<PathError> compCorner(const PathMove& move);
    void compFlushQueue();
    void emitQueued(std::vector<Queued>& queue);
    void commitJunction(const OffsetJunction& junction, const PathMove& next,
                        std::vector<Queued>& between);
    std::optional<PathError> aheadAdd(const PathMove& move);
    std::optional<size_t> aheadFindUndercut() const;
    std::optional<PathError> aheadLeaveOut(size_t index);
    std::optional<PathError> aheadCommit();
    std::optional<PathError> aheadDrain();

    double signedOffset(CompSide side) const;
    void emitElement(const ContourElement& element, const PathMove& move);
    // One straight move of the machine's axes on the stream; the tool position is the caller's.
    void emitStraight(const Pose& target, bool rapid, double feed, const SourceLocation& location);
    void emitLine(const Pose& target, bool rapid, double feed, const SourceLocation& location);
    void emitArc(Plane plane, const Pose& target, const Vec2& center, double sweep, double feed,
                 const SourceLocation& location);
    // Through the space: `element` starts at the tool.
    void emitInSpace(const ContourElement& element, bool rapid, double feed,
                     const SourceLocation& location);

    canon::Sink& m_sink;
    double m_radius = 0.0;
    const PathSpace* m_space = nullptr;
    double m_spaceToleranceMm = 0.0;
    std::optional<PathError> m_spaceError;
    std::vector<MachinePiece> m_pieces;  // reused
    Pose m_tool{};
    // Stage 1.
    std::optional<PathMove> m_held;
    std::optional<Corner> m_corner;
    std::vector<canon::Command> m_heldAfter;
    // Stage 2.
    std::optional<Compensated> m_comp;
    std::vector<Queued> m_compAfter;
    std::optional<ApproachSpec> m_approach;
    CompSide m_side = CompSide::None;
    // Look-ahead (M120): the elements after m_comp.
    int m_lookAhead = 0;
    std::vector<Ahead> m_ahead;
    LeftOut m_leftOutAtEnd;  // left out after the last element of m_ahead
};

}  // namespace kerf::interp
