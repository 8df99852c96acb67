// The real TNC programs of the shared corpus: each one is checked and run (bounded) without a
// crash or hang. Files that are not valid TNC programs are listed with the reason; every other
// file must check without errors.
#include <algorithm>
#include <filesystem>
#include <map>

#include <gtest/gtest.h>

#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"
#include "test_paths.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class NullSink final : public canon::Sink {
public:
    void consume(const canon::Command&) override {}
};

// File name suffix -> why the file does not check clean.
const std::map<std::string, std::string> kKnownBad = {
    {"Sacrifice-Board__11.h", "post-processor writes CYCLE DEF instead of CYCL DEF"},
    {"Sacrifice-Board__912.h", "CYCLE DEF and coordinates written as 'nan'"},
    {"shimemcunha__12.h", "post-processor writes CYCLE DEF instead of CYCL DEF"},
    {"demo_pgm_template_cycle.H", "template with {0:+d} placeholders"},
    {"pgm_head_template.H", "fragment: its label \"end\" is in the foot template"},
    {"BewegBlv.klartext", "calls LBL 3, which the program does not define"},
    {"9030_de.klartext", "calls 90301_de.h, which is not in the corpus"},
    {"3170_de.klartext", "calls 31701_de.h, which is not in the corpus"},
    {"Plan-Beispiel.h", "calls TNC:\\Plan.h, which is not in the corpus"},
};

bool endsWith(const std::string& name, const std::string& suffix) {
    return name.size() >= suffix.size() &&
           name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool knownBad(const std::string& name) {
    for (const auto& [suffix, why] : kKnownBad) {
        if (endsWith(name, suffix)) return true;
    }
    return false;
}

TEST(Corpus, RealProgramsCheckAndRunWithoutCrashing) {
    const fs::path shared = test::sharedDir();
    ASSERT_FALSE(shared.empty()) << "shared corpus not found: set KERF_SHARED_DIR";
    const auto mill = *machine::loadMachine("mill");
    const fs::path state = test::uniqueTempDir("corpus_state");
    int programs = 0, clean = 0;
    for (const auto& entry : fs::directory_iterator(shared / "corpus" / "heidenhain")) {
        const std::string name = entry.path().filename().string();
        const std::string ext = entry.path().extension().string();
        if (ext != ".h" && ext != ".H" && ext != ".klartext") continue;
        ++programs;
        program::SourceRegistry sources;
        KlartextSettings settings;
        settings.machine = &mill;
        settings.ncRoot = entry.path().parent_path();
        settings.remanentFile = state / "qr.txt";
        KlartextInterpreter interpreter(sources, settings);
        const bool loaded = interpreter.load(entry.path());
        const bool errors = hasErrors(interpreter.diagnostics());
        EXPECT_EQ(errors, knownBad(name))
            << name << ": "
            << (interpreter.diagnostics().empty() ? std::string()
                                                  : interpreter.diagnostics().front().format());
        if (!errors) ++clean;
        if (!loaded) continue;
        NullSink sink;
        for (int slice = 0; slice < 100; ++slice) {
            auto status = interpreter.run(sink, 10000);
            if (status == interp::RunStatus::NeedsSync) {
                interp::WorldSnapshot world;
                world.position = interpreter.nominalPosition();
                interpreter.resume(world);
            } else if (status != interp::RunStatus::BudgetUsed) {
                break;
            }
        }
        bool unsupported = false;
        for (const Diagnostic& d : interpreter.diagnostics()) {
            unsupported =
                unsupported || (d.severity == Severity::Error && d.code == "not-supported");
        }
        // Every cycle they use runs, the obsolete 1 and 5 of 668 and BewegBlv too.
        EXPECT_FALSE(unsupported) << name;
    }
    EXPECT_EQ(programs, 29);  // 16 .h, 3 .H and 10 .klartext files in INDEX.md
    EXPECT_EQ(clean, programs - static_cast<int>(kKnownBad.size()));
    fs::remove_all(state);
}

}  // namespace
}  // namespace kerf::klartext
