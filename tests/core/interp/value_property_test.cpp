// Property: whatever a program computes, no canonical command leaves an interpreter with a number
// that is not finite or beyond the stream's bound. Random formulas with large powers, products,
// quotients, functions and signs feed coordinates, feeds, arc centres, dwells, spindle speeds and
// repeat counts of both dialects; every command is then checked twice: by the stream's own rule
// and, independently, by reading the numbers of its trace line.
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/canon/trace_format.h"
#include "core/canon/value_limits.h"
#include "core/interp/fagor/fagor_interpreter.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf {
namespace {

// Every number of a trace line, read as the text says (inf and nan included).
std::vector<double> numbersOf(const std::string& line) {
    std::vector<double> out;
    const char* p = line.c_str();
    while (*p != '\0') {
        const bool starts =
            (*p >= '0' && *p <= '9') || *p == '-' || *p == '+' ||
            ((*p == 'i' || *p == 'n') && (std::string_view(p).substr(0, 3) == "inf" ||
                                          std::string_view(p).substr(0, 3) == "nan"));
        if (starts) {
            char* end = nullptr;
            const double value = std::strtod(p, &end);
            if (end != p) {
                out.push_back(value);
                p = end;
                continue;
            }
        }
        ++p;
    }
    return out;
}

class CheckingSink final : public canon::Sink {
public:
    void consume(const canon::Command& command) override {
        ++count;
        const auto unsafe = canon::findUnsafeValue(command.body);
        if (unsafe) {
            ADD_FAILURE() << program << "\nemitted " << unsafe->quantity << " = " << unsafe->value;
        }
        if (std::holds_alternative<canon::Message>(command.body)) return;  // text, not values
        std::string line;
        canon::TraceFormat format;
        format.axes = kXyzMask;
        canon::appendCommand(line, command, format);
        for (const double value : numbersOf(line)) {
            if (!(std::fabs(value) <= canon::kMaxStreamMagnitude)) {
                ADD_FAILURE() << program << "\ntrace: " << line;
                break;
            }
        }
    }
    std::string program;
    size_t count = 0;
};

// Random formulas in the syntax both dialects share: numbers, parameters, + - * /, signs and
// parentheses; each dialect adds its own power and functions.
class FormulaMaker {
public:
    FormulaMaker(std::mt19937& random, std::vector<std::string> operands,
                 std::vector<std::string> powers, std::vector<std::string> functions)
        : m_random(random),
          m_operands(std::move(operands)),
          m_powers(std::move(powers)),
          m_functions(std::move(functions)) {}

    std::string make(int depth = 0) {
        const int choice = pick(depth > 3 ? 2 : 7);
        switch (choice) {
            case 0:
            case 1:
                return m_operands[static_cast<size_t>(pick(static_cast<int>(m_operands.size())))];
            case 2:
                return make(depth + 1) + " " + "+-*/"[pick(4)] + " " + make(depth + 1);
            case 3:
                return "(" + make(depth + 1) + ")";
            case 4:
                return "-" + make(depth + 1);
            case 5:
                return m_powers[static_cast<size_t>(pick(static_cast<int>(m_powers.size())))];
            default:
                return m_functions[static_cast<size_t>(
                           pick(static_cast<int>(m_functions.size())))] +
                       "(" + make(depth + 1) + ")";
        }
    }
    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_random); }

private:
    std::mt19937& m_random;
    std::vector<std::string> m_operands;
    std::vector<std::string> m_powers;
    std::vector<std::string> m_functions;
};

class ValueProperty : public testing::Test {
protected:
    void SetUp() override {
        mill = *machine::loadMachine("mill");
        lathe = *machine::loadMachine("lathe");
    }
    machine::MachineConfig mill;
    machine::MachineConfig lathe;
    std::mt19937 random{20261127};
};

template <typename Interpreter>
void runChecked(Interpreter& interpreter, CheckingSink& sink, const std::string& text,
                const std::string& name, size_t& failed) {
    sink.program = text;
    if (!interpreter.loadText(text, name)) {
        ++failed;
        return;
    }
    interp::RunStatus status = interp::RunStatus::BudgetUsed;
    for (int slice = 0; slice < 200 && status != interp::RunStatus::Finished &&
                        status != interp::RunStatus::Failed;
         ++slice) {
        status = interpreter.run(sink, 1000);
        if (status == interp::RunStatus::NeedsSync) {
            interp::WorldSnapshot world;
            world.position = interpreter.nominalPosition();
            interpreter.resume(world);
        }
    }
    if (status == interp::RunStatus::Failed) {
        ++failed;
        // A refusal is an error with its place, never a silent stop.
        ASSERT_FALSE(interpreter.diagnostics().empty()) << text;
        const Diagnostic& last = interpreter.diagnostics().back();
        EXPECT_EQ(last.severity, Severity::Error) << text;
        EXPECT_GT(last.line, 0u) << text << last.format();
    }
}

