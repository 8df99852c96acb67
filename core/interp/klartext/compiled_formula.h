#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/interp/klartext/q_parameters.h"

namespace kerf::klartext {

class FormulaEnvironment;

// A numeric formula as the one-pass parser evaluated it, recorded as postfix steps, so that a
// block executed again (a loop, a subprogram) is evaluated without being parsed again. Each step
// does the parser's arithmetic in the parser's order: the results are the same to the last bit.
class CompiledFormula {
public:
    using UnaryFunction = double (*)(double);
    enum class Operation : uint8_t { Add, Subtract, Multiply, Divide, Modulo, Power, Negate };

    // Deepest operand stack kept; deeper formulas are not recorded (they are parsed every time).
    static constexpr int kMaxDepth = 32;

    void clear();
    void pushNumber(double value);
    void pushRead(QRef ref);
    void pushFunction(UnaryFunction function);
    void pushOperation(Operation operation);
    // False when the formula is too deep to record.
    bool complete() const { return m_maxDepth <= kMaxDepth; }

    // The value, or nullopt where the parser reports an error (a value that is not finite, a
    // division by zero): the caller then parses the text again to report it where it is.
    std::optional<double> evaluate(FormulaEnvironment& environment) const;

private:
    enum class Kind : uint8_t { Number, Read, Function, Operation };
    struct Step {
        Kind kind = Kind::Number;
        Operation operation = Operation::Add;
        QRef ref;
        double number = 0.0;
        UnaryFunction function = nullptr;
    };
    void push(const Step& step, int depthChange);

    std::vector<Step> m_steps;
    int m_depth = 0;
    int m_maxDepth = 0;
};

}  // namespace kerf::klartext
