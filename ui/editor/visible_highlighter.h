#pragma once

#include <QObject>
#include <QTextCharFormat>
#include <array>

#include "core/program/dialect.h"
#include "ui/editor/nc_syntax.h"

class QPlainTextEdit;
class QTextDocument;

namespace kerf::ui {

// Colours the lines of a program editor as they come on screen. QSyntaxHighlighter colours the
// whole document whenever it is set, which takes seconds on a million-line program; NC syntax
// is line-local (see scanNcLine), so colouring only the visible lines is exact and costs the
// same for any program size.
class VisibleHighlighter : public QObject {
    Q_OBJECT

public:
    explicit VisibleHighlighter(QPlainTextEdit* editor);

    // Follows edits of this document (the editor's document when constructed).
    void watch(QTextDocument* document);
    void setDialect(program::Dialect dialect);
    program::Dialect dialect() const { return m_dialect; }
    // Colours the lines now on screen that are not coloured yet; returns how many it coloured.
    int highlightVisible();
    static QTextCharFormat formatOf(NcToken token);

private:
    void forget(int position, int charsAdded);

    QPlainTextEdit* m_editor;
    QMetaObject::Connection m_watch;
    program::Dialect m_dialect = program::Dialect::Klartext;
    bool m_busy = false;
    int m_generation = 1;  // block user state of coloured blocks; bumped to recolour all
};

}  // namespace kerf::ui