TEST_F(ValueProperty, KlartextNeverEmitsAnUnsafeNumber) {
    FormulaMaker formula(random, {"1", "7.5", "999999", "Q1", "Q2", "Q3", "PI", "0.001"},
                         {"10 ^ 300", "10 ^ 200", "2 ^ 1000", "10 ^ -300", "Q1 ^ Q2"},
                         {"SQ ", "SIN ", "EXP ", "SQRT ", "ABS ", "TAN ", "INT "});
    CheckingSink sink;
    size_t refused = 0;
    const int programs = 1500;
    for (int n = 0; n < programs; ++n) {
        std::string text = "0 BEGIN PGM R MM\n";
        int line = 1;
        auto add = [&](const std::string& block) {
            text += std::to_string(line++) + " " + block + "\n";
        };
        for (int q = 1; q <= 5; ++q)
            add("Q" + std::to_string(q) + " = " + formula.make());
        add("L X+0 Y+0 Z+0 R0 FMAX");
        switch (formula.pick(7)) {
            case 0:
                add("L X+Q1 Y+Q2 FQ3");
                break;
            case 1:
                add("CC X+Q1 Y+Q2");
                add("C X+0 Y+0 DR+ F100");
                break;
            case 2:
                add("CYCL DEF 9.0 DWELL TIME");
                add("CYCL DEF 9.1 DWELL Q4");
                break;
            case 3:
                add("TOOL CALL 1 Z SQ5");
                add("M3");
                break;
            case 4:
                add("LBL 1");
                add("L IX+Q1 F100");
                add("LBL 0");
                add("CALL LBL 1 REPQ4");
                break;
            case 5:
                add("L X+(" + formula.make() + ") FMAX");
                break;
            default:
                add("CR X+Q1 Y+Q2 R+Q3 DR- F200");
                break;
        }
        text += std::to_string(line) + " END PGM R MM\n";
        program::SourceRegistry sources;
        klartext::KlartextSettings settings;
        settings.machine = &mill;
        klartext::KlartextInterpreter interpreter(sources, settings);
        runChecked(interpreter, sink, text, "R.H", refused);
    }
    // The programs reach both outcomes: most overflow somewhere, some run.
    EXPECT_GT(refused, 0u);
    EXPECT_LT(refused, static_cast<size_t>(programs));
    EXPECT_GT(sink.count, static_cast<size_t>(programs));
}

TEST_F(ValueProperty, FagorNeverEmitsAnUnsafeNumber) {
    FormulaMaker formula(random, {"1", "7.5", "99999", "P1", "P2", "P3", "PI", "0.001"},
                         {"10 EXP 300", "10 EXP 200", "2 EXP 1000", "10 EXP -300", "P1 EXP P2"},
                         {"SIN", "COS", "SQRT", "ABS", "TAN", "ROUND", "FUP"});
    CheckingSink sink;
    size_t refused = 0;
    const int programs = 1500;
    for (int n = 0; n < programs; ++n) {
        std::string text;
        for (int p = 1; p <= 5; ++p)
            text += "(P" + std::to_string(p) + "=" + formula.make() + ")\n";
        text += "G00 X0 Z0\n";
        switch (formula.pick(6)) {
            case 0:
                text += "G01 XP1 ZP2 FP3\n";
                break;
            case 1:
                text += "G01 X10 Z0 F100\nG02 XP1 ZP2 IP3 KP4\n";
                break;
            case 2:
                text += "G04 KP4\n";
                break;
            case 3:
                text += "G97 SP5 M03\n";
                break;
            case 4:
                text += "N10 G91 G01 XP1 F100\nN20 G90\n(RPT N10,N20) N3\n";
                break;
            default:
                text += "G01 X10 Z0 F100\nG03 XP1 ZP2 RP3\n";
                break;
        }
        text += "M30\n";
        program::SourceRegistry sources;
        fagor::FagorSettings settings;
        settings.machine = &lathe;
        fagor::FagorInterpreter interpreter(sources, settings);
        runChecked(interpreter, sink, text, "R.PIM", refused);
    }
    EXPECT_GT(refused, 0u);
    EXPECT_LT(refused, static_cast<size_t>(programs));
    EXPECT_GT(sink.count, static_cast<size_t>(programs));
}

}  // namespace
}  // namespace kerf
