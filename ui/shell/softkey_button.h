#pragma once

#include <QPushButton>

namespace kerf::ui {

// A softkey: its label wraps onto as many lines as the key's height allows and shrinks its font
// if it still does not fit, so a long label (a cycle name, a translation) never makes the key,
// and with it the window, wider than the panel.
class SoftkeyButton : public QPushButton {
public:
    explicit SoftkeyButton(QWidget* parent = nullptr);

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
};

}  // namespace kerf::ui
