#include "ui/editor/find_bar.h"

#include <QCheckBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextDocument>

namespace kerf::ui {

namespace {

QPushButton* makeButton(QWidget* parent) {
    auto* button = new QPushButton(parent);
    button->setMinimumHeight(40);
    return button;
}

}  // namespace

FindBar::FindBar(QPlainTextEdit* editor, QWidget* parent) : QWidget(parent), m_editor(editor) {
    setObjectName("findBar");
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 2, 0, 2);
    m_find = new QLineEdit(this);
    m_replace = new QLineEdit(this);
    m_caseSensitive = new QCheckBox(this);
    m_status = new QLabel(this);
    m_previous = makeButton(this);
    m_next = makeButton(this);
    m_replaceOne = makeButton(this);
    m_replaceAll = makeButton(this);
    m_close = makeButton(this);
    connect(m_find, &QLineEdit::returnPressed, this, [this] { findNext(); });
    connect(m_next, &QPushButton::clicked, this, [this] { findNext(); });
    connect(m_previous, &QPushButton::clicked, this, [this] { findNext(true); });
    connect(m_replaceOne, &QPushButton::clicked, this, &FindBar::replaceCurrent);
    connect(m_replaceAll, &QPushButton::clicked, this, &FindBar::replaceAll);
    connect(m_close, &QPushButton::clicked, this, [this] {
        hide();
        m_editor->setFocus();
    });
    for (QWidget* widget :
         std::initializer_list<QWidget*>{m_find, m_previous, m_next, m_replace, m_replaceOne,
                                         m_replaceAll, m_caseSensitive, m_status, m_close}) {
        layout->addWidget(widget);
    }
    retranslate();
    hide();
}

void FindBar::retranslate() {
    m_find->setPlaceholderText(tr("Find"));
    m_replace->setPlaceholderText(tr("Replace with"));
    m_caseSensitive->setText(tr("Match case"));
    m_previous->setText(tr("Previous"));
    m_next->setText(tr("Next"));
    m_replaceOne->setText(tr("Replace"));
    m_replaceAll->setText(tr("Replace all"));
    m_close->setText(tr("Close"));
}

void FindBar::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void FindBar::setCaseSensitive(bool on) {
    m_caseSensitive->setChecked(on);
}

void FindBar::open() {
    show();
    const QString selected = m_editor->textCursor().selectedText();
    if (!selected.isEmpty() && !selected.contains(QChar::ParagraphSeparator))
        m_find->setText(selected);
    m_find->setFocus();
    m_find->selectAll();
}

bool FindBar::findNext(bool backward) {
    const QString needle = m_find->text();
    if (needle.isEmpty()) return false;
    QTextDocument::FindFlags flags;
    if (backward) flags |= QTextDocument::FindBackward;
    if (m_caseSensitive->isChecked()) flags |= QTextDocument::FindCaseSensitively;
    QTextCursor found = m_editor->document()->find(needle, m_editor->textCursor(), flags);
    if (found.isNull()) {
        // Wrap around once, as editors do.
        QTextCursor start(m_editor->document());
        if (backward) start.movePosition(QTextCursor::End);
        found = m_editor->document()->find(needle, start, flags);
    }
    if (found.isNull()) {
        m_status->setText(tr("Not found"));
        return false;
    }
    m_status->clear();
    m_editor->setTextCursor(found);
    m_editor->centerCursor();
    return true;
}

bool FindBar::replaceCurrent() {
    // Read-only while a program loads, is renumbered or written: finding is fine, replacing not.
    if (m_editor->isReadOnly()) return findNext();
    QTextCursor cursor = m_editor->textCursor();
    const Qt::CaseSensitivity sensitivity =
        m_caseSensitive->isChecked() ? Qt::CaseSensitive : Qt::CaseInsensitive;
    if (cursor.hasSelection() && cursor.selectedText().compare(m_find->text(), sensitivity) == 0) {
        cursor.insertText(m_replace->text());
    }
    return findNext();
}

int FindBar::replaceAll() {
    const QString needle = m_find->text();
    if (needle.isEmpty() || m_editor->isReadOnly()) return 0;
    QTextDocument::FindFlags flags;
    if (m_caseSensitive->isChecked()) flags |= QTextDocument::FindCaseSensitively;
    QTextCursor edit(m_editor->document());
    edit.beginEditBlock();
    int count = 0;
    QTextCursor found = m_editor->document()->find(needle, 0, flags);
    while (!found.isNull()) {
        found.insertText(m_replace->text());
        ++count;
        found = m_editor->document()->find(needle, found, flags);
    }
    edit.endEditBlock();
    m_status->setText(tr("%n replaced", nullptr, count));
    return count;
}

}  // namespace kerf::ui
