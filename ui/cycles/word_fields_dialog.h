#pragma once

#include <QDialog>
#include <QStringList>
#include <optional>
#include <vector>

class QGridLayout;
class QLabel;
class QPushButton;
class QVBoxLayout;

namespace kerf::ui {

// One row of a block dialog: the word as the block writes it and, for a word with a fixed set of
// values, those values (a list to choose from instead of a text field).
struct WordRow {
    QString word;
    QStringList choices;
};

// A dialog that writes one block word by word (path functions, special functions): a title, one
// row per word with its description, the refusal line, OK and Cancel. Enter checks the row and
// moves to the next, on the last it finishes; Esc cancels; refused input keeps the dialog open
// with the reason.
class WordFieldsDialog : public QDialog {
    Q_OBJECT

public:
    void setValues(const QStringList& values);
    QStringList values() const;
    int fieldCount() const { return static_cast<int>(m_inputs.size()); }
    QWidget* input(int field) const { return m_inputs.at(static_cast<size_t>(field)); }
    QString message() const;

    void accept() override;

protected:
    WordFieldsDialog(QWidget* parent, const char* objectName);
    // Called by the derived constructor once its own members are set.
    void build(const QString& title, const std::vector<WordRow>& rows,
               const char* messageObjectName, int inputWidth);
    void retranslate();
    // Puts `widget` (a button that fills the row, such as "Select file") after the row's input.
    void addToRow(int field, QWidget* widget);
    // Shows `text` in the refusal line (empty: clears it).
    void setMessage(const QString& text);

    // Why one row's text or the whole block is refused, if it is.
    virtual std::optional<QString> checkRow(int field, const QString& text) const = 0;
    virtual std::optional<QString> checkBlock(const QStringList& values) const = 0;
    virtual QString rowDescription(int field) const = 0;
    virtual QString dialogTitle() const = 0;

    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QString text(int field) const;

    QGridLayout* m_grid = nullptr;
    std::vector<QWidget*> m_inputs;
    std::vector<QLabel*> m_descriptions;
    QLabel* m_message = nullptr;
    QPushButton* m_ok = nullptr;
    QPushButton* m_cancel = nullptr;
};

}  // namespace kerf::ui
