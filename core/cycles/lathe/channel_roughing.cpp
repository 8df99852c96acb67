// Clearance: the profile is a function of the pass coordinate, so the stretches below a level
// are nested in those below every higher level. A column above a point where the profile is at
// level v is therefore empty above v once the passes above v are done, and every move here runs
// down such a column, along a level just cut, or along the profile itself.
#include "core/cycles/lathe/channel_roughing.h"

#include <algorithm>
#include <cmath>

namespace kerf::cycles::lathe {

namespace {

struct Root {
    size_t level = 0;
    size_t index = 0;
    double after = 0.0;  // the chain parameter the channel's entry is looked for after
};

class ChannelCutter {
public:
    ChannelCutter(const ChannelRoughing& job, LathePath& path) : m_job(job), m_path(path) {
        for (const double v : job.levels)
            m_at.push_back(job.chain->intervalsAt(v, job.side));
    }

    std::vector<Root> roots() const {
        std::vector<Root> out;
        for (size_t k = 0; k < m_at.size(); ++k) {
            for (size_t j = 0; j < m_at[k].size(); ++j) {
                const LevelInterval& i = m_at[k][j];
                if (i.fromCallSide()) continue;
                // New below the level above, or split off the main passes' stretch.
                const LevelInterval* parent = k > 0 ? containing(k - 1, i) : nullptr;
                if (parent != nullptr && !parent->fromCallSide()) continue;
                out.push_back({k, j, j > 0 ? m_at[k][j - 1].exit : 0.0});
            }
        }
        std::sort(out.begin(), out.end(), [&](const Root& a, const Root& b) {
            return m_at[a.level][a.index].enter < m_at[b.level][b.index].enter;
        });
        return out;
    }

    void cut(const Root& root) {
        const Chain& chain = *m_job.chain;
        size_t k = root.level;
        LevelInterval stretch = m_at[k][root.index];
        double above = k > 0 ? m_job.levels[k - 1] : m_job.call.y();
        // Entry: down the empty column to the level above, onto the profile, down its wall.
        const double top = chain.topBefore(root.after, stretch.enter, above, m_job.side);
        const Vec2 topPoint = chain.at(top);
        rapid({here().x(), m_job.call.y()});
        rapid({topPoint.x(), m_job.call.y()});
        rapid({topPoint.x(), above});
        m_path.feed(out(topPoint), plungeFeed());
        followChain(chain, top, stretch.enter, plungeFeed(), m_job.facing, m_path);
        std::vector<Root> inner;
        for (;;) {
            pass(stretch, m_job.levels[k], above);
            if (k + 1 >= m_at.size()) break;
            const LevelInterval* next = nullptr;
            for (size_t j = 0; j < m_at[k + 1].size(); ++j) {
                const LevelInterval& child = m_at[k + 1][j];
                if (!inside(child, stretch)) continue;
                if (next == nullptr) {
                    next = &child;
                } else {
                    inner.push_back({k + 1, j, m_at[k + 1][j - 1].exit});
                }
            }
            if (next == nullptr) {
                floorPass(stretch, m_job.levels[k]);
                break;
            }
            followChain(chain, stretch.enter, next->enter, plungeFeed(), m_job.facing, m_path);
            above = m_job.levels[k];
            stretch = *next;
            ++k;
        }
        rapid({here().x(), m_job.call.y()});
        for (const Root& r : inner)
            cut(r);
    }

private:
    // One pass at `level` over `stretch`, the retract, then (`back`) to its entry at that level.
    void pass(const LevelInterval& stretch, double level, double above, bool back = true) {
        const Chain& chain = *m_job.chain;
        const bool toWall = stretch.exit >= chain.size();
        const double entry = chain.at(stretch.enter).x();
        const double exit = toWall ? chain.end().x() : chain.at(stretch.exit).x();
        const Vec2 end(exit, level);
        cutAlongLevel(m_job.raw, m_job.side, exit, level, m_job.feed, m_job.facing, m_path);
        const double band = m_job.side * (above - level);
        if (m_job.retract && *m_job.retract > 0.0) {
            const double d = std::min({*m_job.retract, std::fabs(exit - entry), band});
            rapid(end + Vec2(-m_job.passDirection * d, m_job.side * d));
        } else if (!m_job.retract) {
            // Up the far wall along the profile while it rises, at most to the level above.
            if (toWall) {
                m_path.feed(out({exit, above}), m_job.feed);
            } else {
                const double t = riseEnd(stretch.exit, above);
                followChain(chain, stretch.exit, t, m_job.feed, m_job.facing, m_path);
            }
        }
        if (!back) return;
        // Back over the level just cut (at the feed over what following the wall left).
        if (!m_job.retract) m_path.feed(out({entry, here().y()}), m_job.feed);
        rapid({entry, here().y()});
        rapid({entry, level});
    }

    // The channel's floor, when it lies deeper than the last level: down the wall to it, along
    // it, back, so that roughing leaves the allowance there too.
    void floorPass(const LevelInterval& stretch, double level) {
        const Chain& chain = *m_job.chain;
        const double exit = std::min(stretch.exit, chain.size());
        const auto [first, last] = chain.lowestBetween(stretch.enter, exit, m_job.side);
        const double floor = chain.at(first).y();
        if (m_job.side * (level - floor) <= kChainTolerance) return;
        followChain(chain, stretch.enter, first, plungeFeed(), m_job.facing, m_path);
        LevelInterval bottom;
        bottom.enter = first;
        bottom.exit = last;
        pass(bottom, floor, level, false);
    }

    // Where the profile, rising from t, stops rising or reaches `cap`.
    double riseEnd(double t, double cap) const {
        const Chain& chain = *m_job.chain;
        for (auto i = static_cast<size_t>(std::floor(t)); i < chain.parts.size(); ++i) {
            const Section& s = chain.parts[i];
            if (m_job.side * (s.b.y() - s.a.y()) < -kChainTolerance) {
                return std::max(t, static_cast<double>(i));
            }
            if (m_job.side * (s.b.y() - cap) >= -kChainTolerance) {
                return std::max(t, static_cast<double>(i) + s.atLevel(cap));
            }
        }
        return chain.size();
    }

    const LevelInterval* containing(size_t k, const LevelInterval& i) const {
        for (const LevelInterval& p : m_at[k]) {
            if (inside(i, p)) return &p;
        }
        return nullptr;
    }
    static bool inside(const LevelInterval& i, const LevelInterval& p) {
        return (p.fromCallSide() || i.enter >= p.enter - 1e-9) && i.exit <= p.exit + 1e-9;
    }

    double plungeFeed() const { return m_job.plungeFeed > 0.0 ? m_job.plungeFeed : m_job.feed; }
    Vec2 out(const Vec2& p) const { return swapped(p, m_job.facing); }
    Vec2 here() const { return swapped(m_path.position(), m_job.facing); }
    void rapid(const Vec2& p) { m_path.rapid(out(p)); }

    const ChannelRoughing& m_job;
    LathePath& m_path;
    std::vector<std::vector<LevelInterval>> m_at;
};

}  // namespace

bool roughChannels(const ChannelRoughing& job, LathePath& path) {
    ChannelCutter cutter(job, path);
    const std::vector<Root> roots = cutter.roots();
    for (const Root& root : roots)
        cutter.cut(root);
    return !roots.empty();
}

}  // namespace kerf::cycles::lathe
