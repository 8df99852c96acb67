#include "motion/planner/lookahead.h"

#include <algorithm>
#include <cmath>

#include "motion/profile/braking_envelope.h"

namespace kerf::motion {

namespace {

constexpr double kFar = 1e12;
constexpr double kTinyLength = 1e-6;
constexpr size_t kNoEntry = static_cast<size_t>(-1);

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

void Lookahead::prepare(Entry& entry) {
    PathElement& e = entry.item.element;
    entry.bounds = axisBounds(e.geometry);
    // The largest share of the tangential limits that still lets the element run at its
    // programmed feed (or, failing that, the share giving the highest velocity).
    double nominal =
        e.feedKind == FeedKind::Rapid || e.feedKind == FeedKind::PerMinute ? e.feed : 1e300;
    double bestCap = -1.0;
    for (double share : kTangentialShares) {
        Limits limits = tangentialLimits(m_model, entry.bounds, share);
        if (e.limits.accel > 0.0) {
            limits = {std::min(limits.accel, e.limits.accel * share / kTangentialShares[0]),
                      std::min(limits.jerk, e.limits.jerk * share / kTangentialShares[0])};
        }
        double cap =
            elementVelocityCap(m_model, e.geometry, entry.bounds, limits, entry.contourBudget);
        if (cap > bestCap * 1.05) {
            bestCap = cap;
            entry.limits = limits;
            entry.localCap = cap;
        }
        if (cap >= 0.95 * nominal) break;
    }
    if (e.capVelocity > 0.0) entry.localCap = std::min(entry.localCap, e.capVelocity);
    entry.cap = entry.localCap;
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

void Lookahead::applyCurvatureSteps(size_t first, size_t last) {
    const double filterTime = m_model.filterTimeS();
    for (size_t i = first; i < last; ++i) {
        if (!isElement(i) || tiny(i)) continue;
        Entry& entry = m_entries[i];
        entry.stepCap = 1e300;
        size_t p = neighbourBefore(i);
        if (p == kNoEntry) continue;
        const Entry& before = m_entries[p];
        AxisVector step{};
        double largest = 0.0;
        for (size_t a = 0; a < step.size(); ++a) {
            step[a] = std::fabs(entry.nStart[a] - before.nEnd[a]);
            largest = std::max(largest, step[a]);
        }
        if (largest < 1e-12) continue;
        // Steps closer than one filter length (at the velocity found) add up: widen the window
        // step by step, nearest first, while the velocity allows it to reach further.
        double v = std::min({entry.localCap, before.localCap, maxVelocity(entry)});
        const PathElement& e = entry.item.element;
        const PathElement& b = before.item.element;
        PointJerkTerms termsBefore = jerkTermsAt(b.geometry, b.geometry.length, before.limits);
        PointJerkTerms termsAfter = jerkTermsAt(e.geometry, 0.0, entry.limits);
        auto addStep = [&](size_t k, AxisVector& sum) {
            const Entry& at = m_entries[k];
            const Entry& prev = m_entries[neighbourBefore(k)];
            for (size_t a = 0; a < sum.size(); ++a)
                sum[a] += std::fabs(at.nStart[a] - prev.nEnd[a]);
        };
        auto hasStep = [&](size_t k) { return k != kNoEntry && neighbourBefore(k) != kNoEntry; };
        AxisVector wide = step;
        double reach = v * filterTime;
        for (size_t k = neighbourAfter(i); k != kNoEntry; k = neighbourAfter(k)) {
            if (m_entries[k].item.element.sStart - e.sStart > reach) break;
            addStep(k, wide);
        }
        for (size_t k = p; hasStep(k); k = neighbourBefore(k)) {
            if (e.sStart - m_entries[k].item.element.sStart > reach) break;
            addStep(k, wide);
        }
        entry.stepCap = curvatureStepCap(m_model, wide, termsBefore, termsAfter, v);
        if (entry.stepCap >= v) continue;
        AxisVector sum = step;
        size_t forward = neighbourAfter(i);
        size_t backward = p;
        double best = 0.0;
        for (;;) {
            double cap = curvatureStepCap(m_model, sum, termsBefore, termsAfter, v);
            double ahead =
                forward != kNoEntry ? m_entries[forward].item.element.sStart - e.sStart : 1e300;
            double behind =
                hasStep(backward) ? e.sStart - m_entries[backward].item.element.sStart : 1e300;
            double next = std::min(ahead, behind);
            best = std::max(best, std::min(cap, next / filterTime));
            if (next / filterTime >= cap) break;
            if (ahead <= behind) {
                addStep(forward, sum);
                forward = neighbourAfter(forward);
            } else {
                addStep(backward, sum);
                backward = neighbourBefore(backward);
            }
        }
        entry.stepCap = best;
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
        } else if (limit >= brakingEnvelope(e.sStart - anchorS, anchorV, entry.limits)) {
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
        if (isElement(i) && !m_entries[i].prepared) prepare(m_entries[i]);
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
