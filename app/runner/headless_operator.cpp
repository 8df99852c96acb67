#include "app/runner/headless_operator.h"

#include <charconv>
#include <cmath>

#include "core/base/translate.h"

namespace kerf::app {

std::optional<fagor::UserMode> userModeFromName(const std::string& name) {
    if (name == "execution") return fagor::UserMode::Execution;
    if (name == "edit") return fagor::UserMode::Edit;
    if (name == "manual") return fagor::UserMode::Manual;
    if (name == "diagnosis") return fagor::UserMode::Diagnosis;
    return std::nullopt;
}

std::optional<std::pair<int, double>> inputAssignment(const std::string& item) {
    if (item.size() < 4 || (item[0] != 'I' && item[0] != 'i') || (item[1] != 'B' && item[1] != 'b'))
        return std::nullopt;
    const size_t equals = item.find('=');
    if (equals == std::string::npos) return std::nullopt;
    int n = -1;
    const auto [end, error] = std::from_chars(item.data() + 2, item.data() + equals, n);
    if (error != std::errc() || end != item.data() + equals || n < 0 || n > 25) return std::nullopt;
    double value = 0.0;
    const char* last = item.data() + item.size();
    const char* from = item.data() + equals + 1;
    if (from < last && *from == '+') ++from;
    const auto [valueEnd, valueError] = std::from_chars(from, last, value);
    if (valueError != std::errc() || valueEnd != last || !std::isfinite(value)) return std::nullopt;
    return std::make_pair(n, value);
}

HeadlessOperator::HeadlessOperator(const RunOptions& options)
    : m_program(options.program.string()) {
    if (!options.userScreen) return;
    m_screen = std::make_unique<fagor::UserScreen>(
        userModeFromName(*options.userScreen).value_or(fagor::UserMode::Execution));
    // "F1,2.5" and repeated options both give items in order.
    for (const std::string& option : options.operatorInput) {
        size_t start = 0;
        for (;;) {
            const size_t comma = option.find(',', start);
            std::string item = option.substr(start, comma - start);
            if (!inputAssignment(item)) m_inputs.push_back(std::move(item));
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    }
}

bool HeadlessOperator::answer(DiagnosticList& problems) {
    using Waiting = fagor::UserScreen::Waiting;
    const bool key = m_screen->waiting() == Waiting::Key;
    if (m_next >= m_inputs.size()) {
        problems.push_back(Diagnostic::make(
            Severity::Note, "operator", m_program, 0, 0,
            key ? KERF_TR_NOOP("the user screen waits for a key (WKEY) and no --operator-input "
                               "is left: the run ends here")
                : KERF_TR_NOOP("the user screen waits for IB{1} and no --operator-input is left: "
                               "the run ends here"),
            std::to_string(m_screen->pendingInput())));
        return false;
    }
    const std::string& input = m_inputs[m_next++];
    if (key) {
        const auto code = fagor::keyCode(input);
        if (!code) {
            problems.push_back(Diagnostic::make(
                Severity::Error, "operator", m_program, 0, 0,
                KERF_TR_NOOP("operator input '{1}' is not a key (F1-F7, $FC00, one character)"),
                input));
            return false;
        }
        m_screen->pressKey(*code);
        return true;
    }
    if (const auto refused = m_screen->enterNumber(input)) {
        Diagnostic d = Diagnostic::make(Severity::Error, "operator", m_program, 0, 0,
                                        KERF_TR_NOOP("operator input '{1}' for IB{2}: {3}"), input);
        d.args = {input, std::to_string(m_screen->pendingInput()), *refused};
        problems.push_back(std::move(d));
        return false;
    }
    return true;
}

void HeadlessOperator::noteBlockLimit(DiagnosticList& problems, uint64_t blocks) const {
    problems.push_back(Diagnostic::make(
        Severity::Note, "operator", m_program, 0, 0,
        KERF_TR_NOOP("the customisation program ran {1} blocks: a user screen runs until the "
                     "operator leaves it (SYSTEM); the run ends here (--max-blocks)"),
        std::to_string(blocks)));
}

std::optional<Diagnostic> HeadlessOperator::dialectProblem(program::Dialect dialect) const {
    if (!active() || dialect == program::Dialect::Fagor) return std::nullopt;
    return Diagnostic::make(Severity::Error, "setup", m_program, 0, 0,
                            KERF_TR_NOOP("--user-screen runs FAGOR customisation programs only"));
}

void HeadlessOperator::print(std::ostream& out) const {
    out << m_screen->describe();
}

void HeadlessOperator::addToReport(nlohmann::json& report) const {
    nlohmann::json screen;
    screen["page"] = m_screen->page();
    nlohmann::json windows = nlohmann::json::array();
    for (size_t i = 0; i < m_screen->windows().size(); ++i) {
        const auto& w = m_screen->windows()[i];
        if (!w) continue;
        windows.push_back(
            {{"window", i}, {"row", w->row}, {"column", w->column}, {"text", w->text}});
    }
    screen["windows"] = windows;
    nlohmann::json symbols = nlohmann::json::array();
    for (const fagor::ScreenSymbol& s : m_screen->symbols())
        symbols.push_back({{"symbol", s.number}, {"column", s.column}, {"row", s.row}});
    screen["symbols"] = symbols;
    screen["softkeys"] = m_screen->softkeys();
    screen["input_prompt"] = m_screen->prompt();
    screen["inputs"] = m_screen->inputs();
    screen["edit_buffer"] = m_screen->editBuffer();
    screen["inserted_blocks"] = m_screen->insertedBlocks();
    screen["left"] = m_screen->left();
    screen["operator_inputs_used"] = m_next;
    report["user_screen"] = screen;
}

}  // namespace kerf::app
