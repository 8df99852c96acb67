// Contour formula blocks (spec §8): SEL CONTOUR "program", DECLARE CONTOUR QC1 = "program"
// DEPTH5, QC10 = (QC1 | QC2) \ QC3, and the simple CONTOUR DEF P1 = "..." I2 = "..." DEPTH5.
#include "core/base/translate.h"
#include "core/interp/klartext/block_parser.h"
#include "core/interp/klartext/formula.h"

namespace kerf::klartext {

namespace {

constexpr long long kMaxDescriptor = 65535;
constexpr int kMaxNesting = 64;        // parentheses of one formula
constexpr size_t kMaxSimpleItems = 9;  // spec §8.2: up to 9 subcontours

using Step = ContourFormulaStep;

// Reads the operands and operators of one formula into postfix order. The four operators have
// one precedence and bind left to right (the spec's `(QC1 | QC2) \ QC3 \ QC4` is a chain).
class FormulaReader {
public:
    explicit FormulaReader(Cursor& cursor) : m_cur(cursor) {}

    bool expression(std::vector<Step>& out, int depth) {
        if (!operand(out, depth)) return false;
        while (true) {
            m_cur.skipBlanks();
            const size_t at = m_cur.position();
            Step::Kind kind;
            switch (m_cur.peekRaw()) {
                case '|':
                    kind = Step::Kind::Union;
                    break;
                case '&':
                    kind = Step::Kind::Intersection;
                    break;
                case '\\':
                    kind = Step::Kind::Difference;
                    break;
                case '^':
                    kind = Step::Kind::SymmetricDifference;
                    break;
                default:
                    return true;
            }
            m_cur.setPosition(at + 1);
            if (!operand(out, depth)) return false;
            out.push_back(Step{kind, 0, at});
        }
    }

    size_t problemAt = 0;
    const char* problem = nullptr;

private:
    bool operand(std::vector<Step>& out, int depth) {
        m_cur.skipBlanks();
        const size_t at = m_cur.position();
        if (m_cur.acceptChar('(')) {
            if (depth >= kMaxNesting) return fail(at, KERF_TR_NOOP("parentheses nested too deep"));
            if (!expression(out, depth + 1)) return false;
            m_cur.skipBlanks();
            if (!m_cur.acceptChar(')')) return fail(m_cur.position(), KERF_TR_NOOP("')' expected"));
            return true;
        }
        int number = 0;
        if (!descriptor(m_cur, number)) {
            return fail(at, KERF_TR_NOOP("a contour descriptor QC1 ... QC65535 or '(' expected"));
        }
        out.push_back(Step{Step::Kind::Descriptor, number, at});
        return true;
    }

    bool fail(size_t at, const char* text) {
        problemAt = at;
        problem = text;
        return false;
    }

