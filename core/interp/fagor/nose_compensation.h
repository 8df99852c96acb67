#pragma once

#include <deque>
#include <optional>
#include <vector>

#include "core/canon/commands.h"
#include "core/interp/fagor/path_item.h"

namespace kerf::fagor {

// Tool nose radius compensation of a lathe (spec part 1 §11) on the programmed contour, emitting
// the path of the theoretical tip: nose-centre path offset by the radius on the G41/G42 side, plus
// radius x tip direction of the location code. Rules (docs/fagor.md, "Nose radius compensation"):
//   - start with plane motion: the G41/G42 line runs from the uncompensated point to the point
//     where its own offset meets the next element's offset (joined as a corner); start without
//     plane motion, an arc or a restart: first perpendicular to the next element's start;
//   - joins: inside corners at the intersection of the offsets; outside corners by COMPMODE:
//     0 straight sections up to 300 degrees between paths, else an arc; 1 always an arc;
//     2 the intersection of the offsets up to 300 degrees, else an arc;
//   - G40 line: its start is the join with the previous element as if it were compensated;
//   - G01/G02/G03/G33/G34 -> G00: the feed element ends perpendicular and the rapid move is not
//     compensated; G00 -> feed restarts compensation. A preparation stop (G04, G53, variables that
//     read the machine) does the same;
//   - G41 <-> G42 without G40: each element on its own side, switching at the intersection of the
//     offsets or with an extra segment between the perpendiculars;
//   - G41 N / G42 N (N 3-50): loops within the last N blocks are cut out, one warning each.
class NoseCompensation {
public:
    explicit NoseCompensation(canon::Sink& out) : m_out(out) {}

    // Where the tip is, nothing pending.
    void reset(const Pose& position);
    // Nose radius and tip direction (in the plane: abscissa = Z component, ordinate = X).
    void setTool(double radius, const Vec2& tipInPlane);
    void setCompMode(int mode) { m_compMode = mode; }

    std::optional<interp::PathError> add(const Move& move);
    void addCommand(canon::Command command);
    // Ends compensated paths perpendicular to their last element; the next compensated move
    // starts compensation again.
    std::optional<interp::PathError> suspend();

    const Pose& position() const { return m_position; }
    bool compensating() const { return m_held.has_value(); }
    // Blocks whose loops collision detection removed since the last call.
    std::vector<SourceLocation> takeRemovedLoops();

private:
    struct Held {
        Move move;
        ContourElement path;  // tool-centre path; an activation starts at the uncompensated point
        bool activation = false;
    };
    struct Join {
        ContourElement held;
        std::vector<ContourElement> transition;
        ContourElement next;
    };
    struct Piece {
        std::optional<canon::Command> command;
        ContourElement path;  // tip path
        MoveKind kind = MoveKind::Feed;
        double feed = 0.0;
        ThreadData thread;
        SourceLocation location;
        uint64_t block = 0;
    };
    enum class Start : uint8_t { Activation, AtPoint };

    double offsetFor(interp::CompSide side) const;
    std::optional<interp::PathError> join(const Held& held, const ContourElement& next,
                                          const ContourElement& nextPath, double offset,
                                          const SourceLocation& at, Join& out) const;
    std::optional<interp::PathError> corner(const Move& move);
    std::optional<interp::PathError> changeSide(const Move& move);
    std::optional<interp::PathError> deactivate(const Move& move);
    void startCompensation(const Move& move);
    void finishHeldPerpendicular();
    void emitHeld(const ContourElement& path);
    void flushQueue();
    // Emits a tool-centre element as the tip path: the tip offset moves its end (and centre).
    void emit(const ContourElement& centrePath, MoveKind kind, double feed,
              const ThreadData& thread, const SourceLocation& at);
    void emitPlain(const Move& move, const Pose& target);
    void push(Piece piece);
    void removeLoops(Piece& piece);
    void output(const Piece& piece);
    void drainWindow(size_t keepBlocks);

    canon::Sink& m_out;
    double m_radius = 0.0;
    Vec2 m_tip{0.0, 0.0};
    int m_compMode = 0;
    Pose m_position{};  // last emitted tip position
    std::optional<Held> m_held;
    struct Queued {
        std::optional<canon::Command> command;
        std::optional<Move> axial;  // a move without plane motion
    };
    std::vector<Queued> m_queue;  // what waits behind the held element
    int m_blocksWithoutMotion = 0;
    std::optional<Start> m_start;
    interp::CompSide m_side = interp::CompSide::None;
    int m_window = 0;
    std::deque<Piece> m_pieces;
    uint64_t m_block = 0;
    std::vector<SourceLocation> m_removedLoops;
};

}  // namespace kerf::fagor
