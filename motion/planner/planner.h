#pragma once

#include <algorithm>
#include <deque>
#include <optional>
#include <vector>

#include "core/base/diagnostic.h"
#include "core/canon/commands.h"
#include "motion/kinematics/machine_model.h"
#include "motion/planner/lookahead.h"
#include "motion/planner/polyline_smoother.h"
#include "motion/planner/share_ladder.h"
#include "motion/port/motion_item.h"

// The motion planner: turns the canonical command stream into path elements and actions for the
// servo cycle. It blends corners within the path tolerance (TNC cycle 32 T, Fagor G51 E; machine
// default otherwise), keeps tangent joins at speed, stops exactly where the program or the machine
// needs it (stops, tool change, sync points, dwell, spindle and M functions, probing, reversals,
// spindle-synchronised moves), checks soft limits before it accepts a move, and holds back only
// as much path as the braking distance needs. Planner (task) thread only.
namespace kerf::motion {

struct CornerBlend;

// No slow point: the motion may keep its velocity there.
inline constexpr double kNoSlowPoint = 1e300;

// What a planner is for. Every refusal (soft limits, a missing axis, no feed, an arc whose end is
// off its circle, ...) is decided in add() on the programmed move itself, before any smoothing,
// corner blending or look-ahead; so a planner that only judges (WorkAreaCheck) skips those and
// refuses exactly what a planning one refuses, at the same block, with the same message.
enum class PlannerRole { Plan, JudgeOnly };

class Planner {
public:
    explicit Planner(const MachineModel& model, PlannerRole role = PlannerRole::Plan);

    // Where the tool tip is (workpiece coordinates) before the next move: at start, after a probe
    // move or after an abort.
    void setPosition(const AxisVector& tip);
    const AxisVector& position() const { return m_position; }

    // Forgets everything planned and not yet taken (after a quick stop or an emergency stop);
    // the next move starts at `tip`.
    void reset(const AxisVector& tip);
    // The spindle as manual operation set it, outside the stream.
    void setSpindle(canon::SpindleDirection direction, double rpm);

    // Adds one command. False when it is refused (diagnostics() says why, naming the block);
    // after a refusal every further command is ignored.
    bool add(const canon::Command& command);
    // The stream pauses here (end, sync point, drain): the motion stops after what was added.
    void flush();
    // Next planned item, or nothing until more of the stream is known (always nothing when the
    // planner only judges).
    std::optional<MotionItem> next();

    bool refused() const { return m_refused; }
    // True after a probe move: the next move starts where the probe stopped (setPosition).
    bool needsPosition() const { return m_needsPosition; }
    const DiagnosticList& diagnostics() const { return m_diagnostics; }
    double toolLength() const { return m_toolLength; }
    // Path length held back in the look-ahead window.
    double pendingLength() const;

    // Programmed moves accepted so far, and the geometry of the last one (unblended): for
    // measuring the path deviation of the executed motion.
    uint32_t acceptedMoves() const { return m_moveCount; }
    const PathGeometry& lastMoveGeometry() const { return m_lastMoveGeometry; }

    // Exact stop after every block (Fagor G07). Not in the canonical stream yet: set by the task.
    void setExactStopMode(bool on) { m_exactStop = on; }
    // Single block stops at each block's programmed end point: the moves planned while it is on
    // are neither blended nor fitted into curves across their ends.
    void setSingleBlock(bool on) { m_singleBlock = on; }

private:
    struct Move {
        PathGeometry geometry;
        double trimStart = 0.0;
        FeedKind feedKind = FeedKind::PerMinute;
        double feed = 0.0;
        bool feedMove = false;
        bool probe = false;
        bool blendable = false;
        double spindleDegPerUnit = 0.0;
        double tolerance = 0.0;
        uint32_t index = 0;
        SourceLocation source;
        bool endsBlock = true;      // the programmed block ends where this move ends
        uint32_t joinedGroup = 0;   // PathElement::joinedGroup
        bool tangentJoin = false;   // starts with the end tangent of the move before (smoothing)
        double fitDeviation = 0.0;  // of a fitted curve from the programmed polyline
        uint32_t firstIndex = 0;    // of a fitted curve: the first programmed move it replaces
        // How far a corner blend may reach into the move at its start and end (0: half of it).
        // A fitted curve lets the blends at its ends reach as far as the programmed segments
        // there would: a longer blend turns more gently, but at the tangential share of a curve.
        double reachStart = 0.0;
        double reachEnd = 0.0;
        double blendReachStart() const { return reach(reachStart); }
        double blendReachEnd() const { return reach(reachEnd); }
        double reach(double limit) const {
            return limit > 0.0 ? std::min(limit, geometry.length / 2.0) : geometry.length / 2.0;
        }
    };

