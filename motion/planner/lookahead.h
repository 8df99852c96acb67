#pragma once

#include <deque>
#include <vector>

#include "motion/kinematics/machine_model.h"
#include "motion/planner/curvature_step_window.h"
#include "motion/planner/velocity_limits.h"
#include "motion/port/motion_item.h"

// The look-ahead window: planned items wait here until their velocity limits and their next
// binding point (the next point ahead that the servo cycle must meet with a = 0, see
// PathElement) can no longer change, i.e. until the path known beyond them is longer than the
// braking distance. Planner thread.
//
// Binding points: going backwards from the end of the window, the current anchor (s_m, v_m)
// defines the braking envelope E(d) (braking_envelope.h). A boundary whose limit v_b lies below
// E is binding: it becomes the anchor with min(v_b, maxRestingVelocity(d, v_m)). A servo
// trajectory that can still meet the anchor stays under E, so the boundaries above E need no
// check: the servo cycle looks at one point ahead only. Nor does a boundary whose limit is at or
// above the cap or the highest feed of the element before (the servo cycle's target there).
// Boundaries where the tangential limits change, the programmed feed drops or the motion stops
// are always binding.
namespace kerf::motion {

class Lookahead {
public:
    explicit Lookahead(const MachineModel& model);

    // Appends an element, with the share of the path tolerance left for the filter's contour
    // error, or an action. An element's capVelocity > 0 and limits.accel > 0 add limits of
    // their own (spindle-synchronised moves).
    void push(const MotionItem& item, double contourBudget = 0.0);
    // The motion must stand still at the end of the items pushed so far (an exact stop).
    void stopHere();
    // The stream ends here for now (sync point, program end, flush): everything is final.
    void close();

    // Drops everything (an abort).
    void clear();

    // Moves the next final item into `out`; false when none is final yet.
    bool pop(MotionItem& out);
    bool empty() const { return m_entries.size() == m_released; }
    // Path length waiting in the window (for tests of the bounded window).
    double pendingLength() const;

private:
    struct Entry {
        MotionItem item;
        bool stopAfter = false;
        double contourBudget = 0.0;
        bool provisional = false;  // bind velocity depends on the window end (may still rise)
        bool anchorIsEnd = false;  // bind point is the window end itself
        bool capsFinal = false;    // a stop follows within the window
        AxisBounds bounds;
        Limits limits;
        double cap = 0.0;       // final machine velocity limit
        double localCap = 0.0;  // before curvature steps
        // Estimated velocity at its end accelerating from the one before (prepare's share choice).
        double exitEstimate = 0.0;
        AxisVector nStart{};  // curvature vector at the ends
        AxisVector nEnd{};
        double stepCap = 1e300;     // velocity limit of the curvature step at the start
        bool stepCapFinal = false;  // no point still to come is within the step's reach
        bool outOfReach = false;    // the limit at the start is above any reachable velocity
        bool prepared = false;
    };

    bool isElement(size_t i) const { return m_entries[i].item.kind == MotionItem::Kind::Element; }
    // `previous`: the element before in the same run (same feed kind, no stop), if any.
    void prepare(Entry& entry, const Entry* previous);
    void applyCurvatureSteps(size_t first, size_t last);
    // Signed jump of n at the start of entry i from its neighbour before (zero when none).
    AxisVector stepAt(size_t i) const;
    void markReachable(size_t first, size_t last);
    bool tiny(size_t i) const;
    // Previous / next non-tiny element without a stop in between, or SIZE_MAX.
    size_t neighbourBefore(size_t i) const;
    size_t neighbourAfter(size_t i) const;
    void plan();
    double maxVelocity(const Entry& entry) const;
    double feedLimit(const Entry& entry) const;

    const MachineModel& m_model;
    std::deque<Entry> m_entries;
    size_t m_released = 0;  // entries before this index were popped (kept as neighbours)
    size_t m_final = 0;     // entries before this index may be popped
    size_t m_pushedSincePlan = 0;
    bool m_planNow = false;
    double m_reach = 0.0;         // how far behind released elements can still be neighbours
    CurvatureStepWindow m_steps;  // scratch of applyCurvatureSteps, kept for its capacity
    std::vector<size_t> m_runFirst;
    std::vector<size_t> m_runLast;
};

}  // namespace kerf::motion
