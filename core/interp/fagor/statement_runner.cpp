#include "core/interp/fagor/statement_runner.h"

#include <algorithm>
#include <cmath>

#include "core/base/translate.h"

namespace kerf::fagor {

namespace {

bool isCustomization(std::string_view w) {
    static constexpr std::string_view kWords[] = {"PAGE", "SYMBOL", "IB",   "ODW",  "DW",    "DWH",
                                                  "DWB",  "SK",     "WKEY", "WBUF", "SYSTEM"};
    for (std::string_view k : kWords) {
        if (k == w) return true;
    }
    return false;
}

// Quotation marks: '"', and the typographic ones of the Portuguese manual.
size_t openingQuote(std::string_view text, size_t at) {
    if (at < text.size() && text[at] == '"') return 1;
    if (text.substr(at, 3) == "\xE2\x80\x9E" || text.substr(at, 3) == "\xE2\x80\x9C") return 3;
    return 0;
}

size_t closingQuote(std::string_view text, size_t at) {
    if (at < text.size() && text[at] == '"') return 1;
    if (text.substr(at, 3) == "\xE2\x80\x9C" || text.substr(at, 3) == "\xE2\x80\x9D") return 3;
    return 0;
}

}  // namespace

bool StatementRunner::fail(size_t offset, const char* code, const char* messageTemplate,
                           std::vector<std::string> args) {
    m_problem = Problem{offset, code, messageTemplate, std::move(args)};
    return false;
}

bool StatementRunner::contextFailed(size_t offset) {
    m_problem.offset = offset;
    return false;
}

void StatementRunner::noteLabel(int64_t label, size_t offset, bool constant) {
    m_info.flow = true;
    if (!constant || m_info.labelCount >= m_info.labels.size()) return;
    m_info.labels[m_info.labelCount] = label;
    m_info.labelOffsets[m_info.labelCount] = offset;
    ++m_info.labelCount;
}

void StatementRunner::noteProgram(size_t offset) {
    // A constant number (EXEC P7): the check can verify the program exists and passes its check.
    const size_t start = m_s->position();
    int64_t value = 0;
    uint8_t digits = 0;
    if (isDigit(m_s->peek()) && m_s->unsignedInteger(value, digits) && digits <= 6) {
        const char next = m_s->peek();
        if (next == '\0' || next == ',') {
            m_info.program = value;
            m_info.programOffset = offset;
        }
    }
    m_s->setPosition(start);
}

bool StatementRunner::run(std::string_view text, size_t begin, size_t end, int repetition) {
    m_s.emplace(text.substr(0, end), begin);
    m_end = end;
    m_exec = m_context != nullptr;
    m_repetition = repetition;
    m_info = StatementInfo{};
    if (!statement(true)) return false;
    return endOfStatement();
}

bool StatementRunner::endOfStatement() {
    if (m_s->peek() == '\0') return true;
    const std::string_view rest = m_s->text().substr(m_s->position());
    return fail(m_s->position(), "syntax", KERF_TR_NOOP("unexpected '{1}'"),
                {std::string(rest.substr(0, rest.find_first_of(" \t,")))});
}

bool StatementRunner::expect(char c) {
    if (m_s->accept(c)) return true;
    return fail(m_s->position(), "syntax", KERF_TR_NOOP("'{1}' expected"), {std::string(1, c)});
}

bool StatementRunner::expression(ExprValue& out) {
    ExpressionContext* values = m_values != nullptr ? m_values : m_context;
    Expression e(*m_s, executing() ? values : nullptr);
    if (e.parse(out)) return true;
    m_problem = e.problem();
    return false;
}

bool StatementRunner::integerExpression(int64_t& out, double lo, double hi, const char* what) {
    const size_t at = m_s->position();
    ExprValue v;
    if (!expression(v)) return false;
    out = 0;
    if (!executing()) return true;
    if (v.number != std::floor(v.number) || v.number < lo || v.number > hi) {
        return fail(at, "range",
                    KERF_TR_NOOP("{1} must be a whole number from {2} to {3}, not {4}"),
                    {what, std::to_string(static_cast<long long>(lo)),
                     std::to_string(static_cast<long long>(hi)), std::to_string(v.number)});
    }
    out = static_cast<int64_t>(v.number);
    return true;
}

bool StatementRunner::labelExpression(int64_t& out) {
    m_s->skipBlanks();
    const size_t at = m_s->position();
    if (!expect('N')) return false;
    const char c = m_s->peek();
    if (isDigit(c)) {
        // A constant label: the check can verify it exists.
        const size_t start = m_s->position();
        int64_t value = 0;
        uint8_t digits = 0;
        if (!m_s->unsignedInteger(value, digits) || digits > 8) {
            return fail(start, "format", KERF_TR_NOOP("a label has at most 8 digits"));
        }
        const char next = m_s->peek();
        if (next == '\0' || next == ',' || next == ')' || isUpper(next)) {
            out = value;
            noteLabel(value, at, true);
            return true;
        }
        m_s->setPosition(start);
    }
    if (!integerExpression(out, 0, 99999999, "a label")) return false;
    noteLabel(out, at, false);
    return true;
}

bool StatementRunner::quoted(std::string& out) {
    m_s->skipBlanks();
    const std::string_view text = m_s->text();
    const size_t at = m_s->position();
    const size_t open = openingQuote(text, at);
    if (open == 0) return fail(at, "syntax", KERF_TR_NOOP("text in quotes expected"));
    for (size_t i = at + open; i < text.size(); ++i) {
        if (const size_t close = closingQuote(text, i)) {
            out = std::string(text.substr(at + open, i - at - open));
            m_s->setPosition(i + close);
            return true;
        }
    }
    return fail(at, "syntax", KERF_TR_NOOP("missing closing quote"));
}

bool StatementRunner::statement(bool allowIf) {
    const size_t at = m_s->position();
    m_s->skipBlanks();
    const std::string_view text = m_s->text();
    size_t end = m_s->position();
    while (end < text.size() && isUpper(text[end]))
        ++end;
    const std::string_view word = text.substr(m_s->position(), end - m_s->position());
    if (word.empty()) {
        const char c = m_s->peek();
        if (c == '\0') return fail(at, "syntax", KERF_TR_NOOP("empty high-level block"));
        if (isLower(c)) {
            return fail(m_s->position(), "syntax",
                        KERF_TR_NOOP("'{1}': words are written in upper case"),
                        {std::string(1, c)});
        }
        return fail(m_s->position(), "syntax", KERF_TR_NOOP("unexpected '{1}'"),
                    {std::string(1, c)});
    }
    const size_t wordAt = m_s->position();
    auto take = [&] { m_s->setPosition(end); };
    m_info.keyword = word;
    m_info.keywordOffset = wordAt;
    if (word == "ERROR" || word == "ERRO") {
        take();
        return errorStatement(wordAt);
    }
    if (word == "MSG") {
        take();
        std::string message;
        if (!quoted(message)) return false;
        if (executing() && !m_context->showMessage(message, m_problem))
            return contextFailed(wordAt);
        return true;
    }
    if (word == "DGWZ") {
        take();
        return graphicZone();
    }
    static constexpr std::pair<std::string_view, LockChange> kLocks[] = {
        {"ESBLK", LockChange::JoinBlocks},       {"DSBLK", LockChange::SeparateBlocks},
        {"DSTOP", LockChange::DisableStop},      {"ESTOP", LockChange::EnableStop},
        {"DFHOLD", LockChange::DisableFeedHold}, {"EFHOLD", LockChange::EnableFeedHold}};
    for (const auto& [name, change] : kLocks) {
        if (word != name) continue;
        take();
        if (executing() && !m_context->changeLocks(change, m_problem)) return contextFailed(wordAt);
        return true;
    }
    if (word == "GOTO") {
        take();
        int64_t label = 0;
        if (!labelExpression(label)) return false;
        if (executing() && !m_context->jump(label, m_problem)) return contextFailed(wordAt);
        return true;
    }
    if (word == "RPT") {
        take();
        int64_t first = 0, last = 0, program = 0;
        if (!labelExpression(first) || !expect(',') || !labelExpression(last)) return false;
        bool otherProgram = false;
        if (m_s->accept(',')) {
            if (!expect('P') || !integerExpression(program, 0, 999999, "a program number")) {
                return false;
            }
            otherProgram = true;
            m_info.labelCount = 0;  // labels of another program: checked when it runs
        }
        const int count = m_repetition < 0 ? 1 : m_repetition;
        if (executing() &&
            !m_context->repeat(
                first, last,
                otherProgram ? std::optional<int>(static_cast<int>(program)) : std::nullopt, count,
                m_problem)) {
            return contextFailed(wordAt);
        }
        return true;
    }
    if (word == "IF") {
        if (!allowIf) return fail(wordAt, "syntax", KERF_TR_NOOP("IF cannot be nested"));
        take();
        return ifStatement();
    }
    if (word == "SUB") {
        if (!allowIf) {
            return fail(wordAt, "syntax", KERF_TR_NOOP("SUB cannot be the action of an IF"));
        }
        take();
        int64_t number = 0;
        uint8_t digits = 0;
        if (!m_s->unsignedInteger(number, digits) || number > 20000) {
            return fail(m_s->position(), "syntax",
                        KERF_TR_NOOP("subroutine number 0-20000 expected after SUB"));
        }
        m_info.kind = StatementInfo::Kind::Sub;
        m_info.number = number;
        if (executing() &&
            !m_context->enterSubroutineDefinition(static_cast<int>(number), m_problem)) {
            return contextFailed(wordAt);
        }
        return true;
    }
    if (word == "RET") {
        take();
        m_info.kind = StatementInfo::Kind::Ret;
        if (executing() && !m_context->returnFromSubroutine(m_problem))
            return contextFailed(wordAt);
        return true;
    }
    if (word == "CALL" || word == "PCALL" || word == "MCALL") {
        take();
        return callStatement(word == "CALL"    ? CallKind::Call
                             : word == "PCALL" ? CallKind::PCall
                                               : CallKind::MCall);
    }
    if (word == "MDOFF") {
        take();
        if (executing() && !m_context->modalCallOff(m_problem)) return contextFailed(wordAt);
        return true;
    }
    if (word == "REPOS") {
        take();
        return reposition();
    }
    if (word == "EXEC" || word == "MEXEC" || word == "OPEN" || word == "WRITE") {
        take();
        return programStatement(word);
    }
    if (isCustomization(word)) {
        take();
        return customization(word);
    }
    return assignments();
}

bool StatementRunner::ifStatement() {
    ExprValue condition;
    if (!expression(condition)) return false;
    const bool saved = m_exec;
    const bool taken = condition.number != 0.0;
    m_exec = saved && taken;
    if (!statement(false)) return false;
    m_s->skipBlanks();
    const std::string_view rest = m_s->text().substr(m_s->position());
    if (rest.substr(0, 4) == "ELSE" && (rest.size() == 4 || !isUpper(rest[4]))) {
        m_s->advance(4);
        m_exec = saved && !taken;
        if (!statement(false)) return false;
    }
    m_exec = saved;
    return true;
}

bool StatementRunner::assignments() {
    // Several assignments to one target count as one.
    std::array<int64_t, 27> seen{};
    size_t count = 0;
    do {
        const size_t at = m_s->position();
        int64_t key = 0;
        if (!assignment(false, nullptr, key)) return false;
        if (std::find(seen.begin(), seen.begin() + static_cast<std::ptrdiff_t>(count), key) ==
            seen.begin() + static_cast<std::ptrdiff_t>(count)) {
            if (count == 26) {
                return fail(at, "syntax",
                            KERF_TR_NOOP("at most 26 assignments to different targets"));
            }
            seen[count++] = key;
        }
    } while (m_s->accept(','));
    return true;
}

// `key` identifies the target, so that a block's distinct targets can be counted.
bool StatementRunner::assignment(bool localsOnly, LocalAssignments* locals, int64_t& key) {
    const size_t at = m_s->position();
    if (isLower(m_s->peek())) {
        return fail(at, "syntax", KERF_TR_NOOP("'{1}': words are written in upper case"),
                    {std::string(1, m_s->peek())});
    }
    const std::string_view name = m_s->letters();
    if (name.empty()) {
        return fail(at, "syntax", KERF_TR_NOOP("parameter or variable expected"));
    }
    Expression e(*m_s, executing() ? m_context : nullptr);
    int parameter = -1;
    bool letter = false;
    VariableRef ref;
    if (name == "P" && (isDigit(m_s->peekRaw()) || m_s->peek() == '(')) {
        if (!e.parameterIndex(parameter)) {
            m_problem = e.problem();
            return false;
        }
    } else if (name.size() == 1) {
        parameter = name[0] - 'A';
        letter = true;
    } else {
        if (localsOnly) {
            return fail(at, "syntax",
                        KERF_TR_NOOP("a subroutine call passes local parameters (P0-P25, A-Z)"));
        }
        if (!e.variableRef(name, at, ref)) {
            m_problem = e.problem();
            return false;
        }
    }
    ExprValue value;
    const char c = m_s->peek();
    if (m_s->accept('=')) {
        if (!expression(value)) return false;
    } else if (letter && (c == '+' || c == '-' || isDigit(c) || c == '.')) {
        // Short form: (A13.7) is (P0=13.7); (M30) is (P12=30).
        double sign = 1.0;
        if (c == '+' || c == '-') {
            sign = c == '-' ? -1.0 : 1.0;
            m_s->advance();
        }
        if (!e.parseNumber(value.number)) {
            m_problem = e.problem();
            return false;
        }
        value.number *= sign;
    } else {
        return fail(m_s->position(), "syntax", KERF_TR_NOOP("'=' expected"));
    }
    key = parameter >= 0 ? parameter
                         : -(static_cast<int64_t>(ref.info->id) * 100000 +
                             static_cast<int64_t>(axisIndex(ref.axis)) * 10000 + ref.index + 1);
    if (!executing()) return true;
    if (locals != nullptr) {
        if (parameter < 0 || parameter > 25) {
            return fail(at, "parameter",
                        KERF_TR_NOOP("a subroutine call passes local parameters P0-P25, not P{1}"),
                        {std::to_string(parameter)});
        }
        locals->values[static_cast<size_t>(parameter)] = value.number;
        locals->defined |= 1u << parameter;
        return true;
    }
    const bool ok = parameter >= 0 ? m_context->writeParameter(parameter, value.number, m_problem)
                                   : m_context->writeVariable(ref, value.number, m_problem);
    return ok || contextFailed(at);
}

bool StatementRunner::errorStatement(size_t keywordAt) {
    std::optional<int> number;
    std::string text;
    const size_t at = m_s->position();
    const char c = m_s->peek();
    const std::string_view rest = m_s->text().substr(m_s->position());
    if (openingQuote(m_s->text(), m_s->position()) == 0) {
        if (c == 'P' && rest.size() > 1 && isDigit(rest[1])) {
            m_s->advance();
            int64_t p = 0;
            uint8_t digits = 0;
            if (!m_s->unsignedInteger(p, digits) || digits > 4) {
                return fail(at, "syntax", KERF_TR_NOOP("parameter number expected after P"));
            }
            double v = 0.0;
            if (executing() && !m_context->readParameter(static_cast<int>(p), v, m_problem)) {
                return contextFailed(at);
            }
            number = static_cast<int>(std::min(std::fabs(v), 1e9));
        } else if (isDigit(c)) {
            int64_t n = 0;
            uint8_t digits = 0;
            if (!m_s->unsignedInteger(n, digits) || digits > 9) {
                return fail(at, "syntax", KERF_TR_NOOP("error number expected"));
            }
            number = static_cast<int>(n);
        } else {
            return fail(at, "syntax",
                        KERF_TR_NOOP("ERROR takes a number, a parameter P0-P299 or a text"));
        }
        m_s->accept(',');  // the manual writes it with and without the comma
        m_s->skipBlanks();
        if (openingQuote(m_s->text(), m_s->position()) != 0 && !quoted(text)) return false;
    } else if (!quoted(text)) {
        return false;
    }
    if (executing() && !m_context->raiseError(number, text, m_problem)) {
        return contextFailed(keywordAt);
    }
    return true;
}

bool StatementRunner::callStatement(CallKind kind) {
    m_s->skipBlanks();
    const size_t at = m_s->position();
    int64_t number = 0;
    if (!integerExpression(number, 0, 20000, "a subroutine number")) return false;
    LocalAssignments locals;
    int count = 0;
    if (kind == CallKind::Call) {
        if (m_s->peek() == ',') {
            return fail(m_s->position(), "syntax",
                        KERF_TR_NOOP("CALL passes no parameters: use PCALL or MCALL"));
        }
    } else {
        while (m_s->accept(',')) {
            int64_t key = 0;
            if (!assignment(true, &locals, key)) return false;
            if (++count > 26) return fail(at, "syntax", KERF_TR_NOOP("at most 26 parameters"));
        }
    }
    if (executing() && !m_context->call(kind, static_cast<int>(number), locals, m_problem)) {
        return contextFailed(at);
    }
    return true;
}

bool StatementRunner::programStatement(std::string_view keyword) {
    m_s->skipBlanks();
    const size_t at = m_s->position();
    if (keyword == "WRITE") {
        const std::string_view text = m_s->text().substr(m_s->position());
        m_s->setPosition(m_end);
        if (executing() && !m_context->writeBlock(text, m_problem)) return contextFailed(at);
        return true;
    }
    if (!expect('P')) return false;
    m_info.opens = keyword == "OPEN";
    noteProgram(at);
    int64_t program = 0;
    if (!integerExpression(program, 0, 999999, "a program number")) return false;
    char mode = '\0';
    std::string comment;
    while (m_s->accept(',')) {
        m_s->skipBlanks();
        const size_t optionAt = m_s->position();
        if (openingQuote(m_s->text(), optionAt) != 0 && keyword == "OPEN") {
            if (!quoted(comment)) return false;
            continue;
        }
        const std::string_view option = m_s->letters();
        if (option == "DNC") {
            if (isDigit(m_s->peekRaw())) m_s->advance();
            m_info.kind = StatementInfo::Kind::DncDirectory;
            if (executing()) {
                return fail(optionAt, "not-available",
                            KERF_TR_NOOP("programs on a PC over DNC are not available: only "
                                         "programs in the NC root"));
            }
            continue;
        }
        if (keyword == "OPEN" && (option == "A" || option == "D") && mode == '\0') {
            mode = option[0];
            continue;
        }
        return fail(
            optionAt, "syntax", KERF_TR_NOOP("unexpected '{1}' in {2}"),
            {std::string(option.empty() ? std::string_view(",") : option), std::string(keyword)});
    }
    if (!executing()) return true;
    const int number = static_cast<int>(program);
    const bool ok = keyword == "OPEN"
                        ? m_context->openProgram(number, mode, comment, m_problem)
                        : m_context->executeProgram(keyword == "MEXEC", number, m_problem);
    return ok || contextFailed(at);
}

bool StatementRunner::reposition() {
    std::array<Axis, kAxisCount> axes{};
    int count = 0;
    do {
        const size_t at = m_s->position();
        const std::string_view letter = m_s->letters();
        const auto axis = letter.size() == 1 ? axisFromLetter(letter[0]) : std::nullopt;
        if (!axis) return fail(at, "syntax", KERF_TR_NOOP("axis letter expected in REPOS"));
        if (count >= kAxisCount) return fail(at, "syntax", KERF_TR_NOOP("too many axes in REPOS"));
        axes[static_cast<size_t>(count++)] = *axis;
    } while (m_s->accept(','));
    if (executing() && !m_context->reposition(axes, count, m_problem)) {
        return contextFailed(m_s->position());
    }
    return true;
}

bool StatementRunner::graphicZone() {
    const size_t at = m_s->position();
    ExprValue v[4];
    for (int i = 0; i < 4; ++i) {
        if (i > 0 && !expect(',')) return false;
        if (!expression(v[i])) return false;
    }
    if (executing() &&
        !m_context->graphicZone(v[0].number, v[1].number, v[2].number, v[3].number, m_problem)) {
        return contextFailed(at);
    }
    return true;
}

namespace {

// Customisation instructions take global parameters only (spec part 2 §6.8).
class GlobalsOnly final : public ExpressionContext {
public:
    explicit GlobalsOnly(ExpressionContext& inner) : m_inner(inner) {}
    bool readParameter(int number, double& out, Problem& problem) override {
        if (number >= 0 && number <= 25) {
            problem = Problem{0,
                              "parameter",
                              KERF_TR_NOOP("customisation instructions take global parameters, "
                                           "not the local P{1}"),
                              {std::to_string(number)}};
            return false;
        }
        return m_inner.readParameter(number, out, problem);
    }
    bool readVariable(const VariableRef& ref, double& out, Problem& problem) override {
        return m_inner.readVariable(ref, out, problem);
    }

private:
    ExpressionContext& m_inner;
};

}  // namespace

bool StatementRunner::screenNumbers(ScreenStatement& out,
                                    const std::array<std::pair<int, int>, 3>& ranges, int count,
                                    const std::array<const char*, 3>& names) {
    for (int i = 0; i < count; ++i) {
        const auto n = static_cast<size_t>(i);
        if (i > 0 && !expect(',')) return false;
        int64_t value = 0;
        if (!integerExpression(value, ranges[n].first, ranges[n].second, names[n])) return false;
        out.numbers[n] = static_cast<int>(value);
    }
    return true;
}

bool StatementRunner::inputFormat(InputFormat& out) {
    // [-]i[.d]: i integer digits 0-6, d decimals 0-5.
    m_s->skipBlanks();
    const size_t at = m_s->position();
    out.negative = m_s->accept('-');
    const std::string_view text = m_s->text();
    size_t i = m_s->position();
    auto digit = [&](int max, int& into) {
        if (i >= text.size() || !isDigit(text[i]) || text[i] - '0' > max) return false;
        into = text[i++] - '0';
        return true;
    };
    bool ok = digit(6, out.integerDigits);
    out.decimals = 0;
    if (ok && i < text.size() && text[i] == '.') {
        ++i;
        ok = digit(5, out.decimals);
    }
    if (!ok || (i < text.size() && isDigit(text[i]))) {
        return fail(at, "syntax",
                    KERF_TR_NOOP("input format [-]i.d expected (i integer digits 0-6, d decimals "
                                 "0-5)"));
    }
    m_s->setPosition(i);
    return true;
}

bool StatementRunner::windowData(std::string_view keyword, ScreenStatement& out) {
    int64_t window = 0;
    if (!integerExpression(window, 0, UserScreen::kWindows - 1, "a data window")) return false;
    ExprValue v;
    if (!expect('=') || !expression(v)) return false;
    std::string text = keyword == "DWH"   ? hexadecimalText(v.number)
                       : keyword == "DWB" ? binaryText(v.number)
                                          : decimalText(v.number);
    out.windows.push_back({static_cast<int>(window), std::move(text)});
    return true;
}

bool StatementRunner::customization(std::string_view keyword) {
    const size_t at = m_s->position() - keyword.size();
    m_info.kind = StatementInfo::Kind::Customization;
    std::optional<GlobalsOnly> globals;
    if (executing()) globals.emplace(*m_context);
    m_values = globals ? &*globals : nullptr;
    struct Restore {
        ExpressionContext*& values;
        ~Restore() { values = nullptr; }
    } restore{m_values};
    using Kind = ScreenStatement::Kind;
    ScreenStatement st;
    bool ok = true;
    if (keyword == "PAGE") {
        st.kind = Kind::Page;
        ok = screenNumbers(st, {{{0, 255}}}, 1, {"a user page"});
    } else if (keyword == "SYMBOL") {
        st.kind = Kind::Symbol;
        ok = screenNumbers(st, {{{0, 255}, {0, 639}, {0, 335}}}, 3,
                           {"a symbol", "a pixel column", "a pixel row"});
    } else if (keyword == "ODW") {
        st.kind = Kind::DefineWindow;
        ok = screenNumbers(st, {{{0, UserScreen::kWindows - 1}, {0, 20}, {0, 79}}}, 3,
                           {"a data window", "a text row", "a text column"});
    } else if (keyword == "IB") {
        st.kind = Kind::Input;
        int64_t index = 0;
        ok = integerExpression(index, 0, UserScreen::kInputs - 1, "an input variable") &&
             expect('=');
        st.index = static_cast<int>(index);
        if (ok && m_s->letters() != "INPUT")
            ok = fail(m_s->position(), "syntax", KERF_TR_NOOP("INPUT expected"));
        ok = ok && quoted(st.text);
        if (ok && m_s->accept(',')) {
            InputFormat format;
            ok = inputFormat(format);
            st.format = format;
        }
    } else if (keyword == "DW" || keyword == "DWH" || keyword == "DWB") {
        st.kind = Kind::ShowData;
        ok = windowData(keyword, st);
        while (ok && m_s->accept(',')) {
            m_s->skipBlanks();
            const size_t nextAt = m_s->position();
            const std::string_view next = m_s->letters();
            if (next != "DW" && next != "DWH" && next != "DWB") {
                ok = fail(nextAt, "syntax", KERF_TR_NOOP("DW expected"));
                break;
            }
            ok = windowData(next, st);
        }
    } else if (keyword == "SK") {
        st.kind = Kind::Softkeys;
        do {
            m_s->skipBlanks();
            if (m_s->peek() == 'S') {
                const size_t skAt = m_s->position();
                if (m_s->letters() != "SK") ok = fail(skAt, "syntax", KERF_TR_NOOP("SK expected"));
            }
            int64_t key = 0;
            std::string text;
            ok = ok && integerExpression(key, 1, UserScreen::kSoftkeys, "a softkey") && expect('=');
            const size_t textAt = m_s->position();
            ok = ok && quoted(text);
            if (ok && text.size() > 20) {
                ok =
                    fail(textAt, "range", KERF_TR_NOOP("a softkey text has at most 20 characters"));
            }
            st.softkeys.emplace_back(static_cast<int>(key), std::move(text));
        } while (ok && m_s->accept(','));
    } else if (keyword == "WKEY") {
        st.kind = Kind::WaitKey;
    } else if (keyword == "WBUF") {
        st.kind = Kind::InsertBlock;
        if (m_s->peek() != '\0') {
            st.kind = Kind::AppendToBlock;
            ok = quoted(st.text);
            if (ok && m_s->accept(',')) {
                ExprValue v;
                ok = expression(v);
                st.value = v.number;
            }
        }
    } else if (keyword == "SYSTEM") {
        st.kind = Kind::System;
    }
    if (!ok) return false;
    if (executing() && !m_context->screen(st, m_problem)) return contextFailed(at);
    return true;
}

}  // namespace kerf::fagor
