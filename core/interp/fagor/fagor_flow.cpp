// Program flow: GOTO, RPT, subroutines (CALL, PCALL, MCALL, M functions, interrupts), EXEC and
// MEXEC.
#include <algorithm>
#include <set>

#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {

BlockPosition FagorInterpreter::nextBlock() const {
    return BlockPosition{m_line.nextOffset, m_reader->line()};
}

bool FagorInterpreter::insideModal() const {
    return std::any_of(m_frames.begin(), m_frames.end(), [](const Frame& f) { return f.modal; });
}

void FagorInterpreter::afterBlock() {
    if (m_jumped) return;
    repeatEnd(m_blockOffset);
}

bool FagorInterpreter::repeatEnd(size_t blockOffset) {
    if (m_frames.empty()) return false;
    Frame& top = m_frames.back();
    if (top.kind != Frame::Kind::Repeat || top.rangeProgram != m_program ||
        top.rangeEnd != blockOffset) {
        return false;
    }
    if (top.remaining > 0) {
        --top.remaining;
        readFrom(top.rangeProgram, top.rangeStart);
        return true;
    }
    const Frame done = top;
    m_frames.pop_back();
    readFrom(done.program, done.returnTo);
    repeatEnd(done.callBlock);
    return true;
}

bool FagorInterpreter::jump(int64_t label, Problem& problem) {
    if (!waitForCheck()) return false;
    const BlockPosition* target = m_program->findLabel(label);
    if (target == nullptr) {
        return problemOf(problem, "label",
                         KERF_TR_NOOP("label N{1} is not defined in this program"),
                         {std::to_string(label)});
    }
    // A jump out of an RPT range ends the repetition.
    while (!m_frames.empty() && m_frames.back().kind == Frame::Kind::Repeat &&
           m_frames.back().rangeProgram == m_program &&
           (target->offset < m_frames.back().rangeStart.offset ||
            target->offset > m_frames.back().rangeEnd)) {
        m_frames.pop_back();
    }
    readFrom(m_program, *target);
    return true;
}

bool FagorInterpreter::repeat(int64_t start, int64_t end, std::optional<int> program, int count,
                              Problem& problem) {
    if (!waitForCheck()) return false;
    FagorProgram* owner = m_program;
    if (program) {
        owner = programByNumber(*program, true, problem);
        if (owner == nullptr) return false;
    }
    const BlockPosition* first = owner->findLabel(start);
    const BlockPosition* last = owner->findLabel(end);
    if (first == nullptr || last == nullptr) {
        return problemOf(problem, "label", KERF_TR_NOOP("label N{1} is not defined in the program"),
                         {std::to_string(first == nullptr ? start : end)});
    }
    if (last->offset < first->offset) {
        return problemOf(problem, "flow", KERF_TR_NOOP("RPT: block N{1} comes before block N{2}"),
                         {std::to_string(end), std::to_string(start)});
    }
    if (count <= 0) return true;
    if (static_cast<int>(m_frames.size()) >= m_settings.maxCallNesting) {
        return problemOf(problem, "nesting", KERF_TR_NOOP("more than {1} nested levels"),
                         {std::to_string(m_settings.maxCallNesting)});
    }
    Frame frame;
    frame.kind = Frame::Kind::Repeat;
    frame.program = m_program;
    frame.returnTo = nextBlock();
    frame.rangeProgram = owner;
    frame.rangeStart = *first;
    frame.rangeEnd = last->offset;
    frame.remaining = count - 1;
    frame.callBlock = m_blockOffset;
    m_frames.push_back(frame);
    readFrom(owner, *first);
    return true;
}

FagorProgram* FagorInterpreter::programByNumber(int number, bool keepLabels, Problem& problem) {
    const size_t loaded = m_programs.size();
    FagorProgram* p = programFileByNumber(number, keepLabels, problem);
    if (p != nullptr && m_programs.size() > loaded && hasErrors(p->diagnostics)) {
        appendDiagnostics(m_diagnostics, p->diagnostics);
        problemOf(problem, "call", KERF_TR_NOOP("program {1} has errors"),
                  {std::to_string(number)});
        return nullptr;
    }
    return p;
}

