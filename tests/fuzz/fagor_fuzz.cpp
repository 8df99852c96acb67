// libFuzzer target: any bytes as a FAGOR 8035 T program must be checked and, if clean, run for a
// bounded number of blocks without crashing, hanging or leaking. OPEN/WRITE and EXEC stay inside
// the sandbox folder; no tables are given, so none is written.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/interp/fagor/fagor_interpreter.h"
#include "core/machine/machine_loader.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const kerf::machine::MachineConfig machine = *kerf::machine::loadMachine("lathe");
    static const std::filesystem::path root = kerf::fuzz::sandbox("kerf_fuzz_fagor_root");
    kerf::program::SourceRegistry sources;
    kerf::fagor::FagorSettings settings;
    settings.machine = &machine;
    settings.ncRoot = root;
    kerf::fagor::FagorInterpreter interpreter(sources, settings);
    std::string text(reinterpret_cast<const char*>(data), size);
    if (!interpreter.loadText(std::move(text), (root / "FUZZ.PIM").string())) return 0;
    kerf::fuzz::runBounded(interpreter, 20000);
    return 0;
}
