#include "graphics/stock/progressive_stock.h"

#include <utility>

namespace kerf::graphics {

ProgressiveStock::ProgressiveStock(StockOptions options, int meshMaxSide,
                                   std::chrono::milliseconds publishInterval)
    : m_simulation(std::move(options)),
      m_meshMaxSide(meshMaxSide),
      m_interval(publishInterval),
      m_latest(std::make_shared<Snapshot>()),
      m_worker([this] { run(); }) {}

ProgressiveStock::~ProgressiveStock() {
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    m_worker.join();
}

void ProgressiveStock::setStart(const Pose& start) {
    {
        std::lock_guard lock(m_mutex);
        Item item;
        item.kind = Item::Kind::Start;
        item.start = start;
        m_queue.push_back(std::move(item));
    }
    m_wake.notify_all();
}

void ProgressiveStock::push(const canon::Command& command) {
    {
        std::lock_guard lock(m_mutex);
        m_queue.push_back(Item{Item::Kind::Command, command, Pose{}});
    }
    m_wake.notify_all();
}

void ProgressiveStock::push(std::vector<canon::Command> commands) {
    {
        std::lock_guard lock(m_mutex);
        for (auto& command : commands) {
            m_queue.push_back(Item{Item::Kind::Command, std::move(command), Pose{}});
        }
    }
    m_wake.notify_all();
}

void ProgressiveStock::finish() {
    {
        std::lock_guard lock(m_mutex);
        Item item;
        item.kind = Item::Kind::Finish;
        m_queue.push_back(std::move(item));
    }
    m_wake.notify_all();
}

std::shared_ptr<const ProgressiveStock::Snapshot> ProgressiveStock::latest() const {
    std::lock_guard lock(m_mutex);
    return m_latest;
}

bool ProgressiveStock::waitFinished(std::chrono::milliseconds timeout) const {
    std::unique_lock lock(m_mutex);
    return m_wake.wait_for(lock, timeout, [this] { return m_latest->finished; });
}

size_t ProgressiveStock::pendingCommands() const {
    std::lock_guard lock(m_mutex);
    return m_queue.size();
}

void ProgressiveStock::publish(bool finished) {
    auto snapshot = std::make_shared<Snapshot>();
    snapshot->mesh = std::make_shared<const Mesh>(m_simulation.mesh(m_meshMaxSide));
    snapshot->removedVolumeMm3 = m_simulation.removedVolumeMm3();
    snapshot->movesSimulated = m_simulation.movesSimulated();
    snapshot->version = m_simulation.version();
    snapshot->finished = finished;
    {
        std::lock_guard lock(m_mutex);
        snapshot->sequence = ++m_sequence;
        m_latest = std::move(snapshot);
    }
    m_wake.notify_all();
}

void ProgressiveStock::run() {
    auto lastPublish = std::chrono::steady_clock::now();
    uint64_t publishedVersion = 0;
    bool everPublished = false;
    std::vector<Item> batch;
    for (;;) {
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait_for(lock, m_interval, [this] { return m_stop || !m_queue.empty(); });
            if (m_stop) return;
            // Take a bounded batch so snapshots keep coming while a long program streams in.
            const size_t take = std::min<size_t>(m_queue.size(), 4096);
            batch.clear();
            for (size_t i = 0; i < take; ++i) {
                batch.push_back(std::move(m_queue.front()));
                m_queue.pop_front();
            }
        }
        bool finished = false;
        for (Item& item : batch) {
            if (item.kind == Item::Kind::Start) {
                m_simulation.setStart(item.start);
            } else if (item.kind == Item::Kind::Finish) {
                m_simulation.finish();
                finished = true;
            } else {
                m_simulation.consume(item.command);
            }
        }
        const auto now = std::chrono::steady_clock::now();
        const bool changed = m_simulation.version() != publishedVersion ||
                             (!everPublished && m_simulation.hasStock());
        if (finished || (changed && now - lastPublish >= m_interval)) {
            publish(finished);
            publishedVersion = m_simulation.version();
            everPublished = true;
            lastPublish = now;
        }
    }
}

}  // namespace kerf::graphics
