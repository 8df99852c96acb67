#include "core/interp/fagor/fagor_interpreter.h"

#include <algorithm>

#include "core/base/translate.h"
#include "core/program/mapped_copy.h"

namespace kerf::fagor {

namespace {

// A table file in the NC root; none there is no table. A link that leads outside, a FIFO or a
// folder in its place is an error.
template <typename Table>
void loadTable(const program::NcRoot& root, const std::filesystem::path& path,
               std::optional<Table>& into, DiagnosticList& out) {
    std::error_code ignored;
    if (path.empty() || !std::filesystem::exists(std::filesystem::symlink_status(path, ignored)))
        return;
    auto bytes = root.read(path);
    auto table = bytes ? Table::parse(*bytes, path.string()) : bytes.error();
    if (!table) {
        out.push_back(table.error());
        return;
    }
    into = std::move(*table);
}

Pose sum(const Pose& a, const Pose& b) {
    Pose p = a;
    for (size_t i = 0; i < p.values.size(); ++i)
        p.values[i] += b.values[i];
    return p;
}

}  // namespace

FagorInterpreter::FagorInterpreter(program::SourceRegistry& sources, FagorSettings settings)
    : m_sources(sources),
      m_settings(std::move(settings)),
      m_root(m_settings.ncRoot.empty() ? std::filesystem::path(".") : m_settings.ncRoot,
             m_settings.runOutputs),
      m_parser(this),
      m_runner(this),
      m_compensation(m_output),
      m_shaper(m_compensation) {
    // A customisation program may nest five levels beyond its own (spec part 2 §6.8).
    if (m_settings.userScreen != nullptr) {
        m_settings.maxCallNesting = std::min(m_settings.maxCallNesting, 5);
    }
    loadTable(m_root, m_settings.toolOffsetFile, m_toolOffsets, m_diagnostics);
    loadTable(m_root, m_settings.zeroOffsetFile, m_zeroOffsets, m_diagnostics);
    loadTable(m_root, m_settings.toolFile, m_toolTable, m_diagnostics);
    if (m_zeroOffsets) {
        m_selection = m_zeroOffsets->selection();
        m_startOffset = sum(m_zeroOffsets->selectedOffset(), m_zeroOffsets->plcOffset());
    }
    if (m_selection == ZeroOffsetSelection{} &&
        m_settings.presetInMachine.values != Pose{}.values) {
        // No zero offset selected: the machine's workpiece origin acts as a G92 preset.
        m_selection.preset = true;
        m_selection.presetOffset = m_settings.presetInMachine;
        m_startOffset = m_settings.presetInMachine;
        if (m_zeroOffsets) m_startOffset = sum(m_startOffset, m_zeroOffsets->plcOffset());
    }
    m_offset = m_startOffset;
    if (m_settings.startInMachine) {
        for (size_t i = 0; i < m_position.values.size(); ++i)
            m_position.values[i] = m_settings.startInMachine->values[i] - m_startOffset.values[i];
    }
    m_output.setZones(&m_zones);
    m_output.setMachineOffset(m_startOffset);
    m_compensation.setCompMode(m_settings.compMode);
    resetModal();
    m_spindle.rpm = m_settings.startSpindleRpm;
    if (m_settings.machine != nullptr) {
        m_machineAxes = axisMaskOf(m_settings.machine->enabledAxisLetters());
    }
    const machine::AxisConfig* x =
        m_settings.machine != nullptr ? m_settings.machine->axis('X') : nullptr;
    m_streamDiameter = x != nullptr && x->diameterMode;
}

FagorInterpreter::~FagorInterpreter() {
    closeOpenProgram();  // first: it waits for the check, and writes only if it passed
    if (m_checkThread.joinable()) {
        m_checking->executionOffset.store(SIZE_MAX);
        m_checkThread.join();
    }
}

void FagorInterpreter::resetModal() {
    const FagorSettings& s = m_settings;
    ModalState m;
    m.motion = s.imoveLinear ? 1 : 0;
    m.plane = PlaneFrame::standard(s.iplane);
    m.planeG = s.iplane == Plane::XY ? 17 : s.iplane == Plane::ZX ? 18 : 19;
    m.inch = s.inches;
    m.incremental = s.incremental;
    const machine::AxisConfig* x = s.machine != nullptr ? s.machine->axis('X') : nullptr;
    m.diameter = s.diameter.value_or(x != nullptr && x->diameterMode);
    m.feed = s.feedPerRevolution ? FeedKind::PerRevolution : FeedKind::PerMinute;
    m.corner = s.roundCorner ? CornerKind::Round : CornerKind::Sharp;
    m_modal = m;
    m_polarOrigin = Vec2(0.0, 0.0);
    m_tool.radius = m_tool.data.radius;
    m_locks = canon::ControlLocks{};
    for (int i = 0; i < kAxisCount; ++i)
        m_output.setAxisScale(static_cast<Axis>(i), 1.0);
}

// ---- loading ---------------------------------------------------------------------------------

MaybeError FagorInterpreter::replaceFile(const std::filesystem::path& file,
                                         std::string_view content) {
    if (m_settings.writeFiles) return m_root.replace(file, content);
    // A dry run (kerf check) admits the write as a run would and leaves the file.
    if (MaybeError refused = m_root.admitWrite(file)) return refused;
    m_unwritten[file] = std::string(content);
    return std::nullopt;
}

bool FagorInterpreter::waitForCheck() {
    if (!m_checkThread.joinable()) return !m_checkFailed;
    m_checking->executionOffset.store(SIZE_MAX);
    m_checkThread.join();
    DiagnosticList found = m_checking->diagnostics;
    checkCalledPrograms(*m_checking, found);
    if (hasErrors(found)) {
        // The program would not have started: only the check's findings count.
        m_diagnostics.erase(
            m_diagnostics.begin() + static_cast<std::ptrdiff_t>(m_diagnosticsAtLoad),
            m_diagnostics.end());
        m_checkFailed = true;
        m_status = interp::RunStatus::Failed;
    }
    m_diagnostics.insert(m_diagnostics.begin() + static_cast<std::ptrdiff_t>(m_diagnosticsAtLoad),
                         found.begin(), found.end());
    return !m_checkFailed;
}

FagorProgram* FagorInterpreter::loadProgram(const std::filesystem::path& path, std::string* error,
                                            bool keepLabels) {
    for (auto& p : m_programs) {
        if (p->path == path) {
            if (keepLabels && !p->keepLabels && p.get() != m_checking) {
                p->keepLabels = true;
                checkProgram(*p);
            }
            return p.get();
        }
    }
    const auto unwritten = m_unwritten.find(path);
    auto source = unwritten != m_unwritten.end()
                      ? Expected<std::shared_ptr<const program::SourceText>>(
                            program::SourceText::fromString(unwritten->second, path.string()))
                      : m_root.loadProgram(path);
    if (!source) {
        if (error) *error = source.error().message();
        return nullptr;
    }
    auto program = std::make_unique<FagorProgram>();
    program->source = *source;
    program->path = path;
    program->fileId = m_sources.add(path.string());
    program->number = programNumberOf(path);
    program->machineAxes = m_machineAxes;
    program->userChannel = m_settings.userScreen != nullptr;
    program->keepLabels = keepLabels;
    checkProgram(*program);
    m_programs.push_back(std::move(program));
    return m_programs.back().get();
}

bool FagorInterpreter::load(const std::filesystem::path& path, CheckMode mode) {
    if (hasErrors(m_diagnostics)) return false;  // a table could not be read
    auto source = program::SourceText::load(path);
    if (!source) {
        appendDiagnostic(m_diagnostics, source.error());
        return false;
    }
    auto owned = std::make_unique<FagorProgram>();
    FagorProgram* program = owned.get();
    program->source = *source;
    program->path = path;
    program->fileId = m_sources.add(path.string());
    program->number = programNumberOf(path);
    program->machineAxes = m_machineAxes;
    program->userChannel = m_settings.userScreen != nullptr;
    m_programs.push_back(std::move(owned));
    m_diagnosticsAtLoad = m_diagnostics.size();
    if (mode == CheckMode::Background) {
        m_checking = program;
        program->followExecution = true;
        program->executionOffset.store(0);
        m_checkThread = std::thread([program] { checkProgram(*program); });
    } else {
        checkProgram(*program);
        DiagnosticList found = program->diagnostics;
        checkCalledPrograms(*program, found);
        appendDiagnostics(m_diagnostics, found);
        if (hasErrors(found)) return false;
    }
    enterProgram(program, BlockPosition{0, 1});
    m_status = interp::RunStatus::BudgetUsed;
    return true;
}

bool FagorInterpreter::loadText(std::string text, const std::string& path) {
    if (hasErrors(m_diagnostics)) return false;
    auto owned = std::make_unique<FagorProgram>();
    FagorProgram* program = owned.get();
    program->source = program::SourceText::fromString(std::move(text), path);
    program->path = path;
    program->fileId = m_sources.add(path);
    program->number = programNumberOf(path);
    program->machineAxes = m_machineAxes;
    program->userChannel = m_settings.userScreen != nullptr;
    checkProgram(*program);
    m_programs.push_back(std::move(owned));
    DiagnosticList found = program->diagnostics;
    checkCalledPrograms(*program, found);
    appendDiagnostics(m_diagnostics, found);
    if (hasErrors(found)) return false;
    enterProgram(program, BlockPosition{0, 1});
    m_status = interp::RunStatus::BudgetUsed;
    return true;
}

void FagorInterpreter::enterProgram(FagorProgram* program, const BlockPosition& at) {
    readFrom(program, at);
    m_firstLine = at.offset == 0;
    m_parameters.setOemAllowed(program->oem);
}

void FagorInterpreter::readFrom(FagorProgram* program, const BlockPosition& at) {
    m_program = program;
    std::string_view text = program->source->text();
    if (program->end < text.size()) text = text.substr(0, program->end);
    m_reader.emplace(text);
    m_reader->seek(at.offset, at.line);
    m_releasedBefore = at.offset;
    m_firstLine = false;
    m_jumped = true;
}

// ---- diagnostics -----------------------------------------------------------------------------

void FagorInterpreter::fail(const char* code, const char* messageTemplate,
                            std::vector<std::string> args) {
    Diagnostic d = Diagnostic::make(Severity::Error, code, m_sources.path(m_at.fileId), m_at.line,
                                    m_at.column, messageTemplate);
    d.args = std::move(args);
    appendDiagnostic(m_diagnostics, std::move(d));
    m_status = interp::RunStatus::Failed;
}

void FagorInterpreter::failAt(size_t offset, const Problem& problem) {
    m_at.column = program::columnOf(m_line.text, offset);
    fail(problem.code.c_str(), problem.messageTemplate.c_str(), problem.args);
}

void FagorInterpreter::warn(const char* code, const char* messageTemplate,
                            std::vector<std::string> args) {
    Diagnostic d = Diagnostic::make(Severity::Warning, code, m_sources.path(m_at.fileId), m_at.line,
                                    m_at.column, messageTemplate);
    d.args = std::move(args);
    appendDiagnostic(m_diagnostics, std::move(d));
}

bool FagorInterpreter::pathOk(const std::optional<interp::PathError>& error) {
    std::optional<interp::PathError> e = error ? error : m_output.takeError();
    reportRemovedLoops();
    if (!e) return true;
    Diagnostic d = Diagnostic::make(Severity::Error, e->code, m_sources.path(e->location.fileId),
                                    e->location.line, e->location.column, e->messageTemplate);
    d.args = e->args;
    appendDiagnostic(m_diagnostics, std::move(d));
    m_status = interp::RunStatus::Failed;
    return false;
}

void FagorInterpreter::outputValuesOk() {
    if (!m_output.failed()) return;
    auto error = m_output.takeError();
    // The first error stays the one reported.
    if (error && m_status != interp::RunStatus::Failed) (void)pathOk(error);
}

void FagorInterpreter::reportRemovedLoops() {
    for (const SourceLocation& at : m_compensation.takeRemovedLoops()) {
        appendDiagnostic(
            m_diagnostics,
            Diagnostic::make(
                Severity::Warning, "collision", m_sources.path(at.fileId), at.line, at.column,
                KERF_TR_NOOP("collision detection removed a loop of the compensated path")));
    }
}

void FagorInterpreter::emit(canon::CommandBody body) {
    // Commands carry the block, not the word (diagnostics do).
    const SourceLocation at{m_at.fileId, m_at.line, 1, m_at.blockNumber};
    m_shaper.addCommand(canon::Command{at, std::move(body)});
}

// ---- the run loop ----------------------------------------------------------------------------

interp::RunStatus FagorInterpreter::run(canon::Sink& sink, uint64_t blockBudget) {
    m_output.setTarget(&sink);
    if (m_status != interp::RunStatus::BudgetUsed) return m_status;
    if (!m_started) {
        m_started = true;
        m_output.reset(m_position);
        m_compensation.reset(m_position);
        const bool diameter = m_modal.diameter;
        m_modal.diameter = m_streamDiameter;
        setDiameter(diameter);
    }
    while (blockBudget-- > 0 && m_status == interp::RunStatus::BudgetUsed) {
        if (m_resumeBlock) {
            m_resumeBlock = false;
        } else {
            if (m_pendingInterrupt != 0) startPendingInterrupt();
            m_blockOffset = m_reader->offset();
            if (m_blockOffset >= m_releasedBefore + program::kTextReleaseStep) {
                // Every MiB read: tell the check how far the run is, and let the kernel drop
                // the text behind (a long program's mapped copy; a jump back reads it again).
                m_releasedBefore = m_blockOffset;
                if (m_program == m_checking && m_checkThread.joinable()) {
                    m_program->executionOffset.store(m_blockOffset);
                }
                program::releasePagesBefore(m_program->source->text(), m_blockOffset);
            }
            if (!m_reader->next(m_line, false)) {
                endOfText();
                continue;
            }
            ++m_blocks;
        }
        executeBlock();
        // A block that waits for the machine (G04 K0, G52, G75) is still done: an RPT range may
        // end with it.
        const bool done = m_status == interp::RunStatus::BudgetUsed ||
                          (m_status == interp::RunStatus::NeedsSync && !m_resumeBlock);
        if (done) afterBlock();
        outputValuesOk();
    }
    if (m_status == interp::RunStatus::Failed && waitForCheck()) {
        // The blocks before the error run; only the one that failed and those after it do not.
        (void)m_shaper.flush();
        (void)m_compensation.suspend();
    }
    outputValuesOk();
    return m_status;
}

void FagorInterpreter::executeBlock() {
    m_at = SourceLocation{m_program->fileId, m_line.firstLine, 1, -1};
    const bool firstLine = m_firstLine;
    m_firstLine = false;
    m_jumped = false;
    if (!m_parser.parse(m_line.text, firstLine, m_block)) {
        failAt(m_parser.problem().offset, m_parser.problem());
        return;
    }
    m_at.blockNumber = m_block.label;
    if ((m_block.skipMarks & m_settings.blockSkip) != 0) return;
    if (m_block.label >= 0) m_lastLabel = m_block.label;
    switch (m_block.kind) {
        case ParsedBlock::Kind::Iso:
            if (m_settings.userScreen != nullptr &&
                (m_block.iso.gCount != 0 || m_block.iso.hasOtherWords())) {
                fail("user-channel",
                     KERF_TR_NOOP("a customisation program runs in the user channel: it has no "
                                  "ISO blocks (no motion, no M, S, T)"));
                return;
            }
            executeIso(m_block.iso, repetitionOfBlock());
            break;
        case ParsedBlock::Kind::HighLevel: {
            const size_t begin = m_block.highLevelOffset;
            const uint8_t flags = m_syncedThisBlock ? 0 : statementFlags(m_block.highLevel);
            if ((flags & kPrepStop) != 0) {
                // Reading the machine stops block preparation: compensation is interrupted.
                preparationStop();
                if (m_status != interp::RunStatus::BudgetUsed) return;
            }
            if ((flags & kMachineData) != 0) {
                // Wait for the machine, then read this block again with its data.
                emit(canon::SyncPoint{canon::SyncReason::ReadPosition});
                if (!pathOk(m_compensation.suspend())) return;
                m_resumeBlock = true;
                m_syncedThisBlock = true;
                m_status = interp::RunStatus::NeedsSync;
                return;
            }
            m_syncedThisBlock = false;
            if (!m_runner.run(m_line.text, begin, begin + m_block.highLevel.size(),
                              m_block.repetition)) {
                if (m_status != interp::RunStatus::Failed)
                    failAt(m_runner.problem().offset, m_runner.problem());
            }
            break;
        }
        default:
            break;
    }
    if (m_block.endOfFile && m_status == interp::RunStatus::BudgetUsed && !m_jumped) {
        m_program->end = std::min(m_program->end, m_line.nextOffset);
        readFrom(m_program, BlockPosition{m_line.nextOffset, m_reader->line()});
    }
}

void FagorInterpreter::resume(const interp::WorldSnapshot& world) {
    if (m_status != interp::RunStatus::NeedsSync) return;
    m_world = world.position;
    if (m_pendingProbe) {
        probeResult(world);
        if (m_status == interp::RunStatus::Failed) return;
    }
    // The operator may have moved the machine at a stop: continue from where it really is.
    if ((world.position.xyz() - m_output.position().xyz()).norm() > 1e-6) {
        m_position = world.position;
        m_output.reset(world.position);
        m_compensation.reset(world.position);
    }
    m_status = interp::RunStatus::BudgetUsed;
}

bool FagorInterpreter::endOfText() {
    while (!m_frames.empty()) {
        const Frame top = m_frames.back();
        if (top.kind != Frame::Kind::Program) {
            fail("flow", top.kind == Frame::Kind::Repeat
                             ? KERF_TR_NOOP("the program ends before the last block of the RPT")
                             : KERF_TR_NOOP("the program ends inside a subroutine (RET missing)"));
            return false;
        }
        m_frames.pop_back();
        if (top.newLocals) m_parameters.popLocalLevel();
        readFrom(top.program, top.returnTo);
        m_parameters.setOemAllowed(top.program->oem);
        repeatEnd(top.callBlock);
        return true;
    }
    finish(-1);
    return false;
}

void FagorInterpreter::finish(int mCode) {
    if (!waitForCheck()) return;
    if (!pathOk(m_shaper.flush())) return;
    if (!pathOk(m_compensation.suspend())) return;
    if (!m_endEmitted) {
        if (mCode == 2 || mCode == 30) {
            // A general reset, and M05.
            if (m_spindle.direction != canon::SpindleDirection::Stopped) {
                m_spindle.direction = canon::SpindleDirection::Stopped;
                emitSpindle();
            }
            // The built-in machine's PLC switches the coolant off with the spindle (docs/fagor.md).
            if (m_mActive[8]) emit(canon::CoolantControl{false, false});
            // The reset applies to what runs next; the stream of this run ends here.
            resetModal();
        }
        emit(canon::ProgramStop{canon::StopKind::End, mCode});
        (void)m_compensation.suspend();
        m_endEmitted = true;
    }
    closeOpenProgram();
    auto save = [&](auto& table, const std::filesystem::path& path) {
        if (table && table->modified() && !path.empty()) {
            if (auto error = replaceFile(path, table->serialize())) {
                appendDiagnostic(m_diagnostics, *error);
            }
        }
    };
    save(m_toolOffsets, m_settings.toolOffsetFile);
    save(m_zeroOffsets, m_settings.zeroOffsetFile);
    save(m_toolTable, m_settings.toolFile);
    if (m_status != interp::RunStatus::Failed) m_status = interp::RunStatus::Finished;
}

}  // namespace kerf::fagor
