// libFuzzer target: any bytes as a FAGOR 8035 T program must be checked and, if clean, run for a
// bounded number of blocks without crashing, hanging or leaking.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "core/interp/fagor/fagor_interpreter.h"
#include "core/machine/machine_loader.h"

namespace {

class NullSink final : public kerf::canon::Sink {
public:
    void consume(const kerf::canon::Command&) override {}
};

const kerf::machine::MachineConfig& lathe() {
    static const kerf::machine::MachineConfig config = *kerf::machine::loadMachine("lathe");
    return config;
}

// OPEN/WRITE and EXEC stay inside this folder; no tables are given, so none is written.
const std::filesystem::path& root() {
    static const std::filesystem::path path = [] {
        auto p = std::filesystem::temp_directory_path() / "kerf_fuzz_fagor_root";
        std::filesystem::create_directories(p);
        return p;
    }();
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    kerf::program::SourceRegistry sources;
    kerf::fagor::FagorSettings settings;
    settings.machine = &lathe();
    settings.ncRoot = root();
    kerf::fagor::FagorInterpreter interpreter(sources, settings);
    std::string text(reinterpret_cast<const char*>(data), size);
    if (!interpreter.loadText(std::move(text), (root() / "FUZZ.PIM").string())) return 0;
    NullSink sink;
    uint64_t budget = 20000;
    while (budget > 0) {
        auto status = interpreter.run(sink, 1000);
        budget = budget > 1000 ? budget - 1000 : 0;
        if (status == kerf::interp::RunStatus::NeedsSync) {
            kerf::interp::WorldSnapshot world;
            world.position = interpreter.nominalPosition();
            interpreter.resume(world);
            continue;
        }
        if (status != kerf::interp::RunStatus::BudgetUsed) break;
    }
    return 0;
}