    void addMove(Move move, const AxisVector& target, const SourceLocation& source);
    // Corners, held short lines and blends for the next move of the path.
    void pushMove(Move move);
    // Runs of short lines smoothed within the tolerance (PolylineSmoother).
    bool smoothable(const Move& move) const;
    bool continuesRun(const Move& move) const;
    void releaseRun(bool final);
    void endRun();
    bool acceptGeometry(const PathGeometry& geometry, const SourceLocation& source);
    // `exitVelocity`: the highest velocity at the end of the pending move (0: it stops there).
    void emitPending(double trimEnd, double exitVelocity = kNoSlowPoint);
    void cornerTo(Move& move);
    // Ends the pending move where the blend starts and emits the blend.
    void emitBlend(const Move& corner, const CornerBlend& blend, double contourBudget);
    // The highest velocity on a corner blend (at the lowest tangential share).
    double blendVelocity(const CornerBlend& blend, double contourBudget) const;
    // A short line whose corner with the pending move would need more than half of it is held
    // back, so that the next move can blend across it (blendAcrossShort) instead of turning twice
    // within its length; otherwise settleShort turns its corners as usual.
    bool worthHolding(const Move& move) const;
    bool blendAcrossShort(Move& move);
    void settleShort();
    // A curve near a stop, or near a corner whose blend is slower than the curve's first share
    // stage, is cut where the tangential share may change (shareLadder).
    void emitElement(const Move& move, const PathGeometry& geometry, double contourBudget,
                     bool blockEnd, double exitVelocity = kNoSlowPoint);
    void pushElement(const Move& move, const PathGeometry& geometry, double contourBudget,
                     bool blockEnd, const ShareStage* stage);
    // Ends any run being smoothed, then stops after the pending move.
    void exactStop();
    void stopAfterPending();
    void emitAction(const Action& action, const SourceLocation& source);
    void endSynchronisation(const SourceLocation& source);
    void refuse(Diagnostic diagnostic);
    std::optional<Move> feedMove(const AxisVector& target, double feed,
                                 const SourceLocation& source);

    const MachineModel& m_model;
    PlannerRole m_role;
    Lookahead m_lookahead;
    AxisVector m_position{};
    double m_pathS = 0.0;
    double m_sinceStop = 0.0;  // path length since the motion last stopped
    // Path length since the last corner blend and the highest velocity on that blend.
    double m_sinceBlend = 0.0;
    double m_blendVelocity = kNoSlowPoint;
    uint64_t m_sequence = 0;
    std::optional<Move> m_pending;
    std::optional<Move> m_short;  // held between m_pending and the next move
    PolylineSmoother m_smoother;
    std::deque<Move> m_run;  // the segments of the run being smoothed not yet released
    size_t m_runFirst = 1;   // the smoother's segment number of m_run.front()
    std::vector<SmoothPiece> m_pieces;
    double m_tolerance = 0.0;
    uint32_t m_joinedGroup = 0;   // the group of the blocks a ControlLocks joins now, 0: none
    uint32_t m_joinedGroups = 0;  // groups numbered so far
    double m_toolLength = 0.0;
    canon::FeedMode m_feedMode = canon::FeedMode::PerMinute;
    canon::SpindleDirection m_spindleDirection = canon::SpindleDirection::Stopped;
    double m_spindleRpm = 0.0;
    bool m_synchronised = false;
    Vec3Array m_syncDirection{};
    double m_syncSign = 1.0;
    bool m_exactStop = false;
    bool m_singleBlock = false;
    bool exactStops() const { return m_exactStop || m_singleBlock; }
    uint32_t m_moveCount = 0;
    PathGeometry m_lastMoveGeometry;
    bool m_refused = false;
    bool m_needsPosition = false;
    DiagnosticList m_diagnostics;
};

}  // namespace kerf::motion