FagorProgram* FagorInterpreter::programFileByNumber(int number, bool keepLabels, Problem& problem) {
    if (m_open.number == number) commitOpenProgram();  // what WRITE added so far is read back
    for (auto& p : m_programs) {
        if (p->number == number) {
            if (keepLabels && !p->keepLabels) return loadProgram(p->path, nullptr, true);
            return p.get();
        }
    }
    for (const auto& [path, text] : m_unwritten) {
        if (programNumberOf(path) == number) return loadProgram(path, nullptr, keepLabels);
    }
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(m_root.path(), error)) {
        std::error_code ignored;
        if (!entry.is_regular_file(ignored) || programNumberOf(entry.path()) != number) continue;
        std::string reason;
        FagorProgram* p = loadProgram(entry.path(), &reason, keepLabels);
        if (p == nullptr) {
            problemOf(problem, "io", KERF_TR_NOOP("cannot read program {1}: {2}"),
                      {std::to_string(number), reason});
        }
        return p;
    }
    problemOf(problem, "call", KERF_TR_NOOP("program {1} is not in the NC root"),
              {std::to_string(number)});
    return nullptr;
}

void FagorInterpreter::checkCalledPrograms(const FagorProgram& program, DiagnosticList& out) {
    std::vector<const FagorProgram*> pending{&program};
    std::set<const FagorProgram*> seen{&program};
    // A program the run writes with OPEN (EX-12.12 writes one, then EXECs it) is not there yet or
    // will be replaced: the run checks it when it gets there.
    std::set<int> written;
    bool writesUnknown = false;
    auto noteWrites = [&](const FagorProgram& p) {
        written.insert(p.opened.begin(), p.opened.end());
        writesUnknown = writesUnknown || p.opensAny;
    };
    noteWrites(program);
    while (!pending.empty()) {
        const FagorProgram* caller = pending.back();
        pending.pop_back();
        for (const ProgramCall& call : caller->calls) {
            if (writesUnknown || written.count(call.number) != 0) continue;
            auto error = [&](const Problem& problem) {
                Diagnostic d =
                    Diagnostic::make(Severity::Error, problem.code, caller->source->path(),
                                     call.line, call.column, problem.messageTemplate);
                d.args = problem.args;
                appendDiagnostic(out, std::move(d));
            };
            Problem problem;
            FagorProgram* callee = programFileByNumber(call.number, false, problem);
            if (callee == nullptr) {
                error(problem);
                continue;
            }
            if (!seen.insert(callee).second) continue;
            appendDiagnostics(out, callee->diagnostics);
            if (hasErrors(callee->diagnostics)) {
                problemOf(problem, "call", KERF_TR_NOOP("program {1} has errors"),
                          {std::to_string(call.number)});
                error(problem);
                continue;
            }
            noteWrites(*callee);
            pending.push_back(callee);
        }
    }
}

const SubroutineEntry* FagorInterpreter::findSubroutine(int number, FagorProgram*& owner,
                                                        Problem& problem) {
    if (!waitForCheck()) return nullptr;
    auto search = [&]() -> int {
        int found = 0;
        for (auto& p : m_programs) {
            if (p->findSubroutine(number) == nullptr) continue;
            if (found++ == 0) owner = p.get();
        }
        return found;
    };
    int found = search();
    if (found == 0 && !m_scannedRoot) {
        // Subroutines of other programs in the control's memory: the program files of the NC root.
        m_scannedRoot = true;
        commitOpenProgram();
        const auto scan = [this](const std::filesystem::path& path) {
            if (programNumberOf(path) < 0) return;
            FagorProgram* p = loadProgram(path, nullptr, false);
            if (p != nullptr && hasErrors(p->diagnostics)) {
                appendDiagnostics(m_diagnostics, p->diagnostics);
            }
        };
        for (const auto& [path, text] : m_unwritten)
            scan(path);  // a dry run's programs (kerf check)
        std::error_code error;
        for (const auto& entry : std::filesystem::directory_iterator(m_root.path(), error)) {
            std::error_code ignored;
            if (entry.is_regular_file(ignored)) scan(entry.path());
        }
        found = search();
    }
    if (found == 0) {
        problemOf(problem, "subroutine", KERF_TR_NOOP("subroutine {1} is not defined"),
                  {std::to_string(number)});
        return nullptr;
    }
    if (found > 1) {
        problemOf(problem, "subroutine",
                  KERF_TR_NOOP("subroutine {1} is defined in more than one program"),
                  {std::to_string(number)});
        return nullptr;
    }
    if (hasErrors(owner->diagnostics)) {
        problemOf(problem, "call", KERF_TR_NOOP("the program with subroutine {1} has errors"),
                  {std::to_string(number)});
        return nullptr;
    }
    return owner->findSubroutine(number);
}

