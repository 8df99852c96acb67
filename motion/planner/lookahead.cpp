#include "motion/planner/lookahead.h"

#include <algorithm>
#include <cmath>

#include "motion/profile/braking_envelope.h"

namespace kerf::motion {

namespace {

constexpr double kFar = 1e12;
constexpr double kTinyLength = 1e-6;
constexpr size_t kNoEntry = static_cast<size_t>(-1);
// An element keeps the tangential limits of the one before down to this factor below its own.
constexpr double kMaxShareStepDown = 2.5;
// Elements up to this long keep the share of the element before whatever their length needs
// (vertex noise, blends, halved fitted spans).
constexpr double kKeepShareMaxLengthMm = 0.6;
// Below its feed, an element keeps the share of the one before when that lowers its own-sweep
// velocity limit by no more than this factor.
constexpr double kKeptShareCapFraction = 0.96;
// A share above the summed choice is taken where its own-sweep limit reaches this part of the feed.
constexpr double kRaisedShareFeedFraction = 0.98;
// Points of a curvature-step window kept beyond the reach (rounding of the distances).
constexpr double kReachMarginMm = 1e-6;

// Time to cross `length` entering at vIn, accelerating at `accel` up to `cap` (no jerk ramps).
double crossingTime(double vIn, double cap, double accel, double length) {
    const double v0 = std::min(vIn, cap);
    const double rampLength = (cap * cap - v0 * v0) / (2.0 * accel);
    if (rampLength >= length)
        return 2.0 * length / (v0 + std::sqrt(v0 * v0 + 2.0 * accel * length));
    return (cap - v0) / accel + (length - rampLength) / cap;
}

// The same from a = 0, with the jerk ramps of an S-curve: the velocity change dv takes
// dv / A + A / J (2 sqrt(dv / J) when A is not reached) and covers its mean velocity times that.
// Where the element ends before the cap, the velocity reached there is found by bisection.
double crossingTimeFromRest(double vIn, double cap, const Limits& limits, double length) {
    const double v0 = std::min(vIn, cap);
    auto rampTime = [&](double dv) {
        return dv * limits.jerk >= limits.accel * limits.accel
                   ? dv / limits.accel + limits.accel / limits.jerk
                   : 2.0 * std::sqrt(dv / limits.jerk);
    };
    const double full = rampTime(cap - v0);
    const double fullLength = (v0 + cap) / 2.0 * full;
    if (fullLength <= length) return full + (length - fullLength) / cap;
    double lo = v0;
    double hi = cap;
    for (int k = 0; k < 40; ++k) {
        const double mid = (lo + hi) / 2.0;
        ((v0 + mid) / 2.0 * rampTime(mid - v0) <= length ? lo : hi) = mid;
    }
    return 2.0 * length / (v0 + lo);
}

bool sameLimits(const Limits& a, const Limits& b) {
    return a.accel == b.accel && a.jerk == b.jerk;
}

}  // namespace

Lookahead::Lookahead(const MachineModel& model) : m_model(model) {}

void Lookahead::push(const MotionItem& item, double contourBudget) {
    Entry entry;
    entry.item = item;
    entry.contourBudget = contourBudget;
    m_entries.push_back(entry);
    ++m_pushedSincePlan;
}

void Lookahead::stopHere() {
    for (size_t i = m_entries.size(); i-- > m_released;) {
        if (isElement(i)) {
            m_entries[i].stopAfter = true;
            return;
        }
    }
}

void Lookahead::clear() {
    m_entries.clear();
    m_released = m_final = m_pushedSincePlan = 0;
    m_planNow = false;
}

void Lookahead::close() {
    stopHere();
    m_planNow = true;
}

double Lookahead::pendingLength() const {
    double length = 0.0;
    for (size_t i = m_released; i < m_entries.size(); ++i) {
        if (isElement(i)) length += m_entries[i].item.element.geometry.length;
    }
    return length;
}

double Lookahead::feedLimit(const Entry& entry) const {
    // At 100 % override: with more the servo cycle stays below the chain near feed drops, with
    // less it may briefly pass the lower programmed feed there.
    const PathElement& e = entry.item.element;
    double feed = e.feed;
    if (e.feedKind == FeedKind::PerRevolution || e.feedKind == FeedKind::SpindleSynced) {
        feed *= m_model.spindleMaxRpm / 60.0;
    }
    return feed;
}

double Lookahead::maxVelocity(const Entry& entry) const {
    const PathElement& e = entry.item.element;
    double feed = e.feed;
    switch (e.feedKind) {
        case FeedKind::Rapid:
            break;
        case FeedKind::PerMinute:
            feed *= m_model.options.maxFeedOverride;
            break;
        case FeedKind::PerRevolution:
            feed *= m_model.spindleMaxRpm / 60.0 * m_model.options.maxFeedOverride;
            break;
        case FeedKind::SpindleSynced:
            feed *= m_model.spindleMaxRpm / 60.0;
            break;
    }
    return std::min(entry.cap, feed);
}

void Lookahead::prepare(Entry& entry, const Entry* previous) {
    PathElement& e = entry.item.element;
    entry.bounds = axisBounds(e.geometry);
    // The largest share of the tangential limits that still lets the element run at its
    // programmed feed (or, failing that, the share giving the highest velocity).
    double nominal =
        e.feedKind == FeedKind::Rapid || e.feedKind == FeedKind::PerMinute ? e.feed : 1e300;
    double bestCap = -1.0;
    // Limits of its own (a stage of a share ladder near a stop, share_ladder.h): as they are.
    const bool ownShare = e.limits.accel > 0.0 && e.feedKind != FeedKind::SpindleSynced;
    if (ownShare) entry.limits = e.limits;
    for (double share : kTangentialShares) {
        if (ownShare) break;
        Limits limits = tangentialLimits(m_model, entry.bounds, share);
        if (e.limits.accel > 0.0) {
            limits = {std::min(limits.accel, e.limits.accel * share / kTangentialShares[0]),
                      std::min(limits.jerk, e.limits.jerk * share / kTangentialShares[0])};
        }
        double cap =
            summedPeaksVelocityCap(m_model, e.geometry, entry.bounds, limits, entry.contourBudget);
        if (cap > bestCap * 1.05) {
            bestCap = cap;
            entry.limits = limits;
        }
        if (cap >= 0.95 * nominal) break;
    }
    // The summed peaks are those of a whole turn, but an arc of a fitted curve reaches only some
    // of its phases. Where the element runs at its feed with the chosen share, a higher share is
    // taken when its limit over the element's own sweep still lets it run within 2 % of the feed
    // (the flanks of a sine polyline: 90 % instead of 30 %). An element held below its feed
    // keeps the summed choice, which trades acceleration for velocity (a true arc R5: 10 %).
    if (!ownShare && e.limits.accel <= 0.0 &&
        elementVelocityCap(m_model, e.geometry, entry.bounds, entry.limits, entry.contourBudget) >=
            nominal) {
        for (double share : kTangentialShares) {
            Limits limits = tangentialLimits(m_model, entry.bounds, share);
            if (limits.accel <= entry.limits.accel) break;
            if (elementVelocityCap(m_model, e.geometry, entry.bounds, limits,
                                   entry.contourBudget) >= kRaisedShareFeedFraction * nominal) {
                entry.limits = limits;
                break;
            }
        }
    }
    // Below its feed (near the crest of a curve) the summed choice gives the highest velocity,
    // but the element is entered no faster than the motion gets there: the lower of the cap of
    // the one before and its estimated exit velocity (accelerating all along from the one
    // before it, `exitEstimate`). Where that is lower than this element's cap, a higher share may
    // cross it sooner. The share with the shortest crossing (accelerate from the entry velocity
    // up to the share's own cap, or the feed, then cruise) is taken. Keeping the share of the
    // element before goes on accelerating; a change of share is a point with a = 0, so there the
    // crossing starts from a = 0 with the share's jerk ramps (2026-11-28: leaving the crests of
    // a sine as 0.5 mm lines, runs of 0.25 mm arcs each too short for a change without them
    // stayed at 10 % all the way up from the crest's 71 mm/s).
    if (!ownShare && e.limits.accel <= 0.0 && previous) {
        const double chosenCap = elementVelocityCap(m_model, e.geometry, entry.bounds, entry.limits,
                                                    entry.contourBudget);
        const double entryVelocity =
            std::min({previous->exitEstimate, previous->localCap, nominal});
        const double length = e.geometry.length;
        if (entryVelocity < std::min(chosenCap, nominal)) {
            auto timeWith = [&](const Limits& limits, double cap) {
                return sameLimits(limits, previous->limits)
                           ? crossingTime(entryVelocity, cap, limits.accel, length)
                           : crossingTimeFromRest(entryVelocity, cap, limits, length);
            };
            double fastest = timeWith(entry.limits, std::min(chosenCap, nominal));
            Limits chosen = entry.limits;
            for (double share : kTangentialShares) {
                Limits limits = tangentialLimits(m_model, entry.bounds, share);
                if (limits.accel <= entry.limits.accel) break;
                const double cap = elementVelocityCap(m_model, e.geometry, entry.bounds, limits,
                                                      entry.contourBudget);
                const double time = timeWith(limits, std::min(cap, nominal));
                if (time < fastest) {
                    fastest = time;
                    chosen = limits;
                }
            }
            entry.limits = chosen;
        }
    }
    // Keep the limits of the element before when they let this one run at its feed too (or,
    // below its feed, lower its own-sweep limit by at most 4 %: braking into the crest of a sine
    // at 30 % instead of dropping to 10 %): where
    // they change the motion must pass with a = 0, and on a polyline the radius noise would
    // otherwise flip the share from one vertex to the next. A long element that would reach its
    // feed at the kept share only beyond its own end takes its own share instead: one point with
    // a = 0 costs less than accelerating all along it at the lower share (a fitted raster row
    // after a U-turn kept 60 % for 20 mm).
    const double runVelocity = std::min(nominal, bestCap);
    const bool keepingIsCheap =
        previous && (e.geometry.length <= kKeepShareMaxLengthMm ||
                     runVelocity * runVelocity <= 2.0 * previous->limits.accel * e.geometry.length);
    // Below its feed, the kept share may lower the element's own-sweep limit a little.
    auto keptCapFits = [&](double keptCap) {
        const double ownCap = elementVelocityCap(m_model, e.geometry, entry.bounds, entry.limits,
                                                 entry.contourBudget);
        return ownCap < nominal && keptCap >= kKeptShareCapFraction * ownCap;
    };
    if (keepingIsCheap && e.limits.accel <= 0.0 && !sameLimits(previous->limits, entry.limits)) {
        Limits widest = tangentialLimits(m_model, entry.bounds, kTangentialShares[0]);
        const Limits& kept = previous->limits;
        // Only from a neighbouring share down (a row after a tight U-turn keeps its own).
        if (kept.accel <= widest.accel && kept.jerk <= widest.jerk &&
            kept.accel * kMaxShareStepDown >= entry.limits.accel &&
            (summedPeaksVelocityCap(m_model, e.geometry, entry.bounds, kept, entry.contourBudget) >=
                 std::min(0.95 * nominal, bestCap) ||
             keptCapFits(elementVelocityCap(m_model, e.geometry, entry.bounds, kept,
                                            entry.contourBudget)))) {
            entry.limits = kept;
        }
    }
    // Where the highest share leaves the element's velocity limit as it is (a line, a gently
    // curved span of a fitted raster row), the acceleration goes up to the top share and the
    // jerk stays (velocity_limits.h): the rows of a 0.05 mm raster climbed at 90 % where the
    // bound climbs at 100 %. A short element (vertex noise, a blend) after one at the highest
    // share keeps it, as above: each change of share is a point with a = 0.
    const Limits widest = tangentialLimits(m_model, entry.bounds, kTangentialShares[0]);
    const bool mayLeaveWidest = e.geometry.length > kKeepShareMaxLengthMm || !previous ||
                                !sameLimits(previous->limits, widest);
    if (!ownShare && e.limits.accel <= 0.0 && mayLeaveWidest && sameLimits(entry.limits, widest)) {
        const Limits top = topTangentialLimits(m_model, entry.bounds);
        const double widestCap =
            elementVelocityCap(m_model, e.geometry, entry.bounds, widest, entry.contourBudget);
        if (elementVelocityCap(m_model, e.geometry, entry.bounds, top, entry.contourBudget) >=
            std::min(nominal, widestCap))
            entry.limits = top;
    }
    // The share chosen by the summed peaks (velocity_limits.h); the limit itself phase-aware.
    entry.localCap =
        elementVelocityCap(m_model, e.geometry, entry.bounds, entry.limits, entry.contourBudget);
    if (e.capVelocity > 0.0) entry.localCap = std::min(entry.localCap, e.capVelocity);
    entry.cap = entry.localCap;
    const double entryEstimate = previous ? std::min(previous->exitEstimate, entry.localCap) : 0.0;
    entry.exitEstimate = std::min(
        entry.localCap,
        std::sqrt(entryEstimate * entryEstimate + 2.0 * entry.limits.accel * e.geometry.length));
    entry.nStart = pointAt(e.geometry, 0.0).curvature;
    entry.nEnd = pointAt(e.geometry, e.geometry.length).curvature;
    entry.prepared = true;
}

bool Lookahead::tiny(size_t i) const {
    return m_entries[i].item.element.geometry.length < kTinyLength;
}

size_t Lookahead::neighbourBefore(size_t i) const {
    while (i > 0 && isElement(i - 1) && !m_entries[i - 1].stopAfter) {
        --i;
        if (!tiny(i)) return i;
    }
    return kNoEntry;
}

size_t Lookahead::neighbourAfter(size_t i) const {
    while (i + 1 < m_entries.size() && isElement(i + 1) && !m_entries[i].stopAfter) {
        ++i;
        if (!tiny(i)) return i;
    }
    return kNoEntry;
}

AxisVector Lookahead::stepAt(size_t i) const {
    AxisVector step{};
    if (!isElement(i) || tiny(i)) return step;
    size_t p = neighbourBefore(i);
    if (p == kNoEntry) return step;
    for (size_t a = 0; a < step.size(); ++a)
        step[a] = m_entries[i].nStart[a] - m_entries[p].nEnd[a];
    return step;
}

void Lookahead::applyCurvatureSteps(size_t first, size_t last) {
    // Limits found final in an earlier pass stay.
    while (first < last && isElement(first) && m_entries[first].stepCapFinal)
        ++first;
    if (first == last) return;
    // A limit counts the steps within v T <= maxVelocity T of its point, also those of elements
    // already released: the window starts that far back in the run holding `first`.
    double reach = 0.0;
    for (size_t i = first; i < last; ++i) {
        if (isElement(i)) reach = std::max(reach, maxVelocity(m_entries[i]));
    }
    reach *= m_model.filterTimeS();
    const double from = isElement(first) ? m_entries[first].item.element.sStart : 0.0;
    size_t begin = first;
    while (begin > 0 && isElement(begin - 1) && !m_entries[begin - 1].stopAfter &&
           from - m_entries[begin].item.element.sStart <= reach + kReachMarginMm)
        --begin;
    m_steps.clear();
    m_runFirst.assign(last - begin, 0);
    m_runLast.assign(last - begin, 0);
    double s = 0.0;
    for (size_t i = begin; i < last; ++i) {
        if (isElement(i)) s = m_entries[i].item.element.sStart;
        m_steps.add(s, stepAt(i));
        size_t k = i - begin;
        bool joined = k > 0 && isElement(i - 1) && isElement(i) && !m_entries[i - 1].stopAfter;
        m_runFirst[k] = joined ? m_runFirst[k - 1] : k;
    }
    for (size_t k = last - begin; k-- > 0;) {
        size_t i = k + begin;
        bool joined = i + 1 < last && isElement(i) && isElement(i + 1) && !m_entries[i].stopAfter;
        m_runLast[k] = joined ? m_runLast[k + 1] : k;
    }
    const size_t lastPoint = last - begin - 1;
    for (size_t i = first; i < last; ++i) {
        if (!isElement(i) || tiny(i) || m_entries[i].stepCapFinal) continue;
        Entry& entry = m_entries[i];
        entry.stepCap = 1e300;
        entry.stepCapFinal = true;
        size_t p = neighbourBefore(i);
        if (p == kNoEntry) continue;
        const Entry& before = m_entries[p];
        AxisVector step = stepAt(i);
        double largest = 0.0;
        for (double value : step)
            largest = std::max(largest, std::fabs(value));
        if (largest < 1e-12) continue;
        double v = std::min({entry.localCap, before.localCap, maxVelocity(entry)});
        const PathElement& e = entry.item.element;
        const PathElement& b = before.item.element;
        PointJerkTerms termsBefore = jerkTermsAt(b.geometry, b.geometry.length, before.limits);
        PointJerkTerms termsAfter = jerkTermsAt(e.geometry, 0.0, entry.limits);
        size_t k = i - begin;
        entry.stepCap =
            m_steps.cap(m_model, k, m_runFirst[k], m_runLast[k], termsBefore, termsAfter, v);
        // The limit counts the points of its run within v T: it stays once the run has ended
        // or has points beyond that reach (the planning passes after this one skip it).
        entry.stepCapFinal =
            m_runLast[k] < lastPoint ||
            m_steps.position(lastPoint) - m_steps.position(k) > v * m_model.filterTimeS();
    }
}

void Lookahead::markReachable(size_t first, size_t last) {
    // A limit above the fastest acceleration from the last point the motion had to meet with
    // a = 0 (forwards, the mirror image of the braking envelope) can never be reached: it needs no
    // check. Without this, limits that rise along the path would each be met with a = 0.
    double anchorS = 0.0;
    double anchorV = 0.0;
    for (size_t i = first; i < last; ++i) {
        if (!isElement(i)) continue;
        Entry& entry = m_entries[i];
        const PathElement& e = entry.item.element;
        double limit = std::min(entry.cap, entry.stepCap);
        entry.outOfReach = false;
        bool fresh = i == first || !isElement(i - 1) || m_entries[i - 1].stopAfter ||
                     !sameLimits(m_entries[i - 1].limits, entry.limits);
        if (fresh) {
            anchorS = e.sStart;
            anchorV = i == first ? limit
                                 : (isElement(i - 1) && !m_entries[i - 1].stopAfter ? limit : 0.0);
        } else if (limit >= std::min(m_entries[i - 1].cap, maxVelocity(m_entries[i - 1])) ||
                   limit >= brakingEnvelope(e.sStart - anchorS, anchorV, entry.limits)) {
            // The servo cycle keeps the element before at or below its cap and its feed (its
            // target velocity there; equal limits along a run), or it cannot accelerate that
            // far: the motion never passes this limit.
            entry.outOfReach = true;
        } else {
            anchorS = e.sStart;
            anchorV = limit;
        }
    }
}

void Lookahead::plan() {
    m_pushedSincePlan = 0;
    for (size_t i = m_released; i < m_entries.size(); ++i) {
        if (!isElement(i) || m_entries[i].prepared) continue;
        const Entry* previous = nullptr;
        if (i > 0 && isElement(i - 1) && !m_entries[i - 1].stopAfter &&
            m_entries[i - 1].item.element.feedKind == m_entries[i].item.element.feedKind)
            previous = &m_entries[i - 1];
        prepare(m_entries[i], previous);
    }
    applyCurvatureSteps(m_final, m_entries.size());
    markReachable(m_final, m_entries.size());

    // Backwards: binding points.
    double lastEnd = 0.0;
    double highest = 0.0;
    for (size_t i = m_final; i < m_entries.size(); ++i) {
        if (!isElement(i)) continue;
        lastEnd = m_entries[i].item.element.sEnd();
        highest = std::max(highest, maxVelocity(m_entries[i]));
    }
    double anchorS = lastEnd;
    double anchorV = 0.0;
    double anchorFeed = 0.0;
    FeedKind anchorKind = FeedKind::PerMinute;
    bool provisional = true;
    bool anchorIsEnd = true;
    bool stopPending = false;
    bool stopAhead = false;
    for (size_t i = m_entries.size(); i-- > m_final;) {
        if (!isElement(i)) {
            stopPending = true;
            continue;
        }
        Entry& entry = m_entries[i];
        PathElement& e = entry.item.element;
        if (entry.stopAfter || stopPending) {
            anchorS = e.sEnd();
            anchorV = 0.0;
            provisional = false;
            anchorIsEnd = false;
            stopPending = false;
            stopAhead = true;
        }
        e.bindS = anchorS;
        e.bindVelocity = anchorV;
        e.bindFeed = anchorFeed;
        e.bindFeedKind = anchorKind;
        e.limits = entry.limits;
        e.capVelocity = entry.cap;
        entry.provisional = provisional;
        entry.anchorIsEnd = anchorIsEnd;
        entry.capsFinal = stopAhead;
        if (i == 0 || !isElement(i - 1)) {
            stopPending = i > 0;
            continue;
        }
        const Entry& before = m_entries[i - 1];
        const PathElement& b = before.item.element;
        bool forced =
            !sameLimits(before.limits, entry.limits) || b.feedKind != e.feedKind || e.feed < b.feed;
        double distance = anchorS - e.sStart;
        double limit = std::min(entry.cap, entry.stepCap);
        // Where the programmed feed drops, the chain must plan for the new feed: the servo cycle
        // holds the feed itself everywhere else.
        bool feedDrop = b.feedKind != e.feedKind || e.feed < b.feed;
        if (feedDrop) limit = std::min(limit, feedLimit(entry));
        if (forced ||
            (!entry.outOfReach && limit < brakingEnvelope(distance, anchorV, entry.limits))) {
            double resting = maxRestingVelocity(distance, anchorV, entry.limits);
            if (limit <= resting) provisional = false;
            anchorV = std::min(limit, resting);
            anchorS = e.sStart;
            anchorIsEnd = false;
            anchorFeed = e.feed;
            anchorKind = e.feedKind;
        }
    }

    // Forwards: which entries can no longer change.
    double capReach = 2.0 * highest * m_model.filterTimeS();
    m_reach = std::max(m_reach, capReach);
    for (size_t i = m_final; i < m_entries.size(); ++i) {
        Entry& entry = m_entries[i];
        if (isElement(i)) {
            PathElement& e = entry.item.element;
            if (!entry.capsFinal && e.sEnd() + capReach > lastEnd) break;
            if (entry.provisional) {
                // Only a bind on the window's own end can be replaced: nothing binds before it.
                if (!entry.anchorIsEnd) break;
                if (lastEnd - e.sEnd() < stoppingDistance(highest, entry.limits)) break;
                e.bindS = e.sEnd() + kFar;
                e.bindVelocity = kFar;
            }
        }
        m_final = i + 1;
    }
}

bool Lookahead::pop(MotionItem& out) {
    if (m_final == m_released) {
        size_t waiting = m_entries.size() - m_final;
        if (waiting == 0) return false;
        if (!m_planNow && m_pushedSincePlan < std::max<size_t>(64, waiting / 2)) return false;
        m_planNow = false;
        plan();
        if (m_final == m_released) return false;
    }
    out = m_entries[m_released].item;
    ++m_released;
    // Released elements stay as long as they can be neighbours of the next ones.
    while (m_released > 0 && m_released < m_entries.size()) {
        const Entry& oldest = m_entries.front();
        const Entry& next = m_entries[m_released];
        bool keep = oldest.item.kind == MotionItem::Kind::Element &&
                    next.item.kind == MotionItem::Kind::Element &&
                    next.item.element.sStart - oldest.item.element.sEnd() < m_reach;
        if (keep) break;
        m_entries.pop_front();
        --m_released;
        --m_final;
    }
    return true;
}

}  // namespace kerf::motion
