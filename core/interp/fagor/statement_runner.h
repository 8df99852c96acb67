#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/interp/fagor/expression.h"
#include "core/interp/fagor/user_screen.h"

namespace kerf::fagor {

// Local parameters a PCALL or MCALL passes to the subroutine (up to 26).
struct LocalAssignments {
    std::array<double, 26> values{};
    uint32_t defined = 0;  // bit n: P<n> given
};

enum class LockChange : uint8_t {
    JoinBlocks,
    SeparateBlocks,
    DisableStop,
    EnableStop,
    DisableFeedHold,
    EnableFeedHold
};

enum class CallKind : uint8_t { Call, PCall, MCall };

// A screen customisation instruction with its values (spec part 2 §6.8), ranges checked.
struct ScreenStatement {
    enum class Kind : uint8_t {
        Page,           // PAGE numbers[0]
        Symbol,         // SYMBOL numbers[0] at column numbers[1], row numbers[2]
        Input,          // IB index = INPUT text [, format]
        DefineWindow,   // ODW numbers[0] at row numbers[1], column numbers[2]
        ShowData,       // DW/DWH/DWB: windows
        Softkeys,       // SK: softkeys
        WaitKey,        // WKEY
        AppendToBlock,  // WBUF text [, value]
        InsertBlock,    // WBUF
        System,         // SYSTEM
    };
    struct WindowData {
        int window = 0;
        std::string text;  // the value as the window shows it
    };
    Kind kind = Kind::Page;
    std::array<int, 3> numbers{};
    int index = 0;
    std::string text;
    std::optional<InputFormat> format;
    std::optional<double> value;
    std::vector<WindowData> windows;
    std::vector<std::pair<int, std::string>> softkeys;
};

// What high-level statements do: the interpreter carries it out. Each returns false with
// `problem` filled (code and message; the runner sets the offset) when it cannot.
class StatementContext : public ExpressionContext {
public:
    virtual bool writeParameter(int number, double value, Problem& problem) = 0;
    virtual bool writeVariable(const VariableRef& ref, double value, Problem& problem) = 0;
    virtual bool jump(int64_t label, Problem& problem) = 0;
    // RPT: blocks `start` to `end` (both included) of `program` (nullopt: this one), `count` times.
    virtual bool repeat(int64_t start, int64_t end, std::optional<int> program, int count,
                        Problem& problem) = 0;
    virtual bool call(CallKind kind, int number, const LocalAssignments& locals,
                      Problem& problem) = 0;
    virtual bool enterSubroutineDefinition(int number, Problem& problem) = 0;
    virtual bool returnFromSubroutine(Problem& problem) = 0;
    virtual bool modalCallOff(Problem& problem) = 0;
    virtual bool executeProgram(bool modal, int program, Problem& problem) = 0;
    // OPEN: `mode` 'A' (append), 'D' (delete first) or '\0'.
    virtual bool openProgram(int program, char mode, std::string_view comment,
                             Problem& problem) = 0;
    virtual bool writeBlock(std::string_view text, Problem& problem) = 0;
    virtual bool raiseError(std::optional<int> number, std::string_view text, Problem& problem) = 0;
    virtual bool showMessage(std::string_view text, Problem& problem) = 0;
    virtual bool graphicZone(double zMin, double zMax, double inner, double outer,
                             Problem& problem) = 0;
    virtual bool changeLocks(LockChange change, Problem& problem) = 0;
    virtual bool screen(const ScreenStatement& statement, Problem& problem) = 0;
    // REPOS: axes in the order listed.
    virtual bool reposition(const std::array<Axis, kAxisCount>& axes, int count,
                            Problem& problem) = 0;
};

// Static facts about a statement, for the program check.
struct StatementInfo {
    enum class Kind : uint8_t { Other, Sub, Ret, Customization, DncDirectory };
    Kind kind = Kind::Other;
    int64_t number = -1;  // SUB n
    // Constant labels named by GOTO and RPT (without P) in the statement.
    std::array<int64_t, 4> labels{};
    std::array<size_t, 4> labelOffsets{};
    uint8_t labelCount = 0;
    bool flow = false;         // GOTO or RPT: the label index is needed
    int64_t program = -1;      // EXEC/MEXEC/OPEN P<constant>: the program it runs or writes
    size_t programOffset = 0;  // of its P
    bool opens = false;        // OPEN: a program the run creates (constant number or not)
    std::string_view keyword;
    size_t keywordOffset = 0;  // in the block text
};

// Reads one high-level statement (the text inside the block's parentheses) and, with a context,
// executes it (spec part 2 §6). Without a context it only checks the syntax and fills info().
class StatementRunner {
public:
    explicit StatementRunner(StatementContext* context) : m_context(context) {}

    // `text` is the block text, `begin`/`end` the statement inside the parentheses; `repetition`
    // the block's N count (-1: none).
    bool run(std::string_view text, size_t begin, size_t end, int repetition);
    const Problem& problem() const { return m_problem; }
    const StatementInfo& info() const { return m_info; }

private:
    bool statement(bool allowIf);
    bool assignments();
    bool assignment(bool localsOnly, LocalAssignments* locals, int64_t& key);
    bool expression(ExprValue& out);
    bool integerExpression(int64_t& out, double lo, double hi, const char* what);
    bool labelExpression(int64_t& out);
    bool quoted(std::string& out);
    bool expect(char c);
    bool endOfStatement();
    bool ifStatement();
    bool errorStatement(size_t keywordAt);
    bool callStatement(CallKind kind);
    bool programStatement(std::string_view keyword);
    bool customization(std::string_view keyword);
    bool screenNumbers(ScreenStatement& out, const std::array<std::pair<int, int>, 3>& ranges,
                       int count, const std::array<const char*, 3>& names);
    bool inputFormat(InputFormat& out);
    bool windowData(std::string_view keyword, ScreenStatement& out);
    bool reposition();
    bool graphicZone();
    bool fail(size_t offset, const char* code, const char* messageTemplate,
              std::vector<std::string> args = {});
    bool contextFailed(size_t offset);
    bool executing() const { return m_exec && m_context != nullptr; }
    void noteLabel(int64_t label, size_t offset, bool constant);
    void noteProgram(size_t offset);

    StatementContext* m_context;
    ExpressionContext* m_values = nullptr;  // instead of m_context for expressions, when set
    std::optional<Scanner> m_s;
    size_t m_end = 0;
    bool m_exec = false;
    int m_repetition = -1;
    Problem m_problem;
    StatementInfo m_info;
};

}  // namespace kerf::fagor
