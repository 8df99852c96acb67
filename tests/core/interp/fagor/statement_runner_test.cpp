#include "core/interp/fagor/statement_runner.h"

#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace kerf::fagor {
namespace {

// Records what statements ask for.
class Recorder final : public StatementContext {
public:
    std::map<int, double> p;
    std::vector<std::string> log;

    bool readParameter(int n, double& out, Problem&) override {
        out = p[n];
        return true;
    }
    bool readVariable(const VariableRef&, double& out, Problem&) override {
        out = 5.0;
        return true;
    }
    bool writeParameter(int n, double v, Problem&) override {
        p[n] = v;
        return true;
    }
    bool writeVariable(const VariableRef& ref, double v, Problem& problem) override {
        if ((ref.info->flags & kWrite) == 0) {
            problem.code = "variable";
            return false;
        }
        log.push_back(std::string(ref.info->name) + "=" + std::to_string(static_cast<int>(v)));
        return true;
    }
    bool jump(int64_t label, Problem&) override {
        log.push_back("GOTO " + std::to_string(label));
        return true;
    }
    bool repeat(int64_t a, int64_t b, std::optional<int> program, int count, Problem&) override {
        log.push_back("RPT " + std::to_string(a) + "," + std::to_string(b) + "," +
                      (program ? std::to_string(*program) : "-") + "x" + std::to_string(count));
        return true;
    }
    bool call(CallKind kind, int n, const LocalAssignments& locals, Problem&) override {
        std::string s = kind == CallKind::Call    ? "CALL"
                        : kind == CallKind::PCall ? "PCALL"
                                                  : "MCALL";
        s += " " + std::to_string(n);
        for (int i = 0; i < 26; ++i) {
            if ((locals.defined & (1u << i)) != 0) {
                s += " P" + std::to_string(i) + "=" +
                     std::to_string(static_cast<int>(locals.values[static_cast<size_t>(i)]));
            }
        }
        log.push_back(s);
        return true;
    }
    bool enterSubroutineDefinition(int n, Problem&) override {
        log.push_back("SUB " + std::to_string(n));
        return true;
    }
    bool returnFromSubroutine(Problem&) override {
        log.push_back("RET");
        return true;
    }
    bool modalCallOff(Problem&) override {
        log.push_back("MDOFF");
        return true;
    }
    bool executeProgram(bool modal, int n, Problem&) override {
        log.push_back(std::string(modal ? "MEXEC " : "EXEC ") + std::to_string(n));
        return true;
    }
    bool openProgram(int n, char mode, std::string_view comment, Problem&) override {
        log.push_back("OPEN " + std::to_string(n) + (mode ? std::string(1, mode) : "") + " " +
                      std::string(comment));
        return true;
    }
    bool writeBlock(std::string_view text, Problem&) override {
        log.push_back("WRITE " + std::string(text));
        return true;
    }
    bool raiseError(std::optional<int> n, std::string_view text, Problem& problem) override {
        log.push_back("ERROR " + (n ? std::to_string(*n) : "-") + " " + std::string(text));
        problem.code = "program-error";
        return false;
    }
    bool showMessage(std::string_view text, Problem&) override {
        log.push_back("MSG " + std::string(text));
        return true;
    }
    bool graphicZone(double a, double b, double c, double d, Problem&) override {
        log.push_back("DGWZ " + std::to_string(static_cast<int>(a + b + c + d)));
        return true;
    }
    bool changeLocks(LockChange change, Problem&) override {
        log.push_back("LOCK " + std::to_string(static_cast<int>(change)));
        return true;
    }
    bool screen(const ScreenStatement& st, Problem&) override {
        screens.push_back(st);
        return true;
    }
    std::vector<ScreenStatement> screens;
    bool reposition(const std::array<Axis, kAxisCount>& axes, int count, Problem&) override {
        std::string s = "REPOS";
        for (int i = 0; i < count; ++i)
            s += axisLetter(axes[static_cast<size_t>(i)]);
        log.push_back(s);
        return true;
    }
};

bool run(Recorder& r, std::string_view statement, int repetition = -1) {
    StatementRunner runner(&r);
    const std::string text = "(" + std::string(statement) + ")";
    return runner.run(text, 1, text.size() - 1, repetition);
}

Problem failure(std::string_view statement) {
    Recorder r;
    StatementRunner runner(&r);
    const std::string text = "(" + std::string(statement) + ")";
    EXPECT_FALSE(runner.run(text, 1, text.size() - 1, -1)) << statement;
    return runner.problem();
}

TEST(FagorStatements, AssignmentsLeftToRight) {
    Recorder r;
    r.p = {{1, 1}, {2, 2}, {3, 3}, {4, 4}, {5, 5}};
    ASSERT_TRUE(run(r, "P1=P1+P2, P1=P1+P3, P1=P1*P4, P1=P1/P5"));
    EXPECT_DOUBLE_EQ(r.p[1], (1.0 + 2 + 3) * 4 / 5);
    ASSERT_TRUE(run(r, "A13.7"));
    EXPECT_DOUBLE_EQ(r.p[0], 13.7);
    ASSERT_TRUE(run(r, "B=-2, C-4"));
    EXPECT_DOUBLE_EQ(r.p[1], -2.0);
    EXPECT_DOUBLE_EQ(r.p[2], -4.0);
    // The manual's pitfall: inside parentheses M30 is P12 = 30.
    ASSERT_TRUE(run(r, "M30"));
    EXPECT_DOUBLE_EQ(r.p[12], 30.0);
    ASSERT_TRUE(run(r, "TOX3=P111"));
    EXPECT_EQ(r.log.back(), "TOX=0");
}

TEST(FagorStatements, IfElseRunsOneAction) {
    Recorder r;
    r.p[8] = 12.8;
    ASSERT_TRUE(run(r, "IF (P8 EQ 12.8) CALL 3 ELSE PCALL 5, A2, B5, D8"));
    EXPECT_EQ(r.log.back(), "CALL 3");
    r.p[8] = 1;
    ASSERT_TRUE(run(r, "IF (P8 EQ 12.8) CALL 3 ELSE PCALL 5, A2, B5, D8"));
    EXPECT_EQ(r.log.back(), "PCALL 5 P0=2 P1=5 P3=8");
    r.p[4] = 10;  // E is P4 (A = P0); the seed's "P5 (E)" contradicts its own A = P0 rule
    ASSERT_TRUE(run(r, "IF (E EQ 10) M10"));
    EXPECT_DOUBLE_EQ(r.p[12], 10.0);
    ASSERT_TRUE(run(r, "IF KEY EQ 5 GOTO N1000"));  // a condition without parentheses
    EXPECT_EQ(r.log.back(), "GOTO 1000");
    ASSERT_TRUE(run(r, "IF (P4+P3 GE P2) P4=P2 ELSE P4=P4+P3"));
}

TEST(FagorStatements, FlowAndPrograms) {
    Recorder r;
    r.p[7] = 20;
    ASSERT_TRUE(run(r, "RPT N10, N20", 3));
    EXPECT_EQ(r.log.back(), "RPT 10,20,-x3");
    ASSERT_TRUE(run(r, "RPT N(P7-10), N(P7), P123"));
    EXPECT_EQ(r.log.back(), "RPT 10,20,123x1");
    ASSERT_TRUE(run(r, "PCALL 10, P0=20, P1=-10"));
    EXPECT_EQ(r.log.back(), "PCALL 10 P0=20 P1=-10");
    ASSERT_TRUE(run(r, "MCALL 10"));
    ASSERT_TRUE(run(r, "MDOFF"));
    ASSERT_TRUE(run(r, "EXEC P12345"));
    EXPECT_EQ(r.log.back(), "EXEC 12345");
    ASSERT_TRUE(run(r, "OPEN P12345, D, \"PARABOLA\""));
    EXPECT_EQ(r.log.back(), "OPEN 12345D PARABOLA");
    ASSERT_TRUE(run(r, "WRITE G01 XP4 ZP5"));
    EXPECT_EQ(r.log.back(), "WRITE G01 XP4 ZP5");
    ASSERT_TRUE(run(r, "WRITE (SUB ?P102)"));
    EXPECT_EQ(r.log.back(), "WRITE (SUB ?P102)");
    ASSERT_TRUE(run(r, "REPOS X, Z"));
    EXPECT_EQ(r.log.back(), "REPOSXZ");
    ASSERT_TRUE(run(r, "DSTOP"));
    EXPECT_EQ(r.log.back(), "LOCK 2");
    ASSERT_TRUE(run(r, "MSG \"Verificar ferramenta\""));
    EXPECT_EQ(r.log.back(), "MSG Verificar ferramenta");
    ASSERT_TRUE(run(r, "MSG \xE2\x80\x9EVerificar\xE2\x80\x9C"));  // the seed's quotes
    EXPECT_EQ(r.log.back(), "MSG Verificar");
}

TEST(FagorStatements, ErrorForms) {
    Recorder r;
    r.p[100] = 5;
    EXPECT_FALSE(run(r, "ERROR 5"));
    EXPECT_EQ(r.log.back(), "ERROR 5 ");
    EXPECT_FALSE(run(r, "ERROR P100, \"Erro do usuario\""));
    EXPECT_EQ(r.log.back(), "ERROR 5 Erro do usuario");
    EXPECT_FALSE(run(r, "ERROR 3 \"x\""));  // the manual also omits the comma
    EXPECT_EQ(r.log.back(), "ERROR 3 x");
    EXPECT_FALSE(run(r, "ERRO \"Erro do usuario\""));  // the seed's spelling
    EXPECT_EQ(r.log.back(), "ERROR - Erro do usuario");
}

TEST(FagorStatements, CheckOnlyReportsStaticFacts) {
    StatementRunner runner(nullptr);
    const std::string sub = "(SUB 12)";
    ASSERT_TRUE(runner.run(sub, 1, sub.size() - 1, -1));
    EXPECT_EQ(runner.info().kind, StatementInfo::Kind::Sub);
    EXPECT_EQ(runner.info().number, 12);
    const std::string jump = "(IF (P1 EQ 2) GOTO N100 ELSE GOTO N(P3))";
    ASSERT_TRUE(runner.run(jump, 1, jump.size() - 1, -1));
    EXPECT_EQ(runner.info().labelCount, 1);
    EXPECT_EQ(runner.info().labels[0], 100);
    EXPECT_TRUE(runner.info().flow);
    const std::string page = "(ODW 1, 6, 33)";
    ASSERT_TRUE(runner.run(page, 1, page.size() - 1, -1));
    EXPECT_EQ(runner.info().kind, StatementInfo::Kind::Customization);
}

TEST(FagorStatements, CustomisationInstructionsCarryTheirValues) {
    using Kind = ScreenStatement::Kind;
    Recorder r;
    r.p[100] = 10;
    r.p[101] = 3;
    ASSERT_TRUE(run(r, "PAGE (P101+7)"));
    EXPECT_EQ(r.screens.back().kind, Kind::Page);
    EXPECT_EQ(r.screens.back().numbers[0], 10);
    ASSERT_TRUE(run(r, "SYMBOL 7, 639, 335"));
    EXPECT_EQ(r.screens.back().numbers, (std::array<int, 3>{7, 639, 335}));
    ASSERT_TRUE(run(r, "ODW 2, 14, 33"));
    EXPECT_EQ(r.screens.back().kind, Kind::DefineWindow);
    EXPECT_EQ(r.screens.back().numbers, (std::array<int, 3>{2, 14, 33}));
    // EX-12.14: the three number formats of the manual.
    ASSERT_TRUE(run(r, "DW1 = 100, DWH2 = 100, DWB3 = 100, DW 4=P100/4"));
    const auto& w = r.screens.back().windows;
    ASSERT_EQ(w.size(), 4u);
    EXPECT_EQ(w[0].window, 1);
    EXPECT_EQ(w[0].text, "100");
    EXPECT_EQ(w[1].text, "64");
    EXPECT_EQ(w[2].text, "01100100");
    EXPECT_EQ(w[3].window, 4);
    EXPECT_EQ(w[3].text, "2.5");
    ASSERT_TRUE(run(r, "SK 1=\"CICLO 1\",SK 2=\"CICLO 2\",SK 7=\"SALIR\""));
    const auto& keys = r.screens.back().softkeys;
    ASSERT_EQ(keys.size(), 3u);
    EXPECT_EQ(keys[2], (std::pair<int, std::string>{7, "SALIR"}));
    ASSERT_TRUE(run(r, "IB 1=INPUT \"X:\",-6.5"));
    const ScreenStatement& input = r.screens.back();
    EXPECT_EQ(input.kind, Kind::Input);
    EXPECT_EQ(input.index, 1);
    EXPECT_EQ(input.text, "X:");
    ASSERT_TRUE(input.format.has_value());
    EXPECT_TRUE(input.format->negative);
    EXPECT_EQ(input.format->integerDigits, 6);
    EXPECT_EQ(input.format->decimals, 5);
    ASSERT_TRUE(run(r, "IB2=INPUT \"Feed\", 5.4"));
    EXPECT_FALSE(r.screens.back().format->negative);
    ASSERT_TRUE(run(r, "IB3=INPUT \"No wait\""));
    EXPECT_FALSE(r.screens.back().format.has_value());
    ASSERT_TRUE(run(r, "WBUF \"X\", P100"));
    EXPECT_EQ(r.screens.back().kind, Kind::AppendToBlock);
    EXPECT_EQ(r.screens.back().value, 10.0);
    ASSERT_TRUE(run(r, "WBUF \"X P100\""));
    EXPECT_FALSE(r.screens.back().value.has_value());
    ASSERT_TRUE(run(r, "WBUF"));
    EXPECT_EQ(r.screens.back().kind, Kind::InsertBlock);
    ASSERT_TRUE(run(r, "WKEY"));
    EXPECT_EQ(r.screens.back().kind, Kind::WaitKey);
    ASSERT_TRUE(run(r, "IF KEY EQ $FC06 SYSTEM ELSE GOTO N5"));
    EXPECT_EQ(r.log.back(), "GOTO 5");  // KEY reads 5 here
}

TEST(FagorStatements, CustomisationErrorsAtTheirValue) {
    EXPECT_EQ(failure("ODW 26, 1, 1").messageTemplate,
              "{1} must be a whole number from {2} to {3}, not {4}");
    EXPECT_EQ(failure("ODW 1, 21, 1").args[0], "a text row");
    EXPECT_EQ(failure("ODW 1, 1, 80").args[0], "a text column");
    EXPECT_EQ(failure("PAGE 256").args[0], "a user page");
    EXPECT_EQ(failure("SYMBOL 1, 640, 0").args[0], "a pixel column");
    EXPECT_EQ(failure("SK 8=\"X\"").args[0], "a softkey");
    EXPECT_EQ(failure("SK 1=\"123456789012345678901\"").offset, 6u);
    EXPECT_EQ(failure("IB26=INPUT \"X\"").args[0], "an input variable");
    EXPECT_EQ(failure("IB1=INPUT \"X\", 7.1").offset, 16u);
    EXPECT_EQ(failure("IB1=INPUT \"X\", 6.6").code, "syntax");
    EXPECT_EQ(failure("DW1=1, ODW 2").messageTemplate, "DW expected");
    // Customisation instructions take no local parameters (spec part 2 §6.8).
    const Problem local = failure("DW1=P3");
    EXPECT_EQ(local.code, "parameter");
    EXPECT_EQ(local.args[0], "3");
    EXPECT_EQ(failure("PAGE A").code, "parameter");
}

TEST(FagorStatements, SyntaxErrors) {
    EXPECT_EQ(failure("").messageTemplate, "empty high-level block");
    EXPECT_EQ(failure("IF (1 EQ 1) IF (2 EQ 2) P1=1").messageTemplate, "IF cannot be nested");
    EXPECT_EQ(failure("IF (1 EQ 1) SUB 3").code, "syntax");
    EXPECT_EQ(failure("CALL 3, A1").code, "syntax");
    EXPECT_EQ(failure("GOTO 10").messageTemplate, "'{1}' expected");
    EXPECT_EQ(failure("P1=").messageTemplate, "value expected");
    EXPECT_EQ(failure("GPOSX N1 P2 = 3").code, "variable");  // read-only
    EXPECT_EQ(failure("PCALL 3, TOX1=2").code, "syntax");
    EXPECT_EQ(failure("EXEC P3, DNC").code, "not-available");
    EXPECT_EQ(failure("P1=1 P2=2").code, "syntax");
}

}  // namespace
}  // namespace kerf::fagor
