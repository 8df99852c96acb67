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

TEST(FagorStatements, CustomisationIsNotSupported) {
    for (const char* s : {"PAGE 10", "SYMBOL 1, 2, 3", "IB1=INPUT \"X:\", -6.5", "ODW 1,10,60",
                          "DW1=DATE, DWH2=100", "SK 1=\"HELP\", SK 2=\"MAX\"", "WKEY",
                          "WBUF \"X\", P100", "WBUF", "SYSTEM"}) {
        EXPECT_EQ(failure(s).code, "not-supported") << s;
    }
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
