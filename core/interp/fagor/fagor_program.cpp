#include "core/interp/fagor/fagor_program.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "core/base/translate.h"
#include "core/interp/fagor/block_parser.h"
#include "core/interp/fagor/g_rules.h"
#include "core/interp/fagor/statement_runner.h"
#include "core/program/line_reader.h"
#include "core/program/mapped_copy.h"

namespace kerf::fagor {

const BlockPosition* FagorProgram::findLabel(int64_t label) const {
    if (label < 0 || label > 99999999) return nullptr;
    auto it = std::lower_bound(labels.begin(), labels.end(), static_cast<uint32_t>(label),
                               [](const auto& entry, uint32_t l) { return entry.first < l; });
    return it != labels.end() && it->first == label ? &it->second : nullptr;
}

const SubroutineEntry* FagorProgram::findSubroutine(int subroutine) const {
    auto it = std::lower_bound(subroutines.begin(), subroutines.end(), subroutine,
                               [](const SubroutineEntry& s, int n) { return s.number < n; });
    return it != subroutines.end() && it->number == subroutine ? &*it : nullptr;
}

int programNumberOf(const std::filesystem::path& path) {
    std::string stem = path.stem().string();
    if (!stem.empty() && (stem[0] == 'P' || stem[0] == 'p')) stem.erase(0, 1);
    if (stem.empty() || stem.size() > 6) return -1;
    int n = 0;
    for (char c : stem) {
        if (c < '0' || c > '9') return -1;
        n = n * 10 + (c - '0');
    }
    return n;
}

namespace {

struct Reference {
    int64_t label;
    uint32_t line;
    uint32_t column;
};

class Checker {
public:
    explicit Checker(FagorProgram& p) : m_program(p), m_file(p.source->path()) {}

    void run();

private:
    void diag(Severity s, const char* code, uint32_t line, uint32_t column, const char* text,
              std::vector<std::string> args = {}) {
        Diagnostic d = Diagnostic::make(s, code, m_file, line, column, text);
        d.args = std::move(args);
        appendDiagnostic(m_program.diagnostics, std::move(d));
    }
    void header(std::string_view text, uint32_t line);
    void iso(const ParsedBlock& block, const program::LogicalLine& line);
    void highLevel(const StatementInfo& info, const program::LogicalLine& line,
                   const BlockPosition& next);
    void finish();
    void indexLabelsBefore(size_t until);