bool FagorInterpreter::callSubroutine(Frame frame, int number, const LocalAssignments* locals,
                                      Problem& problem) {
    FagorProgram* owner = nullptr;
    const SubroutineEntry* entry = findSubroutine(number, owner, problem);
    if (entry == nullptr) return false;
    if (number >= 10000 && !m_program->oem) {
        return problemOf(problem, "subroutine",
                         KERF_TR_NOOP("error 1255: subroutine restricted to OEM programs"));
    }
    if (static_cast<int>(m_frames.size()) >= m_settings.maxCallNesting) {
        return problemOf(problem, "nesting", KERF_TR_NOOP("more than {1} nested levels"),
                         {std::to_string(m_settings.maxCallNesting)});
    }
    if (locals != nullptr) {
        if (!m_parameters.pushLocalLevel(*locals)) {
            return problemOf(problem, "nesting",
                             KERF_TR_NOOP("more than 6 nested levels of local parameters"));
        }
        frame.newLocals = true;
    }
    frame.program = m_program;
    frame.callBlock = m_blockOffset;
    frame.rangeStart = entry->body;
    frame.rangeProgram = owner;
    frame.subroutine = number;
    m_frames.push_back(frame);
    readFrom(owner, entry->body);
    m_parameters.setOemAllowed(owner->oem);
    return true;
}

bool FagorInterpreter::call(CallKind kind, int number, const LocalAssignments& locals,
                            Problem& problem) {
    Frame frame;
    frame.kind = Frame::Kind::Call;
    frame.returnTo = nextBlock();
    if (kind == CallKind::MCall) {
        // Like PCALL, and after every later block with axis motion again.
        m_modalSubroutine = number;
        m_modalLocals = locals;
        frame.modal = true;  // its own moves do not call it again
    }
    return callSubroutine(frame, number, kind == CallKind::Call ? nullptr : &locals, problem);
}

bool FagorInterpreter::enterSubroutineDefinition(int number, Problem& problem) {
    // Execution ran into a definition: it is skipped, like the control's editor shows it.
    if (!waitForCheck()) return false;
    const SubroutineEntry* entry = m_program->findSubroutine(number);
    if (entry == nullptr) {
        return problemOf(problem, "subroutine", KERF_TR_NOOP("subroutine {1} has no RET"),
                         {std::to_string(number)});
    }
    readFrom(m_program, entry->end);
    return true;
}

bool FagorInterpreter::returnFromSubroutine(Problem& problem) {
    while (!m_frames.empty() && m_frames.back().kind == Frame::Kind::Repeat)
        m_frames.pop_back();
    if (m_frames.empty() || m_frames.back().kind == Frame::Kind::Program) {
        return problemOf(problem, "flow", KERF_TR_NOOP("RET outside a subroutine"));
    }
    Frame& top = m_frames.back();
    const Frame done = top;
    m_frames.pop_back();
    if (done.newLocals) m_parameters.popLocalLevel();
    if (done.kind == Frame::Kind::Interrupt) m_parameters.setLocalsAllowed(true);
    if (done.kind == Frame::Kind::MFunction) {
        // The changer's subroutine has run (NBTOOL was the tool asked for): the tool is in
        // place now, reported at the block of the M06.
        const SourceLocation here = m_at;
        m_at = done.callAt;
        if (done.mFunction == 6) changeToPreselectedTool();
        if (done.emitMAfter) emit(canon::MachineFunction{done.mFunction});
        m_at = here;
    }
    m_parameters.setOemAllowed(done.program->oem);
    if (done.kind == Frame::Kind::ModalCall && done.remaining > 0) {
        // X10 N3: the motion and the subroutine again (spec part 1 §3.2).
        m_repeatProgram = done.program;
        m_repeatOffset = done.callBlock;
        m_repeatCount = done.remaining;
        readFrom(done.program, done.motionBlock);
        return true;
    }
    readFrom(done.program, done.returnTo);
    repeatEnd(done.callBlock);
    return true;
}

bool FagorInterpreter::modalCallOff(Problem& problem) {
    (void)problem;
    m_modalSubroutine = -1;
    m_modalProgram = -1;
    return true;
}

bool FagorInterpreter::executeProgram(bool modal, int number, Problem& problem) {
    if (modal && insideModal()) {
        return problemOf(problem, "flow",
                         KERF_TR_NOOP("error 1064: program cannot be executed "
                                      "(MEXEC inside the modal program)"));
    }
    FagorProgram* target = programByNumber(number, false, problem);
    if (target == nullptr) return false;
    if (static_cast<int>(m_frames.size()) >= m_settings.maxCallNesting) {
        return problemOf(problem, "nesting", KERF_TR_NOOP("more than {1} nested levels"),
                         {std::to_string(m_settings.maxCallNesting)});
    }
    if (!m_parameters.pushLocalLevel(LocalAssignments{})) {
        return problemOf(problem, "nesting",
                         KERF_TR_NOOP("more than 6 nested levels of local parameters"));
    }
    // EXEC stops block preparation: compensation is interrupted.
    if (!pathOk(m_shaper.flush()) || !pathOk(m_compensation.suspend())) return false;
    if (modal) m_modalProgram = number;
    Frame frame;
    frame.kind = Frame::Kind::Program;
    frame.program = m_program;
    frame.returnTo = nextBlock();
    frame.newLocals = true;
    frame.modal = modal;
    frame.callBlock = m_blockOffset;
    m_frames.push_back(frame);
    enterProgram(target, BlockPosition{0, 1});
    return true;
}

