// High-level statements with output: ERROR, MSG, DGWZ, the locks, OPEN and WRITE, and GPOS.
#include <algorithm>
#include <cmath>

#include "core/base/atomic_file.h"
#include "core/base/translate.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {

namespace {

// The texts the manual gives for its error numbers.
const char* manualErrorText(int number) {
    switch (number) {
        case 7:
            return KERF_TR_NOOP("incompatible G functions");
        case 63:
            return KERF_TR_NOOP("program subroutine number from 1 to 9999");
        case 1031:
            return KERF_TR_NOOP("the S that changes the gear range must be alone in its block");
        case 1064:
            return KERF_TR_NOOP("program cannot be executed");
        case 1255:
            return KERF_TR_NOOP("subroutine restricted to OEM program");
        default:
            return nullptr;
    }
}

std::filesystem::path newProgramPath(const std::filesystem::path& root, int number) {
    std::string name = std::to_string(number);
    name.insert(0, 6 - std::min<size_t>(6, name.size()), '0');
    return root / ("P" + name + ".PIM");
}

}  // namespace

std::string FagorInterpreter::substituteParameters(std::string_view text, bool marked) {
    // ISO text: every P<n> becomes its value; high-level text: only ?P<n>.
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        const bool mark = marked && text[i] == '?' && i + 1 < text.size() && text[i + 1] == 'P';
        const size_t p = mark ? i + 1 : i;
        const bool ref =
            (mark || (!marked && text[i] == 'P')) && p + 1 < text.size() && isDigit(text[p + 1]);
        if (!ref) {
            out += text[i++];
            continue;
        }
        size_t end = p + 1;
        int number = 0;
        while (end < text.size() && isDigit(text[end]) && end - p <= 4) {
            number = number * 10 + (text[end] - '0');
            ++end;
        }
        double value = 0.0;
        Problem ignored;
        if (m_parameters.get(number, value, ignored)) {
            out += formatTableNumber(value, 5);
        } else {
            out.append(text.substr(i, end - i));
        }
        i = end;
    }
    return out;
}

bool FagorInterpreter::raiseError(std::optional<int> number, std::string_view text,
                                  Problem& problem) {
    std::string shown(text);
    if (shown.empty() && number) {
        const char* known = manualErrorText(*number);
        shown = known != nullptr ? known : "";
    }
    if (!number) {
        emit(canon::Message{canon::MessageKind::Error, shown});
        return problemOf(problem, "program-error", KERF_TR_NOOP("{1}"), {shown});
    }
    const std::string code = std::to_string(*number);
    emit(canon::Message{canon::MessageKind::Error,
                        shown.empty() ? "error " + code : "error " + code + ": " + shown});
    if (shown.empty())
        return problemOf(problem, "program-error", KERF_TR_NOOP("error {1}"), {code});
    return problemOf(problem, "program-error", KERF_TR_NOOP("error {1}: {2}"), {code, shown});
}

bool FagorInterpreter::showMessage(std::string_view text, Problem& problem) {
    (void)problem;
    emit(canon::Message{canon::MessageKind::Info, substituteParameters(text, true)});
    return true;
}

bool FagorInterpreter::graphicZone(double zMin, double zMax, double inner, double outer,
                                   Problem& problem) {
    if (!(zMax > zMin) || inner < 0.0 || !(outer > inner)) {
        return problemOf(problem, "geometry",
                         KERF_TR_NOOP("DGWZ: Z minimum < Z maximum and 0 <= inner < outer"));
    }
    canon::StockCylinder cylinder;
    cylinder.axis = Axis::Z;
    const double diameterScale = m_modal.diameter ? 0.5 : 1.0;
    cylinder.radiusMm = length(outer) * diameterScale;
    cylinder.innerRadiusMm = length(inner) * diameterScale;
    cylinder.lengthMm = length(zMax - zMin);
    cylinder.distanceMm = length(zMax);
    emit(canon::StockDefinition{cylinder});
    return true;
}

bool FagorInterpreter::changeLocks(LockChange change, Problem& problem) {
    (void)problem;
    switch (change) {
        case LockChange::JoinBlocks:
            m_locks.joinBlocks = true;
            break;
        case LockChange::SeparateBlocks:
            m_locks.joinBlocks = false;
            break;
        case LockChange::DisableStop:
            m_locks.stopDisabled = true;
            break;
        case LockChange::EnableStop:
            m_locks.stopDisabled = false;
            break;
        case LockChange::DisableFeedHold:
            m_locks.feedHoldDisabled = true;
            break;
        case LockChange::EnableFeedHold:
            m_locks.feedHoldDisabled = false;
            break;
    }
    emit(m_locks);
    return true;
}

