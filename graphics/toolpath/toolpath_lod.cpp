#include "graphics/toolpath/toolpath_lod.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>

namespace kerf::graphics {

namespace {

double distanceToSegmentSq(const float* p, const float* a, const float* b) {
    const double abx = double{b[0]} - double{a[0]};
    const double aby = double{b[1]} - double{a[1]};
    const double abz = double{b[2]} - double{a[2]};
    const double apx = double{p[0]} - double{a[0]};
    const double apy = double{p[1]} - double{a[1]};
    const double apz = double{p[2]} - double{a[2]};
    const double len2 = abx * abx + aby * aby + abz * abz;
    double t = len2 > 0.0 ? (apx * abx + apy * aby + apz * abz) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double dx = apx - t * abx;
    const double dy = apy - t * aby;
    const double dz = apz - t * abz;
    return dx * dx + dy * dy + dz * dz;
}

uint64_t mix(uint64_t h, uint64_t v) {
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ull;
    return h ^ (h >> 29);
}

int64_t quantize(float v, double inverse) {
    const double q = std::round(double{v} * inverse);
    return static_cast<int64_t>(std::clamp(q, -9.0e15, 9.0e15));
}

// Set of 64-bit segment keys (open addressing; 0 marks an empty slot).
class KeySet {
public:
    explicit KeySet(size_t expected) {
        size_t size = 16;
        while (size < expected * 2)
            size <<= 1;
        m_slots.assign(size, 0);
    }
    // True when the key was not there yet.
    bool insert(uint64_t key) {
        if (key == 0) key = 1;
        const size_t mask = m_slots.size() - 1;
        for (size_t i = static_cast<size_t>(key) & mask;; i = (i + 1) & mask) {
            if (m_slots[i] == key) return false;
            if (m_slots[i] == 0) {
                m_slots[i] = key;
                return true;
            }
        }
    }

private:
    std::vector<uint64_t> m_slots;
};

class SetBuilder {
public:
    explicit SetBuilder(PolylineSet& set) : m_set(set) {}
    void segment(const float* a, const float* b, uint8_t kind) {
        const size_t points = m_set.pointCount();
        const bool continues = m_open && m_lastKind == kind && points > 0 &&
                               std::equal(a, a + 3, &m_set.xyz[3 * (points - 1)]);
        if (!continues) {
            close();
            push(a, kind);
            m_open = true;
            m_lastKind = kind;
        }
        push(b, kind);
    }
    void close() {
        if (m_open) m_set.offsets.push_back(static_cast<int32_t>(m_set.pointCount()));
        m_open = false;
    }

private:
    void push(const float* p, uint8_t kind) {
        m_set.xyz.insert(m_set.xyz.end(), p, p + 3);
        m_set.kind.push_back(kind);
        m_set.bounds.add(Vec3(p[0], p[1], p[2]));
    }
    PolylineSet& m_set;
    bool m_open = false;
    uint8_t m_lastKind = 0;
};

// Level 0 of a chunk: the exact points, one polyline per run of moves of one kind.
PolylineSet exactLevel(const ToolpathData& data, const std::vector<uint8_t>& segmentKind,
                       uint32_t first, uint32_t last) {
    PolylineSet set;
    set.xyz.reserve(3 * (last - first + 1) + 48);
    set.kind.reserve(last - first + 1 + 16);
    SetBuilder builder(set);
    for (uint32_t s = first + 1; s <= last; ++s) {
        builder.segment(&data.xyz[3 * (s - 1)], &data.xyz[3 * s], segmentKind[s]);
    }
    builder.close();
    return set;
}

PolylineSet coarserLevel(const PolylineSet& finer, double tolerance, int window, uint64_t salt) {
    PolylineSet set;
    SetBuilder builder(set);
    std::vector<uint32_t> kept;
    for (size_t line = 0; line < finer.polylineCount(); ++line) {
        const auto begin = static_cast<size_t>(finer.offsets[line]);
        const auto end = static_cast<size_t>(finer.offsets[line + 1]);
        if (end - begin < 2) continue;
        const uint8_t kind = finer.kind[begin];
        kept.clear();
        simplifyPolyline(finer.xyz.data(), begin, end, tolerance, window, kept, salt);
        for (size_t k = 1; k < kept.size(); ++k) {
            builder.segment(&finer.xyz[3 * kept[k - 1]], &finer.xyz[3 * kept[k]], kind);
        }
        builder.close();
    }
    return set;
}

// Drops the segments whose end points, snapped to a grid of the level's tolerance, match a
// segment kept before (in this or an earlier chunk), and the ones shorter than a grid step.
PolylineSet withoutRepeats(const PolylineSet& source, double tolerance, KeySet& seen) {
    PolylineSet set;
    SetBuilder builder(set);
    const double inverse = 1.0 / tolerance;
    for (size_t line = 0; line < source.polylineCount(); ++line) {
        const auto begin = static_cast<size_t>(source.offsets[line]);
        const auto end = static_cast<size_t>(source.offsets[line + 1]);
        const uint8_t kind = source.kind[begin];
        for (size_t k = begin + 1; k < end; ++k) {
            const float* a = &source.xyz[3 * (k - 1)];
            const float* b = &source.xyz[3 * k];
            int64_t qa[3] = {quantize(a[0], inverse), quantize(a[1], inverse),
                             quantize(a[2], inverse)};
            int64_t qb[3] = {quantize(b[0], inverse), quantize(b[1], inverse),
                             quantize(b[2], inverse)};
            if (std::lexicographical_compare(qb, qb + 3, qa, qa + 3)) std::swap(qa, qb);
            uint64_t key = mix(0x51ed270b27u, kind);
            for (int i = 0; i < 3; ++i)
                key = mix(key, static_cast<uint64_t>(qa[i]));
            for (int i = 0; i < 3; ++i)
                key = mix(key, static_cast<uint64_t>(qb[i]));
            if (std::equal(qa, qa + 3, qb) || !seen.insert(key)) {
                builder.close();
                continue;
            }
            builder.segment(a, b, kind);
        }
        builder.close();
    }
    return set;
}

template <typename Fn>
void parallelFor(size_t count, unsigned threads, Fn fn) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<size_t>(threads, count));
    if (threads <= 1) {
        for (size_t i = 0; i < count; ++i)
            fn(i);
        return;
    }
    std::vector<std::thread> pool;
    pool.reserve(threads);
    for (unsigned t = 0; t < threads; ++t) {
        pool.emplace_back([&, t] {
            for (size_t i = t; i < count; i += threads)
                fn(i);
        });
    }
    for (auto& thread : pool)
        thread.join();
}

}  // namespace

