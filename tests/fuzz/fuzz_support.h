// What every fuzz target shares: a sink that drops commands, a sandbox folder per target, and a
// bounded run that answers every sync with the nominal position.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/canon/commands.h"
#include "core/interp/interpreter.h"

namespace kerf::fuzz {

class NullSink final : public canon::Sink {
public:
    void consume(const canon::Command&) override {}
};

// A folder in the temporary directory that programs may read and write.
inline std::filesystem::path sandbox(const std::string& name) {
    auto path = std::filesystem::temp_directory_path() / name;
    std::filesystem::create_directories(path);
    return path;
}

// Runs at most `budget` blocks.
inline void runBounded(interp::Interpreter& interpreter, uint64_t budget) {
    NullSink sink;
    constexpr uint64_t kSlice = 1000;
    while (budget > 0) {
        auto status = interpreter.run(sink, kSlice);
        budget = budget > kSlice ? budget - kSlice : 0;
        if (status == interp::RunStatus::NeedsSync) {
            interp::WorldSnapshot world;
            world.position = interpreter.nominalPosition();
            interpreter.resume(world);
            continue;
        }
        if (status != interp::RunStatus::BudgetUsed) break;
    }
}

}  // namespace kerf::fuzz
