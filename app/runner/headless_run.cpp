#include "app/runner/headless_run.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <ostream>

#include "app/runner/drive_output.h"
#include "app/runner/headless_operator.h"
#include "app/runner/motion_output.h"
#include "app/runner/output_guard.h"
#include "app/runner/picture_output.h"
#include "app/runner/run_report.h"
#include "app/runner/session.h"
#include "app/runner/soft_limit_gate.h"
#include "app/runner/stock_output.h"
#include "core/base/atomic_file.h"
#include "core/canon/tee_sink.h"
#include "core/canon/trace_printer.h"
#include "core/task/dry_run.h"
#include "motion/runtime/work_area_check.h"
#include "motion/sim/simulated_clock.h"

namespace kerf::app {

namespace {

constexpr uint64_t kBlocksPerSlice = 1u << 16;

void printDiagnostics(const DiagnosticList& diagnostics, std::ostream& out) {
    for (const Diagnostic& d : diagnostics)
        out << d.format() << '\n';
}

AxisMask axisMaskOf(const machine::MachineConfig& machine) {
    AxisMask mask = 0;
    for (char letter : machine.enabledAxisLetters()) {
        if (auto axis = axisFromLetter(letter)) mask |= axisBit(*axis);
    }
    return mask;
}

bool diameterByDefault(const machine::MachineConfig& machine) {
    const machine::AxisConfig* x = machine.axis('X');
    return x != nullptr && x->diameterMode;
}

Diagnostic blockLimitError(const RunOptions& options) {
    return task::blockLimitError(options.program.string(), options.maxBlocks,
                                 task::BlockLimitSource::CommandLine);
}

}  // namespace

int checkProgramCommand(const RunOptions& options, std::ostream& diagnostics) {
    HeadlessOperator screenOperator(options);
    auto session = openSession(options, false, screenOperator.screen(), false);
    if (auto refused = screenOperator.dialectProblem(session->program.dialect)) {
        diagnostics << refused->format() << '\n';
        return 1;
    }
    // The run of the check is task::runDry, the one the HMI's "Check program" makes, with the
    // work-area check `kerf run --motion` makes before anything moves.
    DiagnosticList runProblems;
    if (session->ready()) {
        const std::unique_ptr<task::MoveCheck> moves =
            motion::makeWorkAreaCheck(session->machine, session->workOffset);
        task::DryRunOptions dry;
        dry.maxBlocks = options.maxBlocks;
        dry.atSync = [&] {
            return !screenOperator.waiting() || screenOperator.answer(runProblems);
        };
        dry.moves = moves.get();
        const task::DryRunResult end = task::runDry(*session->program.interpreter, dry);
        if (end.end == task::DryRunEnd::BlockLimit) {
            if (screenOperator.active())
                screenOperator.noteBlockLimit(runProblems, options.maxBlocks);
            else
                runProblems.push_back(blockLimitError(options));
        }
        if (end.end == task::DryRunEnd::Refused) {
            const bool atMachineOrigin = session->workOffset.values == Pose{}.values;
            appendDiagnostics(
                runProblems,
                withWorkOffsetHint(task::moveRefusal(*moves, end.refusedAt, session->sources()),
                                   atMachineOrigin));
        }
    }
    DiagnosticList all = session->allDiagnostics();
    appendDiagnostics(all, runProblems);
    printDiagnostics(all, diagnostics);
    return hasErrors(all) ? 1 : 0;
}

int runProgramCommand(const RunOptions& options, std::ostream& diagnostics,
                      PictureOutputFactory makePicture) {
    // The check runs alongside execution unless the trace goes to a stream we cannot take back.
    const bool traceToStdout = options.traceFile && *options.traceFile == "-";
    HeadlessOperator screenOperator(options);  // a FAGOR user screen (--user-screen)
    auto session =
        openSession(options, !traceToStdout && !screenOperator.active(), screenOperator.screen());
    if (auto refused = screenOperator.dialectProblem(session->program.dialect)) {
        diagnostics << refused->format() << '\n';
        return 1;
    }
    if (DiagnosticList refused = outputsOverwritingInputs(options, session->inputs());
        !refused.empty()) {
        printDiagnostics(refused, diagnostics);
        return 1;
    }
    canon::PathStatistics statistics;
    DisplayModeTracker displayMode(diameterByDefault(session->machine));
    canon::TeeSink sinks;
    sinks.add(statistics);
    sinks.add(displayMode);
    StockOutput stock(options, *session);
    if (stock.active()) sinks.add(stock.sink());
    std::unique_ptr<PictureOutput> picture;
    DiagnosticList runProblems;
    if (options.png && makePicture != nullptr) {
        picture = makePicture(options, *session);
        sinks.add(picture->sink());
    } else if (options.png) {
        runProblems.push_back(Diagnostic::make(
            Severity::Error, "picture", options.png->string(), 0, 0,
            KERF_TR_NOOP("no picture: this program cannot draw (kerf-gui draws pictures)")));
    }
    DriveOutput drives(options, *session);
    if (drives.active()) sinks.add(drives.sink());
    MotionOutput motion(options, *session);
    if (motion.active()) sinks.add(motion.sink());
    // The report's machining time: the planner and the servo cycle in simulated time, those of
    // --motion when it runs, else a clock of their own (only for a report: it costs the
    // simulation).
    std::unique_ptr<task::MachiningClock> clock;
    if (options.reportFile && !motion.active()) {
        clock = motion::makeSimulatedClock(session->machine);
        sinks.add(*clock);
    }

    std::FILE* traceStream = nullptr;
    std::unique_ptr<canon::TracePrinter> trace;
    if (options.traceFile) {
        if (*options.traceFile == "-") {
            traceStream = stdout;
        } else {
            traceStream = std::fopen(options.traceFile->c_str(), "wb");
            if (traceStream == nullptr) {
                runProblems.push_back(Diagnostic::make(Severity::Error, "io",
                                                       options.traceFile->string(), 0, 0,
                                                       KERF_TR_NOOP("cannot write the trace")));
            }
        }
        if (traceStream != nullptr) {
            canon::TraceFormat format;
            format.axes = axisMaskOf(session->machine);
            const program::SourceRegistry* sources = &session->sources();
            format.fileName = [sources](uint32_t id) { return sources->displayName(id); };
            trace = std::make_unique<canon::TracePrinter>(traceStream, std::move(format));
            sinks.add(*trace);
        }
    }

    uint64_t blocks = 0;
    if (session->ready()) {
        interp::Interpreter& interpreter = *session->program.interpreter;
        statistics.setStart(interpreter.nominalPosition());
        stock.setStart(interpreter.nominalPosition());
        if (picture) picture->setStart(interpreter.nominalPosition());
        drives.setStart(interpreter.nominalPosition(), runProblems);
        motion.setStart(interpreter.nominalPosition());
        if (clock) clock->setStart(interpreter.nominalPosition());
        for (;;) {
            if (drives.stopped()) break;  // a drive fault ends the program
            if (motion.refused()) break;  // e.g. beyond a soft limit: nothing moved
            if (motion.halted()) break;   // an emergency stop ended the program
            const uint64_t left = options.maxBlocks - interpreter.blocksExecuted();
            interp::RunStatus status =
                interpreter.run(sinks, std::min(drives.blocksPerSlice(kBlocksPerSlice), left));
            if (status == interp::RunStatus::NeedsSync) {
                if (screenOperator.waiting() && !screenOperator.answer(runProblems)) break;
                // Without motion the machine is exactly where the program put it, and a probe
                // move touches at its programmed end point.
                interp::WorldSnapshot world;
                world.position = statistics.position();
                world.probeTriggered = true;
                world.probePosition = world.position;
                if (motion.active()) world = motion.drain();
                if (drives.active()) world = drives.drain();
                if (clock) clock->sync();
                interpreter.resume(world);
                continue;
            }
            if (status != interp::RunStatus::BudgetUsed) break;
            if (interpreter.blocksExecuted() >= options.maxBlocks && screenOperator.active()) {
                screenOperator.noteBlockLimit(runProblems, options.maxBlocks);
                break;
            }
            if (interpreter.blocksExecuted() >= options.maxBlocks) {
                runProblems.push_back(blockLimitError(options));
                break;
            }
        }
        blocks = interpreter.blocksExecuted();
    }
    if (trace && !trace->flush()) {
        runProblems.push_back(Diagnostic::make(Severity::Error, "io", options.traceFile->string(),
                                               0, 0, KERF_TR_NOOP("cannot write the trace")));
    }
    trace.reset();
    if (traceStream != nullptr && traceStream != stdout) std::fclose(traceStream);
    const bool rejected =
        session->program.interpreter && session->program.interpreter->checkFailed();
    canon::PathStatistics nothingRan;
    if (rejected) {
        // The program has errors: it counts as never started.
        blocks = 0;
        if (options.traceFile && !traceToStdout) {
            std::error_code ignored;
            std::filesystem::resize_file(*options.traceFile, 0, ignored);
        }
    }
    const canon::PathStatistics& results = rejected ? nothingRan : statistics;
    stock.finish(runProblems);
    if (picture) picture->finish(session->ready() && !rejected, stock, runProblems);
    drives.finish(session->ready() && !rejected, runProblems);
    motion.finish(session->ready() && !rejected, runProblems);
    double machiningTimeS = 0.0;
    if (session->ready() && !rejected) {
        if (clock) {
            clock->finish();
            machiningTimeS = clock->totalS();
        } else {
            machiningTimeS = motion.machiningTimeS();
        }
    }

    RunSummary summary;
    summary.diagnostics = session->allDiagnostics();
    appendDiagnostics(summary.diagnostics, runProblems);
    summary.ok = session->ready() && !rejected && !hasErrors(summary.diagnostics);
    summary.dialect = program::dialectName(session->program.dialect);
    summary.blocksExecuted = blocks;
    summary.xInDiameter = displayMode.xInDiameter();
    summary.machiningTimeS = machiningTimeS;
    summary.workOffset = session->workOffset;
    printDiagnostics(summary.diagnostics, diagnostics);
    if (screenOperator.active() && !traceToStdout) screenOperator.print(std::cout);

    if (options.reportFile) {
        nlohmann::json report = buildRunReport(summary, results, session->machine);
        stock.addToReport(report);
        if (picture) picture->addToReport(report);
        drives.addToReport(report, summary.xInDiameter);
        motion.addToReport(report, summary.xInDiameter);
        if (screenOperator.active()) screenOperator.addToReport(report);
        if (auto error = writeFileAtomically(*options.reportFile, reportText(report))) {
            diagnostics << error->format() << '\n';
            return 1;
        }
    }
    return summary.ok ? 0 : 1;
}

}  // namespace kerf::app