int FagorInterpreter::repetitionOfBlock() {
    const bool again = m_repeatProgram == m_program && m_repeatOffset == m_blockOffset;
    m_repeatProgram = nullptr;
    m_repeatOffset = SIZE_MAX;
    return again ? m_repeatCount : m_block.repetition;
}

void FagorInterpreter::runModalAfterMotion(int repetition) {
    if (insideModal() || m_status != interp::RunStatus::BudgetUsed) return;
    Problem problem;
    if (m_modalSubroutine >= 0) {
        const int count = repetition < 0 ? 1 : repetition;  // N0: the move only
        if (count == 0) return;
        Frame frame;
        frame.kind = Frame::Kind::ModalCall;
        frame.modal = true;
        frame.returnTo = nextBlock();
        frame.remaining = count - 1;
        frame.motionBlock = BlockPosition{m_blockOffset, m_line.firstLine};
        if (!callSubroutine(frame, m_modalSubroutine, &m_modalLocals, problem)) {
            failAt(0, problem);
        }
    } else if (m_modalProgram >= 0) {
        // The repetition count is ignored: the move and the program run once.
        if (!executeProgram(false, m_modalProgram, problem)) {
            failAt(0, problem);
            return;
        }
        m_frames.back().modal = true;
    }
}

void FagorInterpreter::raiseInterrupt(int input) {
    if (input >= 1 && input <= 4) m_pendingInterrupt = input;
}

void FagorInterpreter::startPendingInterrupt() {
    const int input = m_pendingInterrupt;
    m_pendingInterrupt = 0;
    const int number = m_settings.interruptSubroutines[static_cast<size_t>(input - 1)];
    if (number <= 0 || m_status != interp::RunStatus::BudgetUsed) return;
    if (!pathOk(m_shaper.flush()) || !pathOk(m_compensation.suspend())) return;
    Frame frame;
    frame.kind = Frame::Kind::Interrupt;
    frame.returnTo = BlockPosition{m_reader->offset(), m_reader->line()};
    frame.interruptedAt = m_position;
    // The interrupted block has not been read yet: there is no calling block.
    frame.callBlock = SIZE_MAX;
    Problem problem;
    const size_t saved = m_blockOffset;
    m_blockOffset = SIZE_MAX;
    if (!callSubroutine(frame, number, nullptr, problem)) {
        failAt(0, problem);
    } else {
        m_parameters.setLocalsAllowed(false);
    }
    m_blockOffset = saved;
}

bool FagorInterpreter::reposition(const std::array<Axis, kAxisCount>& axes, int count,
                                  Problem& problem) {
    auto interrupt = std::find_if(m_frames.rbegin(), m_frames.rend(),
                                  [](const Frame& f) { return f.kind == Frame::Kind::Interrupt; });
    if (interrupt == m_frames.rend()) {
        return problemOf(problem, "flow",
                         KERF_TR_NOOP("REPOS is only allowed in an interrupt subroutine"));
    }
    const Pose back = interrupt->interruptedAt;
    const PlaneFrame& plane = m_modal.plane;
    bool planeDone = false;
    for (int i = 0; i < count; ++i) {
        const Axis axis = axes[static_cast<size_t>(i)];
        Pose target = m_position;
        if (axis == plane.abscissa || axis == plane.ordinate) {
            // The plane's two axes move together, on the first of them.
            if (planeDone) continue;
            planeDone = true;
            target[plane.abscissa] = back[plane.abscissa];
            target[plane.ordinate] = back[plane.ordinate];
        } else {
            target[axis] = back[axis];
        }
        Move move;
        move.geometry = ContourElement::line(plane.plane, m_position, target);
        move.kind = MoveKind::Rapid;
        move.location = m_at;
        if (!pathOk(m_shaper.add(move)))
            return problemOf(problem, "flow", KERF_TR_NOOP("REPOS failed"));
        m_position = target;
    }
    return true;
}

}  // namespace kerf::fagor
