#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/interp/klartext/cursor.h"
#include "core/interp/klartext/formula_cache.h"
#include "core/interp/klartext/q_parameters.h"

namespace kerf::klartext {

// What a formula may read while it is evaluated.
class FormulaEnvironment {
public:
    virtual ~FormulaEnvironment() = default;
    virtual double number(QRef ref) = 0;
    virtual const std::string& string(uint16_t index) = 0;
    virtual bool stringDefined(uint16_t index) = 0;
    // SYSSTR(ID.. NR..): system strings (program name, date); empty if unknown.
    virtual std::optional<std::string> systemString(int id, int nr) = 0;
};

// Deepest nesting of parentheses, functions and signs in one formula (the parser recurses).
inline constexpr int kMaxFormulaNesting = 256;

// Longest string a QS parameter holds (TNC 320: 255 characters).
inline constexpr size_t kMaxStringLength = 255;

struct ParseProblem {
    size_t offset = 0;
    std::string code;
    std::string messageTemplate;
    std::vector<std::string> args;
};

// Parses and evaluates TNC formulas in one pass. Precedence, highest first: parentheses and
// functions (SIN Q1 * 2 is (SIN Q1) * 2), signs, powers (^, left to right), * / %, + -. Angles in
// degrees. Without an environment the parser only checks syntax and every value reads as 0.
class FormulaParser {
public:
    // With a cache, expression() evaluates formulas it has parsed before from their compiled form.
    FormulaParser(Cursor& cursor, FormulaEnvironment* environment, FormulaCache* cache = nullptr)
        : m_cursor(cursor), m_env(environment), m_cache(cache) {}

    std::optional<double> expression();
    std::optional<std::string> stringExpression();
    // "+Q1", "-5", "Q2", "+QL3": the operands of FN 0..FN 13 and jump conditions.
    std::optional<double> signedOperand();
    // A Q/QL/QR/QS reference; `strings` allows QS.
    std::optional<QRef> parameter(bool strings);
    // A value after a keyword such as X, F or LEN: signed number, signed Q reference or
    // "(formula)".
    std::optional<double> wordValue();

    const std::optional<ParseProblem>& problem() const { return m_problem; }
    bool checkOnly() const { return m_env == nullptr; }

private:
    std::optional<double> additive();
    std::optional<double> multiplicative();
    std::optional<double> power();
    std::optional<double> unary();
    std::optional<double> primary();
    std::optional<double> stringFunction(std::string_view name);
    std::optional<std::string> stringTerm();
    std::optional<std::string> stringSource(std::string_view prefix);
    std::optional<double> tagValue(std::string_view tag);
    std::optional<double> read(QRef ref);
    std::optional<double> fail(std::string code, std::string messageTemplate,
                               std::vector<std::string> args = {});
    // An error at `at` (the function's name or the operator) when `value` is not a number.
    std::optional<double> domainCheck(double value, const char* what, size_t at);
    // An arithmetic result that is not finite is an overflow, reported at its operator.
    std::optional<double> overflowCheck(double value, size_t operatorOffset, char op);
    // Parses and evaluates the formula at the cursor, recording it into `entry`.
    std::optional<double> recordExpression(FormulaCache::Entry& entry, std::string_view text);
    void record(CompiledFormula::Operation operation) {
        if (m_recording) m_recording->pushOperation(operation);
    }

    Cursor& m_cursor;
    FormulaEnvironment* m_env;
    FormulaCache* m_cache;
    CompiledFormula* m_recording = nullptr;  // while expression() records
    bool m_recordable = true;                // false once the formula uses what cannot be recorded
    std::optional<ParseProblem> m_problem;
    size_t m_problemOffset = 0;
    int m_depth = 0;
};

}  // namespace kerf::klartext
