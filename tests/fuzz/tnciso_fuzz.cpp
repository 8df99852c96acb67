// libFuzzer target: any bytes as a TNC DIN/ISO program must be checked and, if clean, run for a
// bounded number of blocks without crashing, hanging or leaking.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/interp/tnciso/tnciso.h"
#include "core/machine/machine_loader.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const kerf::machine::MachineConfig machine = *kerf::machine::loadMachine("mill");
    static const std::filesystem::path root = kerf::fuzz::sandbox("kerf_fuzz_root");
    kerf::program::SourceRegistry sources;
    kerf::klartext::KlartextSettings settings;
    settings.machine = &machine;
    settings.ncRoot = root;
    kerf::tnciso::enableIso(settings, true);
    kerf::klartext::KlartextInterpreter interpreter(sources, settings);
    std::string text(reinterpret_cast<const char*>(data), size);
    if (!interpreter.loadText(std::move(text), (root / "FUZZ.I").string())) return 0;
    kerf::fuzz::runBounded(interpreter, 20000);
    return 0;
}
