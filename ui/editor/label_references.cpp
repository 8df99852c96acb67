#include "ui/editor/label_references.h"

#include <QRegularExpression>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>
#include <vector>

namespace kerf::ui {

namespace {

// Renames the label numbers in capture groups 1 to `groups` of every match of `pattern` in
// text[0, end).
void renameIn(QString& text, int end, const QRegularExpression& pattern, int groups,
              const RenamedLabels& renamed) {
    int shift = 0;
    auto it = pattern.globalMatch(text.left(end));
    QString out = text;
    while (it.hasNext()) {
        const QRegularExpressionMatch m = it.next();
        for (int g = 1; g <= groups; ++g) {
            if (m.capturedStart(g) < 0) continue;
            bool ok = false;
            const long long number = m.captured(g).toLongLong(&ok);
            const auto found = ok ? renamed.find(number) : renamed.end();
            if (found == renamed.end()) continue;
            const QString replacement = QString::number(found->second);
            out.replace(m.capturedStart(g) + shift, m.capturedLength(g), replacement);
            shift += replacement.size() - m.capturedLength(g);
        }
    }
    text = out;
}

// The code of a line, without its comment.
QStringView codeOf(QStringView line) {
    const qsizetype comment = line.indexOf(QLatin1Char(';'));
    return comment < 0 ? line : line.left(comment);
}

const QRegularExpression& profileCycle() {
    static const QRegularExpression pattern(QStringLiteral("(?<![A-Za-z0-9.])G0*6[689](?![0-9.])"),
                                            QRegularExpression::CaseInsensitiveOption);
    return pattern;
}

const QRegularExpression& otherProgramProfile() {
    static const QRegularExpression pattern(QStringLiteral("(?<![A-Za-z])Q\\s*\\d"),
                                            QRegularExpression::CaseInsensitiveOption);
    return pattern;
}

// A profile cycle of this program: its S and E name labels here.
bool namesProfileHere(QStringView code) {
    const QString text = code.toString();
    return text.contains(profileCycle()) && !text.contains(otherProgramProfile());
}

// Whether the line jumps to or repeats a label, or names a profile's, through a parameter or an
// expression (N P1, N(P1+10), S P3): a renumbering cannot know where it points.
bool hasComputedReference(QStringView code) {
    static const QRegularExpression kGoto(QStringLiteral("\\(\\s*GOTO\\b"),
                                          QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression kLiteralGoto(QStringLiteral("\\(\\s*GOTO\\s*N\\d+\\s*\\)"),
                                                 QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression kRepeat(QStringLiteral("\\(\\s*RPT\\b([^)]*)\\)"),
                                            QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression kLiteralRepeat(
        QStringLiteral("^\\s*N\\d+\\s*,\\s*N\\d+\\s*(,\\s*P.*)?$"),
        QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression kComputedFirstLast(
        QStringLiteral("(?<![A-Za-z])[SE]\\s*(?=[^\\d\\s])"),
        QRegularExpression::CaseInsensitiveOption);
    const QString text = code.toString();
    if (text.contains(kGoto) && !text.contains(kLiteralGoto)) return true;
    for (auto it = kRepeat.globalMatch(text); it.hasNext();) {
        if (!kLiteralRepeat.match(it.next().captured(1)).hasMatch()) return true;
    }
    if (namesProfileHere(code)) {
        // The cycle's own word (G66 ...) is no label; only S and E are looked at.
        if (text.contains(kComputedFirstLast)) return true;
    }
    return false;
}

// The profile labels (S, E) a cycle of this program names.
std::vector<long long> profileLabels(QStringView code) {
    static const QRegularExpression kFirstLast(QStringLiteral("(?<![A-Za-z])[SE]\\s*(\\d+)"),
                                               QRegularExpression::CaseInsensitiveOption);
    std::vector<long long> labels;
    if (!namesProfileHere(code)) return labels;
    for (auto it = kFirstLast.globalMatch(code.toString()); it.hasNext();)
        labels.push_back(it.next().captured(1).toLongLong());
    return labels;
}

}  // namespace

QString withRenamedLabels(QStringView line, const RenamedLabels& renamed) {
    static const QRegularExpression kGoto(QStringLiteral("\\(\\s*GOTO\\s*N(\\d+)"),
                                          QRegularExpression::CaseInsensitiveOption);
    // The count after RPT's parenthesis (N3) is no label; with a P the labels are another
    // program's.
    static const QRegularExpression kRepeat(
        QStringLiteral("\\(\\s*RPT\\s*N(\\d+)\\s*,\\s*N(\\d+)\\s*\\)"),
        QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression kFirstLast(QStringLiteral("(?<![A-Za-z])[SE]\\s*(\\d+)"),
                                               QRegularExpression::CaseInsensitiveOption);
    QString text = line.toString();
    const int comment = text.indexOf(QLatin1Char(';'));
    const int end = comment < 0 ? text.size() : comment;
    renameIn(text, end, kGoto, 1, renamed);
    renameIn(text, end, kRepeat, 2, renamed);
    if (namesProfileHere(QStringView(text).left(end))) renameIn(text, end, kFirstLast, 1, renamed);
    return text;
}

std::optional<RenumberProblem> fagorRenumberProblem(const QTextDocument& document,
                                                    BlockNumbering numbering) {
    using Kind = RenumberProblem::Kind;
    BlockCounter counter(program::Dialect::Fagor, -1, numbering);
    RenamedLabels renamed;
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        const auto numbered = counter.next(block.text());
        if (!numbered) continue;
        if (numbered->wanted > kFagorMaxLabel)
            return RenumberProblem{Kind::LabelTooLong, block.blockNumber() + 1, numbered->wanted};
        renamed.emplace(numbered->current.number, numbered->wanted);  // the first one counts
    }
    return fagorReferenceProblem(document, renamed);
}

std::optional<RenumberProblem> fagorReferenceProblem(const QTextDocument& document,
                                                     const RenamedLabels& renamed) {
    using Kind = RenumberProblem::Kind;
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        const QStringView code = codeOf(block.text());
        const int line = block.blockNumber() + 1;
        if (hasComputedReference(code)) return RenumberProblem{Kind::ComputedReference, line, 0};
        for (const long long label : profileLabels(code)) {
            const auto found = renamed.find(label);
            const long long after = found == renamed.end() ? label : found->second;
            if (after > kFagorMaxProfileLabel)
                return RenumberProblem{Kind::ProfileLabelTooLong, line, after};
        }
    }
    return std::nullopt;
}

bool renameLabelReferences(QTextDocument& document, QTextCursor& edit,
                           const RenamedLabels& renamed) {
    if (renamed.empty()) return false;
    bool changed = false;
    for (QTextBlock block = document.begin(); block.isValid(); block = block.next()) {
        const QString text = block.text();
        const QString renamedText = withRenamedLabels(text, renamed);
        if (renamedText == text) continue;
        edit.setPosition(block.position());
        edit.setPosition(block.position() + block.length() - 1, QTextCursor::KeepAnchor);
        edit.insertText(renamedText);
        changed = true;
    }
    return changed;
}

}  // namespace kerf::ui
