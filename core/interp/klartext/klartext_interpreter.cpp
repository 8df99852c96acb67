#include "core/interp/klartext/klartext_interpreter.h"

#include <algorithm>
#include <set>

#include "core/base/translate.h"
#include "core/interp/klartext/statement_axes.h"
#include "core/program/mapped_copy.h"

namespace kerf::klartext {

// Gives formulas read access to the Q parameters and system strings.
class KlartextInterpreter::Environment final : public FormulaEnvironment {
public:
    explicit Environment(KlartextInterpreter& owner) : m_owner(owner) {}
    double number(QRef ref) override { return m_owner.m_q.get(ref); }
    const std::string& string(uint16_t index) override { return m_owner.m_q.getString(index); }
    bool stringDefined(uint16_t index) override { return m_owner.m_q.stringDefined(index); }
    std::optional<std::string> systemString(int id, int nr) override {
        if (id == 10010 && !m_owner.m_levels.empty()) {
            const ProgramFile* program = m_owner.m_levels.back().program;
            if (nr == 1) return program->source->path();   // program path
            if (nr == 2) return program->folder.string();  // its folder
        }
        return std::nullopt;
    }

private:
    KlartextInterpreter& m_owner;
};

KlartextInterpreter::KlartextInterpreter(program::SourceRegistry& sources,
                                         KlartextSettings settings)
    : m_sources(sources),
      m_settings(std::move(settings)),
      m_root(m_settings.ncRoot.empty() ? std::filesystem::path(".") : m_settings.ncRoot,
             m_settings.runOutputs),
      m_environment(std::make_unique<Environment>(*this)),
      m_parser(m_environment.get()),
      m_path(m_out) {
    m_spindleSpeed = m_settings.startSpindleRpm;
    m_spindle = m_settings.startSpindle;
    if (m_settings.machine != nullptr) {
        m_machineAxes = axisMaskOf(m_settings.machine->enabledAxisLetters());
        if (auto axis = axisFromLetter(m_settings.machine->toolAxis)) m_toolAxis = *axis;
        m_kinematics = machine::TableKinematics::of(*m_settings.machine);
    }
    m_cuts.setMachine(m_settings.machine);
    m_programmed = m_settings.startPosition;
    if (m_settings.basicRotationDeg != 0.0) {
        // The preset's basic rotation turns the working plane from the first block on.
        m_basicRotationDeg = m_settings.basicRotationDeg;
        m_frame.setRotation(m_basicRotationDeg, false, workingPlane());
        m_programmed = m_frame.toProgram(m_settings.startPosition);
    }
    m_path.reset(m_programmed);
    if (!m_settings.remanentFile.empty()) {
        if (auto error = m_q.loadRemanent(m_settings.remanentFile)) {
            appendDiagnostic(m_diagnostics, *error);
            // Nothing runs (load() refuses) and nothing is written: the file stays for the
            // operator to repair.
            m_checkFailed = true;
        }
    }
}

KlartextInterpreter::~KlartextInterpreter() {
    if (m_checkThread.joinable()) {
        m_checking->executionOffset.store(SIZE_MAX);
        m_checkThread.join();
    }
}

bool KlartextInterpreter::waitForCheck() {
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

// ---- loading ---------------------------------------------------------------------------------

ProgramFile* KlartextInterpreter::loadProgram(const std::filesystem::path& path, std::string* error,
                                              Origin origin, bool check) {
    for (auto& p : m_programs) {
        if (p->source->path() == path.string()) return p.get();
    }
    auto source =
        origin == Origin::Main ? program::SourceText::load(path) : m_root.loadProgram(path);
    if (!source) {
        if (error) *error = source.error().message();
        return nullptr;
    }
    auto program = std::make_unique<ProgramFile>();
    program->source = *source;
    program->fileId = m_sources.add(path.string());
    program->folder = path.parent_path();
    program->machineAxes = m_machineAxes;
    program->tools = m_settings.tools;
    if (isIsoProgram(path, origin)) program->syntax = &m_settings.isoSyntax;
    program->mainProgram = origin == Origin::Main;
    if (check) checkProgram(*program);
    m_programs.push_back(std::move(program));
    return m_programs.back().get();
}

bool KlartextInterpreter::load(const std::filesystem::path& path, CheckMode mode) {
    if (m_checkFailed) return false;  // the QR file could not be read
    std::string error;
    ProgramFile* program = loadProgram(path, &error, Origin::Main, mode == CheckMode::Inline);
    if (program == nullptr) {
        appendDiagnostic(m_diagnostics,
                         Diagnostic::make(Severity::Error, "io", path.string(), 0, 0,
                                          KERF_TR_NOOP("cannot read the program: {1}"), error));
        return false;
    }
    m_diagnosticsAtLoad = m_diagnostics.size();
    if (mode == CheckMode::Background) {
        program->inch = programUsesInch(*program);
        m_checking = program;
        program->followExecution = true;
        program->executionOffset.store(0);
        m_checkThread = std::thread([program] { checkProgram(*program); });
    } else {
        DiagnosticList found = program->diagnostics;
        checkCalledPrograms(*program, found);
        appendDiagnostics(m_diagnostics, found);
        if (hasErrors(found)) return false;
    }
    startLevel(program, 0, 0);
    m_status = interp::RunStatus::BudgetUsed;
    return true;
}

bool KlartextInterpreter::loadText(std::string text, const std::string& path) {
    if (m_checkFailed) return false;  // the QR file could not be read
    auto program = std::make_unique<ProgramFile>();
    program->source = program::SourceText::fromString(std::move(text), path);
    program->fileId = m_sources.add(path);
    program->folder = std::filesystem::path(path).parent_path();
    program->machineAxes = m_machineAxes;
    program->tools = m_settings.tools;
    if (isIsoProgram(path, Origin::Main)) program->syntax = &m_settings.isoSyntax;
    program->mainProgram = true;
    checkProgram(*program);
    DiagnosticList found = program->diagnostics;
    checkCalledPrograms(*program, found);
    appendDiagnostics(m_diagnostics, found);
    bool ok = !hasErrors(found);
    m_programs.push_back(std::move(program));
    if (!ok) return false;
    startLevel(m_programs.back().get(), 0, 0);
    m_status = interp::RunStatus::BudgetUsed;
    return true;
}

bool KlartextInterpreter::isIsoProgram(const std::filesystem::path& path, Origin origin) const {
    if (!m_settings.isoSyntax) return false;
    if (origin == Origin::Main) return m_settings.mainProgramIso;
    const std::string extension = path.extension().string();
    return extension == ".I" || extension == ".i";
}

BlockSyntax& KlartextInterpreter::parserFor(const ProgramFile& program,
                                            std::unique_ptr<BlockSyntax>& own) {
    if (program.syntax == nullptr) return m_parser;
    own = (*program.syntax)(m_environment.get());
    return *own;
}

void KlartextInterpreter::selectProgram(const ProgramFile& program) {
    if (program.syntax == nullptr) {
        m_activeParser = &m_parser;
    } else {
        if (!m_isoParser) m_isoParser = (*program.syntax)(m_environment.get());
        m_activeParser = m_isoParser.get();
    }
    m_reader.emplace(program.source->text(), m_activeParser);
}

void KlartextInterpreter::startLevel(ProgramFile* program, size_t returnOffset,
                                     uint32_t returnLine) {
    Level level;
    level.program = program;
    level.returnOffset = returnOffset;
    level.returnLine = returnLine;
    level.inch = program->inch;
    m_levels.push_back(level);
    m_inch = program->inch;
    selectProgram(*program);
    m_activeParser->startProgram();
    m_releasedBefore = 0;
}

// ---- diagnostics -----------------------------------------------------------------------------

Diagnostic KlartextInterpreter::diagnosticAt(Severity severity, const char* code,
                                             const char* messageTemplate,
                                             std::vector<std::string> args) const {
    Diagnostic d;
    d.severity = severity;
    d.code = code;
    d.messageTemplate = messageTemplate;
    d.args = std::move(args);
    d.file = m_sources.path(m_at.fileId);
    d.line = m_at.line;
    d.column = m_at.column;
    return d;
}

MaybeError KlartextInterpreter::replaceFile(const std::filesystem::path& file,
                                            std::string_view content) const {
    // A dry run (the editor's check) admits the write as a run would and leaves the file.
    if (!m_settings.writeFiles) return m_root.admitWrite(file);
    return m_root.replace(file, content);
}

void KlartextInterpreter::fail(const char* code, const char* messageTemplate,
                               std::vector<std::string> args) {
    appendDiagnostic(m_diagnostics,
                     diagnosticAt(Severity::Error, code, messageTemplate, std::move(args)));
    m_status = interp::RunStatus::Failed;
}

void KlartextInterpreter::warn(const char* code, const char* messageTemplate,
                               std::vector<std::string> args) {
    appendDiagnostic(m_diagnostics,
                     diagnosticAt(Severity::Warning, code, messageTemplate, std::move(args)));
}

bool KlartextInterpreter::checkPathError(const std::optional<interp::PathError>& error) {
    if (!error) return true;
    Diagnostic d;
    d.severity = Severity::Error;
    d.code = error->code;
    d.messageTemplate = error->messageTemplate;
    d.args = error->args;
    d.file = m_sources.path(error->location.fileId);
    d.line = error->location.line;
    d.column = error->location.column;
    appendDiagnostic(m_diagnostics, std::move(d));
    m_status = interp::RunStatus::Failed;
    return false;
}

void KlartextInterpreter::reportCollisions() {
    for (const SourceLocation& at : m_cuts.takeCollisions()) {
        Diagnostic d;
        d.severity = Severity::Warning;
        d.code = "collision";
        d.messageTemplate =
            KERF_TR_NOOP("collision: a rapid move runs into the material of the blank");
        d.file = m_sources.path(at.fileId);
        d.line = at.line;
        d.column = at.column;
        appendDiagnostic(m_diagnostics, std::move(d));
    }
}

bool KlartextInterpreter::outputValuesOk() {
    reportCollisions();
    auto error = m_out.takeError();
    if (!error) error = m_path.takeSpaceError();
    if (!error) return true;
    if (m_status == interp::RunStatus::Failed) return false;  // the first error stays the one
    return checkPathError(error);
}

void KlartextInterpreter::emit(canon::CommandBody body) {
    activePath().addCommand(canon::Command{m_at, std::move(body)});
}

// ---- the run loop ----------------------------------------------------------------------------

interp::RunStatus KlartextInterpreter::run(canon::Sink& sink, uint64_t blockBudget) {
    m_out.setTarget(&m_cuts);
    m_cuts.setTarget(&sink);
    if (m_status != interp::RunStatus::BudgetUsed) return m_status;
    if (!m_started) {
        m_started = true;
        m_path.reset(m_frame.toWorkpiece(m_programmed));
        if (m_settings.startPositionKnown)
            m_cuts.setPosition(m_frame.toWorkpiece(m_programmed).xyz());
    }
    while (blockBudget-- > 0 && m_status == interp::RunStatus::BudgetUsed) {
        if (m_touchReplay) {
            // The probing block again, with one more latched touch; not counted again.
            passTouching();
            outputValuesOk();
            continue;
        }
        m_blockOffset = m_reader->offset();
        if (m_blockOffset >= m_releasedBefore + program::kTextReleaseStep) {
            // Every MiB read: tell the check how far the run is, and let the kernel drop the
            // text behind (a long program's mapped copy; a jump back reads it again).
            m_releasedBefore = m_blockOffset;
            ProgramFile& program = *m_levels.back().program;
            if (&program == m_checking && m_checkThread.joinable()) {
                program.executionOffset.store(m_blockOffset);
            }
            program::releasePagesBefore(program.source->text(), m_blockOffset);
        }
        if (!m_reader->next(m_line)) {
            endOfProgram(false);
            outputValuesOk();
            continue;
        }
        ++m_blocks;
        m_cycleMovesInBlock = 0;
        const ProgramFile& program = *m_levels.back().program;
        m_at = SourceLocation{program.fileId, m_line.firstLine, 1, -1};
        if (!m_activeParser->parse(m_line, m_block)) {
            // The syntax was checked on load, so this is an evaluation error (division by zero,
            // a function outside its domain ...).
            const ParseProblem& p = m_activeParser->problem();
            m_at.line = m_line.lineAt(p.offset);
            m_at.column = m_line.columnAt(p.offset);
            fail(p.code.c_str(), p.messageTemplate.c_str(), p.args);
            break;
        }
        m_at.blockNumber = m_block.blockNumber;
        m_currentM.count = 0;  // M functions are only read up to the count (hasM)
        if (m_block.hidden && m_settings.blockSkip) continue;
        execute(m_block.statement);
        // The rest of a DIN/ISO block runs unless the first part stopped, jumped or called.
        for (size_t i = 0; i < m_block.more.size() && m_status == interp::RunStatus::BudgetUsed &&
                           m_reader->offset() == m_line.nextOffset;
             ++i) {
            execute(m_block.more[i]);
        }
        outputValuesOk();
    }
    if (m_status == interp::RunStatus::Failed && waitForCheck()) {
        // The blocks before the error run; only the one that failed and those after it do not.
        (void)m_path.flush();
    }
    outputValuesOk();
    m_out.setTarget(nullptr);
    m_cuts.setTarget(nullptr);
    return m_status;
}

void KlartextInterpreter::resume(const interp::WorldSnapshot& world) {
    if (m_status == interp::RunStatus::NeedsSync && touchHandedToMachine()) {
        resumeTouch(world);
        return;
    }
    if (m_status != interp::RunStatus::NeedsSync || !m_pendingSync) return;
    PendingSync pending = *m_pendingSync;
    m_pendingSync.reset();
    // The operator may have moved the machine at a stop: continue from where it really is.
    if ((world.position.xyz() - m_path.machinePosition().xyz()).norm() > 1e-6) {
        m_path.resetToMachine(world.position);
        m_programmed = programOfPath(m_path.toolPosition());
        m_cuts.setPosition(std::nullopt);
    }
    if (pending.id == 0) {
        m_status = interp::RunStatus::BudgetUsed;
        return;
    }
    SysRead read;
    read.id = pending.id;
    read.nr = pending.nr;
    read.idx = pending.idx;
    read.hasIdx = true;
    int axis = pending.idx - 1;
    double value = 0.0;
    if (axis >= 0 && axis < kAxisCount) {
        const auto i = static_cast<size_t>(axis);
        if (pending.id == 240) {
            // REF: machine coordinates of the tool tip.
            value = world.position.values[i] + m_settings.presetInMachine.values[i];
        } else {
            // The active coordinate system: through the inverse of the transformations; with
            // TCPM the program counts the tool tip on the part, not the axes.
            value = m_frame.toProgram(m_tcpm ? tipOf(world.position) : world.position).values[i];
        }
    }
    m_q.set(pending.target, value / lengthScale());
    m_status = interp::RunStatus::BudgetUsed;
}

bool KlartextInterpreter::endOfProgram(bool explicitEnd) {
    finishFk();
    if (m_status == interp::RunStatus::Failed) return false;
    if (m_levels.size() > 1) {
        // Back to the calling program after its CALL PGM block.
        Level finished = m_levels.back();
        m_levels.pop_back();
        m_q.popLocalLevel();
        size_t level = m_levels.size() - 1;
        while (!m_frames.empty() && m_frames.back().level > level)
            m_frames.pop_back();
        const Level& caller = m_levels.back();
        m_inch = caller.inch;
        selectProgram(*caller.program);
        m_releasedBefore = 0;
        m_reader->seek(finished.returnOffset, finished.returnLine);
        if (!m_pointRuns.empty() && m_pointRuns.back().callerLevel == m_levels.size()) {
            returnFromPointProgram();
        }
        return true;
    }
    if (!explicitEnd) {
        // Ran off the end of the file without END PGM (the check warned about it).
    }
    finish(true, -1);
    return false;
}

void KlartextInterpreter::finish(bool emitEnd, int mCode) {
    if (!waitForCheck()) return;
    if (!checkPathError(m_path.flush()) || !checkPathError(m_path.setLookAhead(0))) return;
    if (emitEnd && !m_endEmitted) {
        // An MDI block's end leaves the machine as it is, unless the block is M2/M30, which
        // switch off what may have run before it (the block's own program does not know that).
        const bool mdiEnd = m_settings.mdi && mCode != 2 && mCode != 30;
        if (!mdiEnd && (m_spindle != canon::SpindleDirection::Stopped || m_settings.mdi)) {
            emit(canon::SpindleControl{canon::SpindleDirection::Stopped, m_spindleSpeed});
            m_spindle = canon::SpindleDirection::Stopped;
        }
        if (!mdiEnd && (m_coolant || m_settings.mdi)) {
            emit(canon::CoolantControl{false, false});
            m_coolant = false;
        }
        emit(canon::ProgramStop{canon::StopKind::End, mCode});
        m_endEmitted = true;
    }
    // A dry run (kerf check, the editor's check) reads the QR parameters and keeps them.
    if (m_settings.writeFiles && m_q.remanentChanged() && !m_settings.remanentFile.empty()) {
        if (auto error = m_q.saveRemanent(m_settings.remanentFile))
            appendDiagnostic(m_diagnostics, *error);
    }
    if (m_status != interp::RunStatus::Failed) m_status = interp::RunStatus::Finished;
}

// ---- labels and calls ------------------------------------------------------------------------

void KlartextInterpreter::jumpTo(const LabelPosition& position) {
    m_reader->seek(position.offset, position.line);
}

const LabelPosition* KlartextInterpreter::resolveLabel(const LabelTarget& target) {
    if (!waitForCheck()) return nullptr;
    const ProgramFile& program = *m_levels.back().program;
    const LabelPosition* position = nullptr;
    std::string shown;
    if (target.number) {
        position = program.findLabel(*target.number);
        shown = std::to_string(*target.number);
    } else if (target.name) {
        position = program.findLabel(*target.name);
        shown = "\"" + *target.name + "\"";
    } else if (target.stringParameter) {
        const std::string& name = m_q.getString(*target.stringParameter);
        position = program.findLabel(name);
        shown = "\"" + name + "\" (QS" + std::to_string(*target.stringParameter) + ")";
    }
    if (position == nullptr) fail("label", KERF_TR_NOOP("label {1} is not defined"), {shown});
    return position;
}

void KlartextInterpreter::callLabel(const CallLabel& call) {
    const size_t level = m_levels.size() - 1;
    if (!m_frames.empty() && m_frames.back().level == level &&
        m_frames.back().callOffset == m_blockOffset) {
        // Execution came back to the CALL block of a program section repeat.
        LabelFrame& frame = m_frames.back();
        if (frame.remaining > 0) {
            --frame.remaining;
            jumpTo(frame.target);
        } else {
            m_frames.pop_back();
        }
        return;
    }
    const LabelPosition* target = resolveLabel(call.target);
    if (target == nullptr) return;
    if (static_cast<int>(m_frames.size()) >= m_settings.maxLabelNesting) {
        fail("nesting", KERF_TR_NOOP("subprograms nested deeper than {1} levels"),
             {std::to_string(m_settings.maxLabelNesting)});
        return;
    }
    LabelFrame frame;
    frame.level = level;
    frame.callOffset = m_blockOffset;
    frame.target = *target;
    frame.returnOffset = m_reader->offset();
    frame.returnLine = m_reader->line();
    frame.remaining = std::max(1, call.repeat) - 1;
    m_frames.push_back(frame);
    jumpTo(*target);
}

void KlartextInterpreter::returnFromLabel() {
    const size_t level = m_levels.size() - 1;
    if (m_frames.empty() || m_frames.back().level != level) return;  // LBL 0 as a plain marker
    LabelFrame& frame = m_frames.back();
    if (frame.remaining > 0) {
        --frame.remaining;
        jumpTo(frame.target);
        return;
    }
    m_reader->seek(frame.returnOffset, frame.returnLine);
    m_frames.pop_back();
}

void KlartextInterpreter::gotoLabel(const LabelTarget& target) {
    const LabelPosition* position = resolveLabel(target);
    if (position == nullptr) return;
    // Leaving a called section by a jump ends that call.
    const size_t level = m_levels.size() - 1;
    while (!m_frames.empty() && m_frames.back().level == level) {
        const LabelFrame& f = m_frames.back();
        const bool sectionRepeat = f.callOffset > f.target.offset;
        const bool inside = position->offset >= f.target.offset &&
                            (!sectionRepeat || position->offset <= f.callOffset);
        if (inside) break;
        m_frames.pop_back();
    }
    jumpTo(*position);
}

Expected<std::filesystem::path> KlartextInterpreter::calledProgramPath(
    const std::string& name, const std::filesystem::path& callerFolder, bool isoCaller) const {
    auto path = m_root.resolve(name, callerFolder);
    if (!path) return path.error();
    std::filesystem::path target = *path;
    std::error_code ignored;
    if (!std::filesystem::exists(target, ignored)) {
        // The TNC accepts the name without its extension: conversational first, then DIN/ISO
        // where the ISO syntax is available (an ISO caller looks for ISO programs first).
        std::vector<const char*> extensions{".H", ".h"};
        if (m_settings.isoSyntax) {
            extensions.insert(isoCaller ? extensions.begin() : extensions.end(), {".I", ".i"});
        }
        for (const char* ext : extensions) {
            std::filesystem::path withExt = target;
            withExt += ext;
            if (std::filesystem::exists(withExt, ignored)) {
                target = withExt;
                break;
            }
        }
    }
    // The name actually opened is checked: "noext" may have become a link "noext.H" to outside.
    if (MaybeError refused = m_root.admit(target)) {
        return Diagnostic::make(Severity::Error, "path", "", 0, 0, refused->messageTemplate, name);
    }
    return target;
}

void KlartextInterpreter::checkCalledPrograms(const ProgramFile& program, DiagnosticList& out) {
    std::vector<const ProgramFile*> pending{&program};
    std::set<const ProgramFile*> seen{&program};
    while (!pending.empty()) {
        const ProgramFile* caller = pending.back();
        pending.pop_back();
        for (const TableReference& table : caller->tables) {
            if (MaybeError problem = checkSelectedTable(table, caller->folder)) {
                problem->file = caller->source->path();
                problem->line = table.line;
                problem->column = table.column;
                appendDiagnostic(out, std::move(*problem));
            }
        }
        for (const ProgramCall& call : caller->calls) {
            auto error = [&](const char* code, const char* text, std::vector<std::string> args) {
                Diagnostic d = Diagnostic::make(Severity::Error, code, caller->source->path(),
                                                call.line, call.column, text);
                d.args = std::move(args);
                appendDiagnostic(out, std::move(d));
            };
            auto target = calledProgramPath(call.name, caller->folder, caller->syntax != nullptr);
            if (!target) {
                error("path", target.error().messageTemplate.c_str(), target.error().args);
                continue;
            }
            std::string reason;
            ProgramFile* callee = loadProgram(*target, &reason, Origin::Called);
            if (callee == nullptr) {
                error("io", KERF_TR_NOOP("cannot call program {1}: {2}"), {call.name, reason});
                continue;
            }
            if (!seen.insert(callee).second) continue;
            appendDiagnostics(out, callee->diagnostics);
            pending.push_back(callee);
        }
    }
}

void KlartextInterpreter::callSelectedProgram() {
    if (m_selectedProgram.empty()) {
        fail("call", KERF_TR_NOOP("CALL SELECTED PGM: no program was selected with SEL PGM"));
        return;
    }
    callProgram(CallPgm{m_selectedProgram});
}

void KlartextInterpreter::callProgram(const CallPgm& call) {
    // Another program ends the look-ahead of M120.
    if (!checkPathError(m_path.setLookAhead(0))) return;
    const ProgramFile& caller = *m_levels.back().program;
    auto path = calledProgramPath(call.path, caller.folder, caller.syntax != nullptr);
    if (!path) {
        fail("path", path.error().messageTemplate.c_str(), path.error().args);
        return;
    }
    const std::filesystem::path& target = *path;
    if (static_cast<int>(m_levels.size()) > m_settings.maxProgramNesting) {
        fail("nesting", KERF_TR_NOOP("program calls nested deeper than {1} levels"),
             {std::to_string(m_settings.maxProgramNesting)});
        return;
    }
    std::string error;
    ProgramFile* program = loadProgram(target, &error, Origin::Called);
    if (program == nullptr) {
        fail("io", KERF_TR_NOOP("cannot call program {1}: {2}"), {call.path, error});
        return;
    }
    if (hasErrors(program->diagnostics)) {
        appendDiagnostics(m_diagnostics, program->diagnostics);
        fail("call", KERF_TR_NOOP("the called program {1} has errors"), {call.path});
        return;
    }
    m_q.pushLocalLevel();
    size_t returnOffset = m_reader->offset();
    uint32_t returnLine = m_reader->line();
    startLevel(program, returnOffset, returnLine);
}

}  // namespace kerf::klartext