void simplifyPolyline(const float* xyz, size_t begin, size_t end, double tolerance, int window,
                      std::vector<uint32_t>& kept, uint64_t salt) {
    if (end <= begin) return;
    kept.push_back(static_cast<uint32_t>(begin));
    if (end - begin == 1) return;
    const double tol2 = tolerance * tolerance;
    // Windows end at points chosen by their coordinates (content-defined: a point whose bits
    // hash to 0 modulo `window`), so repeated passes over the same points, in either direction,
    // get the same breaks and simplify to the same segments; a window never exceeds 4 x window.
    const auto spacing = static_cast<uint64_t>(std::max(2, window));
    const size_t longest = 4 * static_cast<size_t>(spacing);
    std::vector<std::pair<size_t, size_t>> stack;
    std::vector<uint32_t> inner;
    size_t w0 = begin;
    while (w0 + 1 < end) {
        size_t w1 = w0 + 1;
        while (w1 + 1 < end && w1 - w0 < longest) {
            uint32_t bits[3];
            std::memcpy(bits, &xyz[3 * w1], sizeof bits);
            uint64_t h = mix(mix(mix(0x9e37u + salt, bits[0]), bits[1]), bits[2]);
            if (h % spacing == 0) break;
            ++w1;
        }
        inner.clear();
        stack.clear();
        stack.emplace_back(w0, w1);
        while (!stack.empty()) {
            auto [a, b] = stack.back();
            stack.pop_back();
            double worst = -1.0;
            size_t index = a;
            for (size_t i = a + 1; i < b; ++i) {
                const double d = distanceToSegmentSq(&xyz[3 * i], &xyz[3 * a], &xyz[3 * b]);
                if (d > worst) {
                    worst = d;
                    index = i;
                }
            }
            if (worst > tol2) {
                inner.push_back(static_cast<uint32_t>(index));
                stack.emplace_back(a, index);
                stack.emplace_back(index, b);
            }
        }
        std::sort(inner.begin(), inner.end());
        kept.insert(kept.end(), inner.begin(), inner.end());
        kept.push_back(static_cast<uint32_t>(w1));
        w0 = w1;
    }
}

