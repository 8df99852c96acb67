#include "core/interp/klartext/compiled_formula.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/interp/klartext/formula.h"

namespace kerf::klartext {

void CompiledFormula::clear() {
    m_steps.clear();
    m_depth = 0;
    m_maxDepth = 0;
}

void CompiledFormula::push(const Step& step, int depthChange) {
    m_steps.push_back(step);
    m_depth += depthChange;
    m_maxDepth = std::max(m_maxDepth, m_depth);
}

void CompiledFormula::pushNumber(double value) {
    Step step;
    step.number = value;
    push(step, 1);
}

void CompiledFormula::pushRead(QRef ref) {
    Step step;
    step.kind = Kind::Read;
    step.ref = ref;
    push(step, 1);
}

void CompiledFormula::pushFunction(UnaryFunction function) {
    Step step;
    step.kind = Kind::Function;
    step.function = function;
    push(step, 0);
}

void CompiledFormula::pushOperation(Operation operation) {
    Step step;
    step.kind = Kind::Operation;
    step.operation = operation;
    push(step, operation == Operation::Negate ? 0 : -1);
}

std::optional<double> CompiledFormula::evaluate(FormulaEnvironment& environment) const {
    std::array<double, kMaxDepth> stack;
    size_t top = 0;  // number of values on the stack
    for (const Step& step : m_steps) {
        switch (step.kind) {
            case Kind::Number:
                stack[top++] = step.number;
                continue;
            case Kind::Read: {
                const double value = environment.number(step.ref);
                if (!std::isfinite(value)) return std::nullopt;
                stack[top++] = value;
                continue;
            }
            case Kind::Function:
                stack[top - 1] = step.function(stack[top - 1]);
                if (!std::isfinite(stack[top - 1])) return std::nullopt;
                continue;
            case Kind::Operation:
                break;
        }
        if (step.operation == Operation::Negate) {
            stack[top - 1] = -stack[top - 1];
            continue;
        }
        const double right = stack[--top];
        double& left = stack[top - 1];
        switch (step.operation) {
            case Operation::Add:
                left = left + right;
                break;
            case Operation::Subtract:
                left = left - right;
                break;
            case Operation::Multiply:
                left = left * right;
                break;
            case Operation::Divide:
                if (right == 0.0) return std::nullopt;
                left = left / right;
                break;
            case Operation::Modulo:
                if (right == 0.0) return std::nullopt;
                left = std::fmod(left, right);
                break;
            case Operation::Power:
                left = std::pow(left, right);
                break;
            case Operation::Negate:
                break;
        }
        if (!std::isfinite(left)) return std::nullopt;
    }
    return stack[0];
}

}  // namespace kerf::klartext
