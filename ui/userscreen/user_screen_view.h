#pragma once

#include <QWidget>

class QLabel;
class QLineEdit;

namespace kerf::ui {

class UserScreenRun;

// Draws a FAGOR user screen (spec part 2 §6.8): the page, the data windows on the 21 x 80 text
// grid, the user symbols on the 640 x 336 pixel area, the data-input window with its prompt, and
// in edit mode the block being written. Keys typed here go to WKEY, the number typed in the input
// line to IB.
class UserScreenView : public QWidget {
    Q_OBJECT

public:
    explicit UserScreenView(UserScreenRun& run, QWidget* parent = nullptr);

    QLineEdit* inputLine() const { return m_input; }
    void refresh();
    void retranslate();

signals:
    void message(const QString& text);

protected:
    void keyPressEvent(QKeyEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void submitInput();

    UserScreenRun& m_run;
    QLabel* m_title = nullptr;
    QWidget* m_area = nullptr;
    QLabel* m_prompt = nullptr;
    QLineEdit* m_input = nullptr;
    QLabel* m_state = nullptr;
    QLabel* m_block = nullptr;
};

}  // namespace kerf::ui