    FagorProgram& m_program;
    std::string m_file;
    std::vector<Reference> m_references;
    struct OpenSub {
        SubroutineEntry entry;
        uint32_t line = 0;  // of the SUB statement
        uint32_t column = 0;
    };
    std::vector<OpenSub> m_openSubs;
    bool m_warnedOrder = false;
    bool m_flow = false;
    // Labels are indexed only once the program needs them (a jump, a profile, keepLabels) or
    // one comes out of ascending order (it may repeat one: finish() warns), from the line at this
    // offset on; finish() indexes the lines before (SIZE_MAX: none indexed).
    size_t m_indexedFrom = SIZE_MAX;
    int64_t m_lastLabel = -1;
    bool m_labelsAscending = true;
};

void Checker::header(std::string_view text, uint32_t line) {
    // "%comment,attributes," : the comment has at most 20 characters.
    const size_t first = text.find(',');
    const size_t second = first == std::string_view::npos ? first : text.find(',', first + 1);
    if (second == std::string_view::npos) {
        diag(Severity::Warning, "header", line, 1,
             KERF_TR_NOOP("the header should be %comment,attributes, (two commas)"));
    }
    const std::string_view comment =
        text.substr(1, first == std::string_view::npos ? text.size() - 1 : first - 1);
    if (program::columnOf(comment, comment.size()) > 21) {
        diag(Severity::Warning, "header", line, 2,
             KERF_TR_NOOP("the program comment has more than 20 characters"));
    }
    if (first != std::string_view::npos) {
        const std::string_view attributes =
            text.substr(first + 1, second == std::string_view::npos ? std::string_view::npos
                                                                    : second - first - 1);
        m_program.oem = attributes.find('O') != std::string_view::npos;
    }
}

void Checker::iso(const ParsedBlock& block, const program::LogicalLine& line) {
    const IsoBlock& iso = block.iso;
    if (m_program.userChannel && (iso.gCount != 0 || iso.hasOtherWords())) {
        diag(Severity::Error, "user-channel", line.firstLine, 1,
             KERF_TR_NOOP("a customisation program runs in the user channel: it has no ISO "
                          "blocks (no motion, no M, S, T)"));
        return;
    }
    Problem problem;
    bool literal = true;
    for (uint8_t i = 0; i < iso.gCount; ++i)
        literal = literal && !iso.g[i].parameter;
    if (literal && !checkGFunctions(iso, problem)) {
        // A G function not supported (yet) stops the run there, so it fails the check too.
        diag(Severity::Error, problem.code.c_str(), line.firstLine,
             program::columnOf(line.text, problem.offset), problem.messageTemplate.c_str(),
             problem.args);
    }
    for (uint8_t i = 0; i < iso.axisCount; ++i) {
        // The run stops at a word for an axis the machine lacks (G1 Y10 on a lathe).
        const Axis axis = iso.axisOrder[i];
        if ((m_program.machineAxes & axisBit(axis)) != 0) continue;
        diag(Severity::Error, "axis", line.firstLine,
             program::columnOf(line.text, iso.axes[static_cast<size_t>(axisIndex(axis))].offset),
             KERF_TR_NOOP("axis {1} is not available on this machine"),
             {std::string(1, axisLetter(axis))});
        break;
    }
    const int cycle = iso.cycle.g;
    if (cycle == 66 || cycle == 68 || cycle == 69) {
        // The profile is found by its labels S and E: keep the index, check them here when the
        // profile is in this program.
        m_flow = true;
        for (const char letter : {'S', 'E'}) {
            const WordValue& w = iso.cycle[letter];
            if (iso.cycle.has('Q') || w.parameter) continue;
            m_references.push_back({static_cast<int64_t>(w.value), line.firstLine,
                                    program::columnOf(line.text, w.offset)});
        }
    }
    if (block.outOfOrder != 0 && !m_warnedOrder) {
        m_warnedOrder = true;
        diag(Severity::Warning, "word-order", line.firstLine,
             program::columnOf(line.text, block.outOfOrder),
             KERF_TR_NOOP("words out of the order G, coordinates, F, S, T, D, M"));
    }
}

void Checker::highLevel(const StatementInfo& info, const program::LogicalLine& line,
                        const BlockPosition& next) {
    for (uint8_t i = 0; i < info.labelCount; ++i) {
        m_references.push_back(
            {info.labels[i], line.firstLine, program::columnOf(line.text, info.labelOffsets[i])});
    }
    m_flow = m_flow || info.flow;
    if (info.opens) {
        if (info.program >= 0) {
            m_program.opened.push_back(static_cast<int>(info.program));
        } else {
            m_program.opensAny = true;
        }
    } else if (info.program >= 0 && info.kind != StatementInfo::Kind::DncDirectory) {
        m_program.calls.push_back({static_cast<int>(info.program), line.firstLine,
                                   program::columnOf(line.text, info.programOffset)});
    }
    switch (info.kind) {
        case StatementInfo::Kind::Sub: {
            const int n = static_cast<int>(info.number);
            const uint32_t column = program::columnOf(line.text, info.keywordOffset);
            if (!m_openSubs.empty()) {
                diag(Severity::Error, "subroutine", line.firstLine, column,
                     KERF_TR_NOOP("subroutine {1} starts before subroutine {2} has its RET"),
                     {std::to_string(n), std::to_string(m_openSubs.back().entry.number)});
            }
            if (n >= 10000 && !m_program.oem) {
                diag(
                    Severity::Error, "subroutine", line.firstLine, column,
                    KERF_TR_NOOP("error 63: program subroutine numbers from 1 to 9999 (10000-20000 "
                                 "only in OEM programs)"));
            }
            SubroutineEntry entry;
            entry.number = n;
            entry.body = next;
            m_openSubs.push_back({entry, line.firstLine, column});
            break;
        }
        case StatementInfo::Kind::Ret:
            if (!m_openSubs.empty()) {
                const OpenSub open = m_openSubs.back();
                SubroutineEntry entry = open.entry;
                m_openSubs.pop_back();
                entry.end = next;
                if (std::any_of(
                        m_program.subroutines.begin(), m_program.subroutines.end(),
                        [&](const SubroutineEntry& s) { return s.number == entry.number; })) {
                    diag(Severity::Error, "subroutine", open.line, open.column,
                         KERF_TR_NOOP("subroutine {1} is defined twice"),
                         {std::to_string(entry.number)});
                }
                m_program.subroutines.push_back(entry);
            }
            break;
        case StatementInfo::Kind::Customization:
            if (!m_program.userChannel) {
                diag(Severity::Error, "not-supported", line.firstLine,
                     program::columnOf(line.text, info.keywordOffset),
                     KERF_TR_NOOP("{1} is a screen customisation instruction: it runs only in a "
                                  "user customisation program (the user screen)"),
                     {std::string(info.keyword)});
            }
            break;
        case StatementInfo::Kind::DncDirectory:
            diag(Severity::Error, "not-available", line.firstLine,
                 program::columnOf(line.text, info.keywordOffset),
                 KERF_TR_NOOP("programs on a PC over DNC are not available; the program cannot run "
                              "past this block"));
            break;
        case StatementInfo::Kind::Other:
            break;
    }
}

// The labels of the lines before `until`, which the first pass read before it knew that the
// program needs them: parsed again and put ahead of those indexed since, so in file order.
void Checker::indexLabelsBefore(size_t until) {
    const std::string_view text = m_program.source->text();
    program::LineReader reader(text);
    program::LogicalLine line;
    BlockParser parser(nullptr);
    ParsedBlock block;
    std::vector<std::pair<uint32_t, BlockPosition>> earlier;
    bool first = true;
    size_t releasedBefore = 0;
    while (reader.offset() < until && reader.next(line, false)) {
        if (line.offset >= releasedBefore + program::kTextReleaseStep) {
            releasedBefore = line.offset;
            program::releasePagesBefore(text, line.offset);
        }
        const bool firstLine = first;
        first = false;
        if (!parser.parse(line.text, firstLine, block)) continue;
        if (block.label >= 0) {
            earlier.push_back(
                {static_cast<uint32_t>(block.label), BlockPosition{line.offset, line.firstLine}});
        }
        if (block.endOfFile) break;
    }
    m_program.labels.insert(m_program.labels.begin(), earlier.begin(), earlier.end());
}

void Checker::finish() {
    // Labels in ascending order repeat none, so a long numbered program without jumps is never
    // indexed, not even while it is checked.
    if ((m_flow || m_program.keepLabels || !m_labelsAscending) && m_indexedFrom > 0) {
        indexLabelsBefore(m_indexedFrom);
    }
    auto& labels = m_program.labels;
    const auto byNumber = [](const auto& a, const auto& b) { return a.first < b.first; };
    // Numbered programs are usually in order already: no sort (and no merge buffer) then.
    if (!std::is_sorted(labels.begin(), labels.end(), byNumber)) {
        std::stable_sort(labels.begin(), labels.end(), byNumber);
    }
    int duplicates = 0;
    for (size_t i = 1; i < labels.size(); ++i) {
        if (labels[i].first == labels[i - 1].first && ++duplicates <= 10) {
            diag(Severity::Warning, "label", labels[i].second.line, 1,
                 KERF_TR_NOOP("label N{1} is used more than once; jumps go to the first one"),
                 {std::to_string(labels[i].first)});
        }
    }
    labels.erase(std::unique(labels.begin(), labels.end(),
                             [](const auto& a, const auto& b) { return a.first == b.first; }),
                 labels.end());
    for (const Reference& r : m_references) {
        if (m_program.findLabel(r.label) == nullptr) {
            diag(Severity::Error, "label", r.line, r.column,
                 KERF_TR_NOOP("label N{1} is not defined in this program"),
                 {std::to_string(r.label)});
        }
    }
    for (const OpenSub& open : m_openSubs) {
        diag(Severity::Error, "subroutine", open.line, open.column,
             KERF_TR_NOOP("subroutine {1} has no RET"), {std::to_string(open.entry.number)});
    }
    std::sort(
        m_program.subroutines.begin(), m_program.subroutines.end(),
        [](const SubroutineEntry& a, const SubroutineEntry& b) { return a.number < b.number; });
    if (!m_flow && !m_program.keepLabels) {
        // Only jumps need the label index. Another program's RPT into this one loads it again.
        std::vector<std::pair<uint32_t, BlockPosition>>().swap(labels);
    }
}

void Checker::run() {
    const std::string_view text = m_program.source->text();
    program::LineReader reader(text);
    program::LogicalLine line;
    BlockParser parser(nullptr);
    StatementRunner runner(nullptr);
    ParsedBlock block;
    bool first = true;
    // Beside a run, the check keeps at most this far ahead of it, so that only the text between
    // them is resident (a long program's mapped copy, mapped_copy.h); alone, it lets the text
    // behind it go.
    constexpr size_t kWindow = 4 * program::kTextReleaseStep;
    size_t releasedBefore = 0;
    while (reader.next(line, false)) {
        if (m_program.followExecution) {
            while (line.offset > kWindow &&
                   line.offset - kWindow > m_program.executionOffset.load()) {
                std::this_thread::sleep_for(std::chrono::microseconds(200));
            }
        } else if (line.offset >= releasedBefore + program::kTextReleaseStep) {
            releasedBefore = line.offset;
            program::releasePagesBefore(text, line.offset);
        }
        const bool firstLine = first;
        first = false;
        if (!parser.parse(line.text, firstLine, block)) {
            const Problem& p = parser.problem();
            diag(Severity::Error, p.code.c_str(), line.firstLine,
                 program::columnOf(line.text, p.offset), p.messageTemplate.c_str(), p.args);
            continue;
        }
        if (block.label >= 0) {
            m_labelsAscending = m_labelsAscending && block.label > m_lastLabel;
            m_lastLabel = block.label;
            if (m_flow || m_program.keepLabels || !m_labelsAscending) {
                if (m_indexedFrom == SIZE_MAX) m_indexedFrom = line.offset;
                m_program.labels.push_back({static_cast<uint32_t>(block.label),
                                            BlockPosition{line.offset, line.firstLine}});
            }
        }
        switch (block.kind) {
            case ParsedBlock::Kind::Header:
                header(line.text, line.firstLine);
                break;
            case ParsedBlock::Kind::Iso:
                iso(block, line);
                break;
            case ParsedBlock::Kind::HighLevel:
                if (!runner.run(line.text, block.highLevelOffset,
                                block.highLevelOffset + block.highLevel.size(), block.repetition)) {
                    const Problem& p = runner.problem();
                    diag(Severity::Error, p.code.c_str(), line.firstLine,
                         program::columnOf(line.text, p.offset), p.messageTemplate.c_str(), p.args);
                } else {
                    highLevel(runner.info(), line, BlockPosition{line.nextOffset, reader.line()});
                }
                break;
            default:
                break;
        }
        if (block.endOfFile) {
            m_program.end = line.nextOffset;
            break;
        }
    }
    finish();
}

}  // namespace

void checkProgram(FagorProgram& program) {
    program.diagnostics.clear();
    program.labels.clear();
    program.subroutines.clear();
    program.calls.clear();
    program.opened.clear();
    program.opensAny = false;
    Checker(program).run();
}

}  // namespace kerf::fagor
