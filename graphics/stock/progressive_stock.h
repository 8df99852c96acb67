#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "graphics/stock/stock_simulation.h"

namespace kerf::graphics {

// Material removal on a worker thread, for the HMI while a program runs. The caller (the UI or
// the sequencer) pushes canonical commands as they execute; the worker removes material and, at
// most every `publishInterval`, publishes a snapshot (shaded mesh and removed volume) that the UI
// picks up with latest() and swaps into the scene. No call blocks longer than a queue lock.
class ProgressiveStock {
public:
    struct Snapshot {
        std::shared_ptr<const Mesh> mesh;
        double removedVolumeMm3 = 0.0;
        size_t movesSimulated = 0;
        uint64_t version = 0;   // StockSimulation::version() the mesh shows
        uint64_t sequence = 0;  // increments with every snapshot
        bool finished = false;
    };

    explicit ProgressiveStock(
        StockOptions options, int meshMaxSide = 400,
        std::chrono::milliseconds publishInterval = std::chrono::milliseconds(100));
    ~ProgressiveStock();
    ProgressiveStock(const ProgressiveStock&) = delete;
    ProgressiveStock& operator=(const ProgressiveStock&) = delete;

    // Any thread; commands are applied in the order pushed.
    void setStart(const Pose& start);
    void push(const canon::Command& command);
    void push(std::vector<canon::Command> commands);
    // End of the stream: the worker finishes the simulation and publishes a final snapshot.
    void finish();

    // Latest published snapshot (never null; empty mesh before the first one).
    std::shared_ptr<const Snapshot> latest() const;
    // Waits for the final snapshot (tests, headless use); false on time-out.
    bool waitFinished(std::chrono::milliseconds timeout) const;
    size_t pendingCommands() const;

private:
    struct Item {
        enum class Kind : uint8_t { Command, Start, Finish } kind = Kind::Command;
        canon::Command command;
        Pose start;
    };
    void run();
    void publish(bool finished);

    StockSimulation m_simulation;
    int m_meshMaxSide;
    std::chrono::milliseconds m_interval;
    mutable std::mutex m_mutex;
    mutable std::condition_variable m_wake;
    std::deque<Item> m_queue;
    bool m_stop = false;
    std::shared_ptr<const Snapshot> m_latest;
    uint64_t m_sequence = 0;
    std::thread m_worker;  // last: starts after everything above exists
};

}  // namespace kerf::graphics
