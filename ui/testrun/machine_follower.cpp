#include "ui/testrun/machine_follower.h"

#include <algorithm>
#include <limits>

namespace kerf::ui {

namespace {

// How far ahead a new block is looked for at each look, before the rest of the program is.
constexpr size_t kBlockWindow = size_t{1} << 16;
// Bounds the moves and points of one block compared at each look.
constexpr size_t kMaxCandidateMoves = 512;
constexpr size_t kMaxCandidatePoints = 50'000;
// Moves this close to the commanded position count as passing there alike (mm).
constexpr double kTieMm = 0.005;
// The tool moved between two looks when it moved this far (mm).
constexpr double kMovedMm = 1e-4;

struct Nearest {
    double distance = std::numeric_limits<double>::infinity();
    double position = 0.0;  // along the move's points: segment index + part of it
    Vec3 direction{0.0, 0.0, 0.0};
};

// The point of the polyline [from, to] (inclusive) nearest p.
Nearest nearestOnPoints(const graphics::ToolpathData& path, size_t from, size_t to, const Vec3& p) {
    Nearest best;
    for (size_t i = from; i < to; ++i) {
        const Vec3 a = path.point(i);
        const Vec3 ab = path.point(i + 1) - a;
        const double length2 = ab.squaredNorm();
        const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
        const double distance = (a + ab * t - p).norm();
        if (distance < best.distance) {
            best.distance = distance;
            best.position = static_cast<double>(i - from) + t;
            best.direction = ab;
        }
    }
    return best;
}

}  // namespace

std::optional<size_t> MachineFollower::findBlock(const SourceLocation& block, size_t from) {
    const auto& commands = m_program.commands;
    // Before the first look the start may lie anywhere (Start at block).
    const size_t window =
        m_start ? std::min(commands.size(), from + kBlockWindow) : commands.size();
    for (size_t k = from; k < window; ++k)
        if (commands[k].location == block) return k;
    if (window == commands.size() || m_missing == block) return std::nullopt;
    for (size_t k = window; k < commands.size(); ++k)
        if (commands[k].location == block) return k;
    m_missing = block;
    return std::nullopt;
}

void MachineFollower::observe(const SourceLocation& block, const Vec3& nominal) {
    const auto& commands = m_program.commands;
    if (m_point.command >= commands.size() && m_start) return;  // at the end already
    const bool inBlock =
        m_start && m_point.command < commands.size() && commands[m_point.command].location == block;
    if (!inBlock) {
        const size_t from = m_start ? m_point.command + 1 : 0;
        const std::optional<size_t> found = findBlock(block, from);
        if (!found) {
            m_lastNominal = nominal;
            return;
        }
        m_point = {*found, 0.0};
        if (!m_start) m_start = m_point;
    }
    advanceWithinBlock(block, nominal);
    m_lastNominal = nominal;
}

void MachineFollower::advanceWithinBlock(const SourceLocation& block, const Vec3& nominal) {
    const auto& commands = m_program.commands;
    if (!m_program.toolpath) return;
    const graphics::ToolpathData& path = *m_program.toolpath;
    const Vec3 moved = m_lastNominal ? Vec3(nominal - *m_lastNominal) : Vec3(0.0, 0.0, 0.0);
    const bool moving = moved.norm() > kMovedMm;
    struct Candidate {
        RunPoint point;
        Nearest nearest;
    };
    std::vector<Candidate> candidates;
    size_t points = 0;
    for (size_t k = m_point.command;
         k < commands.size() && commands[k].location == block &&
         candidates.size() < kMaxCandidateMoves && points < kMaxCandidatePoints;
         ++k) {
        if (!m_program.isMove(k)) continue;
        const auto [begin, end] = path.pointsOfMove(m_program.movesBefore[k]);
        if (begin == 0 || end <= begin) continue;
        const size_t from = begin - 1;
        const Nearest nearest = nearestOnPoints(path, from, end - 1, nominal);
        points += end - begin;
        double fraction = nearest.position / static_cast<double>(end - 1 - from);
        if (k == m_point.command) fraction = std::max(fraction, m_point.fraction);
        candidates.push_back({{k, fraction}, nearest});
    }
    if (candidates.empty()) return;
    double nearestDistance = std::numeric_limits<double>::infinity();
    for (const Candidate& c : candidates)
        nearestDistance = std::min(nearestDistance, c.nearest.distance);
    const Candidate* chosen = nullptr;
    for (const Candidate& c : candidates) {
        if (c.nearest.distance > nearestDistance + kTieMm) continue;
        if (chosen == nullptr) chosen = &c;
        if (!moving) break;
        if (c.nearest.direction.dot(moved) > 0.0) {
            chosen = &c;
            break;
        }
    }
    const RunPoint& next = chosen->point;
    if (next.command > m_point.command ||
        (next.command == m_point.command && next.fraction > m_point.fraction))
        m_point = next;
}

void MachineFollower::finish() {
    if (!m_start) m_start = RunPoint{};
    m_point = {m_program.commands.size(), 0.0};
}

}  // namespace kerf::ui
