// What every fuzz target shares: a sink that checks every command and drops it, a sandbox folder
// per target, and a bounded run that answers every sync with the nominal position.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/canon/commands.h"
#include "core/canon/value_limits.h"
#include "core/interp/interpreter.h"

namespace kerf::fuzz {

// The interpreters promise that no command carries a non-finite or out-of-range number (the
// planner's soft-limit check relies on it): a command that does is a finding, reported as a crash.
class CheckingSink final : public canon::Sink {
public:
    void consume(const canon::Command& command) override {
        if (canon::findUnsafeValue(command.body)) __builtin_trap();
    }
};

// A folder in the temporary directory that programs may read and write.
inline std::filesystem::path sandbox(const std::string& name) {
    auto path = std::filesystem::temp_directory_path() / name;
    std::filesystem::create_directories(path);
    return path;
}

// Runs at most `budget` blocks.
inline void runBounded(interp::Interpreter& interpreter, uint64_t budget) {
    CheckingSink sink;
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