size_t ToolpathGeometry::segmentCount(size_t level) const {
    size_t n = 0;
    for (const auto& chunk : chunks) {
        if (!chunk.levels.empty()) {
            n += chunk.levels[std::min(level, chunk.levels.size() - 1)].segmentCount();
        }
    }
    return n;
}

size_t ToolpathGeometry::pointCount(size_t level) const {
    size_t n = 0;
    for (const auto& chunk : chunks) {
        if (!chunk.levels.empty()) {
            n += chunk.levels[std::min(level, chunk.levels.size() - 1)].pointCount();
        }
    }
    return n;
}

int chooseLevel(const std::vector<double>& tolerances, double mmPerPixel, double maxErrorPx) {
    int level = 0;
    const double allowed = mmPerPixel * maxErrorPx;
    if (!std::isfinite(allowed)) return 0;
    for (size_t k = 1; k < tolerances.size(); ++k) {
        if (tolerances[k] <= allowed) level = static_cast<int>(k);
    }
    return level;
}

ToolpathGeometry buildToolpathGeometry(const ToolpathData& data, const LodOptions& options) {
    ToolpathGeometry geometry;
    geometry.bounds = data.bounds;
    const double diagonal = data.bounds.diagonal();
    // Nominal tolerance per level (simplification and snapping) and the bound of the deviation
    // from the exact path that follows: each level simplifies the one before, so the errors
    // add up, and snapping a repeat onto a kept segment adds one nominal tolerance.
    std::vector<double> nominal{0.0};
    geometry.tolerances.push_back(0.0);
    if (diagonal > 0.0 && std::isfinite(diagonal)) {
        double tolerance = diagonal * options.finestRelative;
        double sum = 0.0;
        for (int k = 0; k < options.coarseLevels; ++k) {
            nominal.push_back(tolerance);
            sum += tolerance;
            geometry.tolerances.push_back(sum + tolerance);
            tolerance *= options.levelFactor;
        }
    }
    const size_t points = data.pointCount();
    if (points < 2) return geometry;

    // Kind of the segment reaching each point.
    std::vector<uint8_t> segmentKind(points, 0);
    for (size_t m = 0; m < data.moveCount(); ++m) {
        auto [b, e] = data.pointsOfMove(m);
        std::fill(segmentKind.begin() + static_cast<std::ptrdiff_t>(b),
                  segmentKind.begin() + static_cast<std::ptrdiff_t>(e),
                  static_cast<uint8_t>(data.kinds[m]));
    }
    const size_t perChunk = std::max<size_t>(options.pointsPerChunk, 2);
    const size_t segments = points - 1;
    const size_t chunkCount = (segments + perChunk - 1) / perChunk;
    geometry.chunks.resize(chunkCount);
    parallelFor(chunkCount, options.threads, [&](size_t c) {
        ToolpathChunk& chunk = geometry.chunks[c];
        chunk.firstPoint = static_cast<uint32_t>(c * perChunk);
        chunk.lastPoint = static_cast<uint32_t>(std::min(points - 1, (c + 1) * perChunk));
        chunk.levels.push_back(exactLevel(data, segmentKind, chunk.firstPoint, chunk.lastPoint));
        chunk.bounds = chunk.levels[0].bounds;
        for (size_t k = 1; k < geometry.tolerances.size(); ++k) {
            PolylineSet coarser =
                coarserLevel(chunk.levels[k - 1], nominal[k], options.simplifyWindow, k);
            // A level that saves little is not worth its memory or its build time (paths with
            // nothing to merge, such as a random walk): the finer level serves instead.
            if (coarser.segmentCount() * 10 > chunk.levels[k - 1].segmentCount() * 9 && k == 1)
                break;
            chunk.levels.push_back(std::move(coarser));
        }
    });
    // Repeats across the whole path (passes over the same place), level by level in parallel;
    // within a level the chunks go in path order so the first pass keeps its segments.
    parallelFor(geometry.tolerances.size() - 1, options.threads, [&](size_t index) {
        const size_t k = index + 1;
        size_t expected = 0;
        for (const auto& chunk : geometry.chunks) {
            if (k < chunk.levels.size()) expected += chunk.levels[k].segmentCount();
        }
        KeySet seen(expected / 2 + 16);
        for (auto& chunk : geometry.chunks) {
            if (k < chunk.levels.size()) {
                chunk.levels[k] = withoutRepeats(chunk.levels[k], nominal[k], seen);
            }
        }
    });
    return geometry;
}

}  // namespace kerf::graphics
