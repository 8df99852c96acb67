#include "run_program.h"

#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/tnciso/tnciso.h"
#include "core/machine/machine_loader.h"
#include "core/program/source_registry.h"

namespace kerf::ui::test {

namespace {

class FeedRecorder : public canon::Sink {
public:
    void consume(const canon::Command& command) override {
        if (const auto* line = std::get_if<canon::LinearMove>(&command.body)) {
            feedZ.push_back(line->target[Axis::Z]);
            feedXY.push_back({line->target[Axis::X], line->target[Axis::Y]});
        }
    }
    std::vector<double> feedZ;
    std::vector<std::array<double, 2>> feedXY;
};

ProgramRun runProgram(const std::string& text, bool iso) {
    ProgramRun run;
    const auto machine = machine::loadMachine("mill");
    if (!machine) return run;
    program::SourceRegistry sources;
    klartext::KlartextSettings settings;
    settings.machine = &*machine;
    if (iso) tnciso::enableIso(settings, true);
    klartext::KlartextInterpreter interpreter(sources, settings);
    FeedRecorder recorder;
    if (interpreter.loadText(text, iso ? "RUN.I" : "RUN.H")) {
        for (;;) {
            const interp::RunStatus status = interpreter.run(recorder, 1000);
            if (status == interp::RunStatus::NeedsSync) {
                interp::WorldSnapshot world;
                world.position = interpreter.nominalPosition();
                interpreter.resume(world);
                continue;
            }
            if (status == interp::RunStatus::BudgetUsed) continue;
            run.finished = status == interp::RunStatus::Finished;
            break;
        }
    }
    for (const Diagnostic& d : interpreter.diagnostics()) {
        if (d.severity == Severity::Error) run.diagnostics.push_back(d);
    }
    run.feedZ = recorder.feedZ;
    run.feedXY = recorder.feedXY;
    return run;
}

}  // namespace

ProgramRun runKlartextProgram(const std::string& text) {
    return runProgram(text, false);
}

ProgramRun runIsoProgram(const std::string& text) {
    return runProgram(text, true);
}

}  // namespace kerf::ui::test
