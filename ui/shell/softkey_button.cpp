#include "ui/shell/softkey_button.h"

#include <QStyleOptionButton>
#include <QStylePainter>

namespace kerf::ui {

namespace {

constexpr int kMinimumWidth = 40;
constexpr int kPreferredWidth = 96;
constexpr qreal kSmallestPointSize = 6.0;
constexpr int kFlags = Qt::AlignCenter | Qt::TextWordWrap;

}  // namespace

SoftkeyButton::SoftkeyButton(QWidget* parent) : QPushButton(parent) {}

QSize SoftkeyButton::minimumSizeHint() const {
    return {kMinimumWidth, QPushButton::minimumSizeHint().height()};
}

QSize SoftkeyButton::sizeHint() const {
    return {kPreferredWidth, QPushButton::sizeHint().height()};
}

void SoftkeyButton::paintEvent(QPaintEvent*) {
    QStylePainter painter(this);
    QStyleOptionButton option;
    initStyleOption(&option);
    const QString label = option.text;
    option.text.clear();
    painter.drawControl(QStyle::CE_PushButton, option);
    const QRect area = rect().adjusted(4, 2, -4, -2);
    QFont font = this->font();
    // The largest font, down to a floor, at which the wrapped label fits the key.
    while (font.pointSizeF() > kSmallestPointSize) {
        const QRect needed = QFontMetrics(font).boundingRect(area, kFlags, label);
        if (needed.width() <= area.width() && needed.height() <= area.height()) break;
        font.setPointSizeF(font.pointSizeF() - 0.5);
    }
    painter.setFont(font);
    painter.setPen(
        palette().color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::ButtonText));
    painter.setClipRect(area);
    painter.drawText(area, kFlags, label);
}

}  // namespace kerf::ui
