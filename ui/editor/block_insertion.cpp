#include "ui/editor/block_insertion.h"

#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <unordered_map>

namespace kerf::ui {

namespace {

using Kind = RenumberProblem::Kind;

// Where the line's words start: after its number and the blanks that follow it.
int wordsStart(QStringView line, const BlockNumber& number) {
    int pos = number.length;
    while (pos < line.size() && (line[pos] == QLatin1Char(' ') || line[pos] == QLatin1Char('\t')))
        ++pos;
    return pos;
}

QString numberPrefix(long long number, program::Dialect dialect) {
    return dialect == program::Dialect::Klartext ? QStringLiteral("%1 ").arg(number)
                                                 : QStringLiteral("N%1 ").arg(number);
}

// The line (1-based, after the insertion) of a line given 0-based before it.
int lineAfterInsertion(int line, int insertedAt) {
    return line >= insertedAt ? line + 2 : line + 1;
}

// The first line (0-based) outside `moved` that carries each FAGOR label.
std::unordered_map<long long, int> labelsThatStay(const QTextDocument& document,
                                                  const std::vector<BlockInsertion::Move>& moves) {
    std::unordered_map<long long, int> labels;
    auto move = moves.begin();
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        if (move != moves.end() && move->line == block.blockNumber()) {
            ++move;
            continue;
        }
        if (const auto number = readBlockNumber(block.text(), program::Dialect::Fagor))
            labels.emplace(number->number, block.blockNumber());
    }
    return labels;
}

// Why the FAGOR labels cannot move as planned; lines as they are after the insertion.
std::optional<RenumberProblem> labelProblem(const QTextDocument& document,
                                            const BlockInsertion& plan, long long newLabel,
                                            int insertedAt) {
    if (newLabel > kFagorMaxLabel)
        return RenumberProblem{Kind::LabelTooLong, insertedAt + 1, newLabel};
    for (const auto& move : plan.moves) {
        if (move.wanted > kFagorMaxLabel)
            return RenumberProblem{Kind::LabelTooLong, lineAfterInsertion(move.line, insertedAt),
                                   move.wanted};
    }
    const auto staying = labelsThatStay(document, plan.moves);
    auto inUse = [&](long long label, int line) -> std::optional<RenumberProblem> {
        const auto found = staying.find(label);
        if (found == staying.end()) return std::nullopt;
        RenumberProblem problem{Kind::LabelInUse, line, label};
        problem.otherLine = lineAfterInsertion(found->second, insertedAt);
        return problem;
    };
    if (auto problem = inUse(newLabel, insertedAt + 1)) return problem;
    for (const auto& move : plan.moves) {
        if (auto problem = inUse(move.wanted, lineAfterInsertion(move.line, insertedAt)))
            return problem;
    }
    if (plan.renamed.empty()) return std::nullopt;
    auto problem = fagorReferenceProblem(document, plan.renamed);
    if (problem) problem->line = lineAfterInsertion(problem->line - 1, insertedAt);
    return problem;
}

}  // namespace

BlockInsertion planBlockInsertion(const QTextDocument& document, const QTextCursor& cursor,
                                  program::Dialect dialect, bool renumberFollowing) {
    BlockInsertion plan;
    const QTextBlock block = cursor.block();
    const QString text = block.text();
    const bool continuation = dialect == program::Dialect::Klartext && block.previous().isValid() &&
                              continuesOnNextLine(block.previous().text());
    const auto own = continuation ? std::nullopt : readBlockNumber(text, dialect);
    if (own) {
        const int words = wordsStart(text, *own);
        const int at = cursor.positionInBlock();
        plan.before = at < words || (at == words && words < text.size());
        if (plan.before) plan.prefix = numberPrefix(own->number, dialect);
    }
    if (!plan.before) plan.prefix = nextBlockPrefix(text, block.previous().text(), dialect);
    if (plan.prefix.isEmpty()) return plan;
    const long long newLabel = readBlockNumber(plan.prefix, dialect)->number;
    if (renumberFollowing) {
        BlockCounter counter(dialect, newLabel);
        for (QTextBlock next = plan.before ? block : block.next(); next.isValid();
             next = next.next()) {
            const long long previous = counter.last();
            const auto numbered = counter.next(next.text());
            if (!numbered) continue;
            // ISO numbers only need to keep ascending.
            if (dialect != program::Dialect::Klartext && numbered->current.number > previous) break;
            if (numbered->current.number == numbered->wanted) continue;
            plan.moves.push_back({next.blockNumber(), numbered->current, numbered->wanted});
            if (dialect == program::Dialect::Fagor)
                plan.renamed.emplace(numbered->current.number, numbered->wanted);
        }
    }
    if (dialect != program::Dialect::Fagor) return plan;
    // The new line is line block.blockNumber() + 1 (0-based) after the cursor's, or takes the
    // cursor line's place before it.
    const int insertedAt = plan.before ? block.blockNumber() : block.blockNumber() + 1;
    plan.problem = labelProblem(document, plan, newLabel, insertedAt);
    if (plan.problem) {
        plan.prefix.clear();
        plan.moves.clear();
        plan.renamed.clear();
    }
    return plan;
}

}  // namespace kerf::ui
