#include "ui/editor/visible_highlighter.h"

#include <QPlainTextEdit>
#include <QTextBlock>
#include <QTextDocument>
#include <QTextLayout>

namespace kerf::ui {

VisibleHighlighter::VisibleHighlighter(QPlainTextEdit* editor) : QObject(editor), m_editor(editor) {
    connect(editor, &QPlainTextEdit::updateRequest, this, [this] { highlightVisible(); });
    watch(editor->document());
}

void VisibleHighlighter::watch(QTextDocument* document) {
    disconnect(m_watch);
    m_watch = connect(document, &QTextDocument::contentsChange, this,
                      [this](int position, int, int added) { forget(position, added); });
    ++m_generation;  // a new document: nothing of it is coloured yet
}

void VisibleHighlighter::setDialect(program::Dialect dialect) {
    m_dialect = dialect;
    ++m_generation;
    highlightVisible();
}

QTextCharFormat VisibleHighlighter::formatOf(NcToken token) {
    QTextCharFormat format;
    switch (token) {
        case NcToken::BlockNumber:
            format.setForeground(QColor(0x80, 0x80, 0x80));
            break;
        case NcToken::Keyword:
            format.setForeground(QColor(0x00, 0x3c, 0x8c));
            format.setFontWeight(QFont::Bold);
            break;
        case NcToken::Address:
            format.setForeground(QColor(0x8a, 0x1c, 0x6c));
            break;
        case NcToken::Number:
            format.setForeground(QColor(0x10, 0x10, 0x10));
            break;
        case NcToken::Parameter:
            format.setForeground(QColor(0x00, 0x80, 0x80));
            break;
        case NcToken::Function:
            format.setForeground(QColor(0xa0, 0x50, 0x00));
            break;
        case NcToken::Comment:
            format.setForeground(QColor(0x2e, 0x7d, 0x32));
            format.setFontItalic(true);
            break;
    }
    return format;
}

int VisibleHighlighter::highlightVisible() {
    if (m_busy) return 0;  // marking a block dirty can ask for a repaint, which lands here
    m_busy = true;
    QTextDocument* document = m_editor->document();
    const int bottom = m_editor->viewport()->height();
    int coloured = 0;
    // cursorForPosition(0,0) finds the first visible block; QPlainTextEdit keeps it protected.
    QTextBlock block = m_editor->cursorForPosition(QPoint(0, 0)).block();
    for (int lines = 0; block.isValid() && lines < 500; block = block.next(), ++lines) {
        if (block.userState() != m_generation) {
            QVector<QTextLayout::FormatRange> ranges;
            for (const NcSpan& span : scanNcLine(block.text(), m_dialect)) {
                ranges.append({span.start, span.length, formatOf(span.token)});
            }
            block.layout()->setFormats(ranges);
            block.setUserState(m_generation);
            // Tells the layout the block looks different without emitting contentsChange.
            document->markContentsDirty(block.position(), block.length());
            ++coloured;
        }
        if (m_editor->cursorRect(QTextCursor(block)).top() > bottom) break;
    }
    m_busy = false;
    return coloured;
}

void VisibleHighlighter::forget(int position, int charsAdded) {
    QTextDocument* document = m_editor->document();
    QTextBlock block = document->findBlock(position);
    const QTextBlock last = document->findBlock(position + charsAdded);
    while (block.isValid()) {
        block.setUserState(-1);
        if (block == last) break;
        block = block.next();
    }
}

}  // namespace kerf::ui
