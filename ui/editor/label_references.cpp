#include "ui/editor/label_references.h"

#include <QRegularExpression>
#include <QTextBlock>
#include <QTextCursor>
#include <QTextDocument>

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

}  // namespace

QString withRenamedLabels(QStringView line, const RenamedLabels& renamed) {
    static const QRegularExpression kGoto(QStringLiteral("\\(\\s*GOTO\\s*N(\\d+)"),
                                          QRegularExpression::CaseInsensitiveOption);
    // RPT's third value is a count, not a label.
    static const QRegularExpression kRepeat(QStringLiteral("\\(\\s*RPT\\s*N(\\d+)\\s*,\\s*N(\\d+)"),
                                            QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression kProfileCycle(
        QStringLiteral("(?<![A-Za-z0-9.])G0*6[689](?![0-9.])"),
        QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression kOtherProgram(QStringLiteral("(?<![A-Za-z])Q\\s*\\d"),
                                                  QRegularExpression::CaseInsensitiveOption);
    static const QRegularExpression kFirstLast(QStringLiteral("(?<![A-Za-z])[SE]\\s*(\\d+)"),
                                               QRegularExpression::CaseInsensitiveOption);
    QString text = line.toString();
    const int comment = text.indexOf(QLatin1Char(';'));
    const int end = comment < 0 ? text.size() : comment;
    renameIn(text, end, kGoto, 1, renamed);
    renameIn(text, end, kRepeat, 2, renamed);
    const QString code = text.left(end);
    if (code.contains(kProfileCycle) && !code.contains(kOtherProgram)) {
        renameIn(text, end, kFirstLast, 1, renamed);
    }
    return text;
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