    Cursor& m_cur;

public:
    static bool descriptor(Cursor& cur, int& out) {
        cur.skipBlanks();
        const size_t at = cur.position();
        if (!cur.acceptKeyword("QC")) return false;
        auto number = cur.unsignedInteger();
        if (!number || *number < 1 || *number > kMaxDescriptor) {
            cur.setPosition(at);
            return false;
        }
        out = static_cast<int>(*number);
        return true;
    }
};

}  // namespace

bool BlockParser::parseContourFormula(std::string_view head, const program::LogicalLine& line,
                                      size_t at, ParsedBlock& out) {
    Cursor cur(line.text, at);
    FormulaParser formula(cur, m_env);
    auto programName = [&](std::string& path) {
        auto quoted = cur.quoted();
        if (!quoted || quoted->empty()) {
            cur.skipBlanks();
            return failAt(cur.position(), "syntax",
                          KERF_TR_NOOP("program name in quotes expected"));
        }
        path = std::string(*quoted);
        return true;
    };
    auto depthWord = [&](double& depth, bool& present) {
        present = cur.acceptKeyword("DEPTH");
        if (!present) return true;
        cur.skipBlanks();
        const size_t valueAt = cur.position();
        auto value = formula.wordValue();
        if (!value) {
            if (formula.problem()) {
                m_problem = *formula.problem();
                return false;
            }
            return failAt(valueAt, "syntax", KERF_TR_NOOP("DEPTH value expected"));
        }
        depth = *value;
        return true;
    };
    auto end = [&] {
        if (cur.atEnd()) return true;
        return failAt(cur.position(), "syntax", KERF_TR_NOOP("unexpected text '{1}'"),
                      {std::string(cur.restUntilComment())});
    };

    if (head == "SEL") {
        cur.acceptKeyword("CONTOUR");
        SelectContour select;
        if (!programName(select.path) || !end()) return false;
        out.statement = std::move(select);
        return true;
    }
    if (head == "DECLARE") {
        cur.acceptKeyword("CONTOUR");
        DeclareContour declare;
        if (!FormulaReader::descriptor(cur, declare.descriptor)) {
            cur.skipBlanks();
            return failAt(cur.position(), "syntax",
                          KERF_TR_NOOP("a contour descriptor QC1 ... QC65535 expected"));
        }
        cur.skipBlanks();
        if (!cur.acceptChar('='))
            return failAt(cur.position(), "syntax", KERF_TR_NOOP("'=' expected"));
        if (!programName(declare.path) || !depthWord(declare.depth, declare.hasDepth) || !end())
            return false;
        out.statement = std::move(declare);
        return true;
    }
    if (head == "QC") {
        ContourFormula result;
        if (!FormulaReader::descriptor(cur, result.target)) {
            return failAt(at, "syntax",
                          KERF_TR_NOOP("a contour descriptor QC1 ... QC65535 expected"));
        }
        cur.skipBlanks();
        if (!cur.acceptChar('='))
            return failAt(cur.position(), "syntax", KERF_TR_NOOP("'=' expected"));
        FormulaReader reader(cur);
        if (!reader.expression(result.steps, 0))
            return failAt(reader.problemAt, "syntax", reader.problem);
        if (!end()) return false;
        out.statement = std::move(result);
        return true;
    }
    // A subcontour of CONTOUR DEF: a program "..." or a label of this program, LBL n or LBL "name".
    auto subcontour = [&](ContourDefinition::Item& item) {
        cur.skipBlanks();
        if (!cur.acceptKeyword("LBL")) return programName(item.path);
        cur.skipBlanks();
        item.offset = cur.position();
        LabelTarget target;
        if (auto name = cur.quoted()) {
            if (name->empty()) {
                return failAt(item.offset, "syntax", KERF_TR_NOOP("label name must not be empty"));
            }
            target.name = std::string(*name);
        } else {
            auto number = cur.unsignedInteger();
            if (!number || *number < 1 || *number > 65535) {
                return failAt(item.offset, "syntax",
                              KERF_TR_NOOP("a label number from 1 to 65535 or a name expected"));
            }
            target.number = static_cast<int>(*number);
        }
        item.label = std::move(target);
        return true;
    };
    // CONTOUR DEF P1 = "..." [DEPTHd] I2 = LBL 2 [DEPTHd] ...
    cur.acceptKeyword("DEF");
    ContourDefinition definition;
    while (!cur.atEnd()) {
        const size_t itemAt = cur.position();
        ContourDefinition::Item item;
        const char kind = upper(cur.peek());
        if (kind != 'P' && kind != 'I') {
            return failAt(itemAt, "syntax",
                          KERF_TR_NOOP("pocket P1 ... P9 or island I1 ... I9 expected"));
        }
        cur.setPosition(cur.position() + 1);
        item.island = kind == 'I';
        auto number = cur.unsignedInteger();
        if (!number || *number < 1 || *number > static_cast<long long>(kMaxSimpleItems)) {
            return failAt(itemAt, "syntax",
                          KERF_TR_NOOP("pocket P1 ... P9 or island I1 ... I9 expected"));
        }
        item.number = static_cast<int>(*number);
        cur.skipBlanks();
        if (!cur.acceptChar('='))
            return failAt(cur.position(), "syntax", KERF_TR_NOOP("'=' expected"));
        bool hasDepth = false;
        if (!subcontour(item) || !depthWord(item.depth, hasDepth)) return false;
        if (definition.items.size() >= kMaxSimpleItems) {
            return failAt(itemAt, "syntax",
                          KERF_TR_NOOP("CONTOUR DEF combines at most 9 subcontours"));
        }
        if (definition.items.empty() && item.island) {
            return failAt(itemAt, "syntax",
                          KERF_TR_NOOP("the first subcontour of CONTOUR DEF must be a pocket (P)"));
        }
        definition.items.push_back(std::move(item));
    }
    if (definition.items.empty()) {
        return failAt(cur.position(), "syntax",
                      KERF_TR_NOOP("CONTOUR DEF needs a pocket P1 = \"program\""));
    }
    out.statement = std::move(definition);
    return true;
}

}  // namespace kerf::klartext