void FagorInterpreter::commitOpenProgram() {
    if (m_open.path.empty()) return;
    // No file changes before the whole program has passed its check.
    if (!waitForCheck()) {
        m_open = OpenProgram{};
        return;
    }
    if (MaybeError error = replaceFile(m_open.path, m_open.content)) {
        appendDiagnostic(m_diagnostics, *error);
    }
}

void FagorInterpreter::closeOpenProgram() {
    commitOpenProgram();
    m_open = OpenProgram{};
}

bool FagorInterpreter::openProgram(int number, char mode, std::string_view comment,
                                   Problem& problem) {
    closeOpenProgram();
    std::filesystem::path path;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(m_root.path(), error)) {
        std::error_code ignored;
        if (entry.is_regular_file(ignored) && programNumberOf(entry.path()) == number) {
            path = entry.path();
            break;
        }
    }
    const bool exists = !path.empty();
    if (exists && mode == '\0') {
        return problemOf(problem, "file",
                         KERF_TR_NOOP("program {1} exists: OPEN needs A (append) or D (delete)"),
                         {std::to_string(number)});
    }
    for (auto it = m_programs.begin(); it != m_programs.end() && exists; ++it) {
        // The same file under any name: "./fr/../fr/P000100.PIM", a link, a hard link.
        if (!sameFile((*it)->path, path)) continue;
        const FagorProgram* open = it->get();
        const bool running =
            m_program == open || std::any_of(m_frames.begin(), m_frames.end(), [&](const Frame& f) {
                return f.program == open || f.rangeProgram == open;
            });
        if (running || open == m_checking) {
            return problemOf(problem, "file",
                             KERF_TR_NOOP("program {1} is running: it cannot be opened"),
                             {std::to_string(number)});
        }
        m_programs.erase(it);  // it changes: a later EXEC reads it again
        break;
    }
    if (!exists) path = newProgramPath(m_root.path(), number);
    if (MaybeError refused = m_root.admitWrite(path)) {
        return problemOf(problem, "file", KERF_TR_NOOP("cannot write program {1}: {2}"),
                         {std::to_string(number), refused->message()});
    }
    std::string content;
    if (exists && mode == 'A') {
        auto previous = m_root.read(path);
        if (!previous) {
            return problemOf(problem, "file", KERF_TR_NOOP("cannot read program {1}: {2}"),
                             {std::to_string(number), previous.error().message()});
        }
        content = std::move(*previous);
        if (!content.empty() && content.back() != '\n') content += '\n';
    } else {
        content = "%" + std::string(comment) + ",,\n";
    }
    m_open = OpenProgram{path, number, std::move(content)};
    return true;
}

bool FagorInterpreter::writeBlock(std::string_view text, Problem& problem) {
    if (m_open.path.empty()) {
        return problemOf(problem, "file", KERF_TR_NOOP("WRITE needs a program opened with OPEN"));
    }
    size_t first = 0;
    while (first < text.size() && (text[first] == ' ' || text[first] == '\t'))
        ++first;
    const bool highLevel = first < text.size() && text[first] == '(';
    std::string block = substituteParameters(text.substr(first), highLevel);
    while (!block.empty() && (block.back() == ' ' || block.back() == '\t'))
        block.pop_back();
    m_open.content += block;
    m_open.content += '\n';
    return true;
}

bool FagorInterpreter::gpos(const VariableRef& ref, double& out, Problem& problem) {
    FagorProgram* owner = programByNumber(ref.program, true, problem);
    if (owner == nullptr) return false;
    if (owner == m_checking && !waitForCheck()) return false;
    const BlockPosition* block = owner->findLabel(ref.index);
    if (block == nullptr) {
        return problemOf(problem, "label", KERF_TR_NOOP("GPOS: program {1} has no block N{2}"),
                         {std::to_string(ref.program), std::to_string(ref.index)});
    }
    program::LineReader reader(owner->source->text(), block->offset, block->line);
    program::LogicalLine line;
    if (!reader.next(line, false))
        return problemOf(problem, "label", KERF_TR_NOOP("GPOS: block not found"));
    BlockParser parser(this);
    ParsedBlock parsed;
    if (!parser.parse(line.text, false, parsed)) {
        problem = parser.problem();
        return false;
    }
    const bool programmed = parsed.kind == ParsedBlock::Kind::Iso && parsed.iso.has(ref.axis);
    // An axis the block does not program reads as 100000.
    out = programmed ? parsed.iso.axes[static_cast<size_t>(axisIndex(ref.axis))].value : 100000.0;
    return true;
}

}  // namespace kerf::fagor
