#include "ui/shell/touch_dialog.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QDialog>
#include <QEvent>
#include <QLineEdit>
#include <QSize>

#include "ui/shell/softkey_bar.h"

namespace kerf::ui {

void makeTouchSizedRows(QComboBox& combo) {
    for (int i = 0; i < combo.count(); ++i)
        combo.setItemData(i, QSize(0, SoftkeyBar::kMinimumKeyHeight), Qt::SizeHintRole);
}

namespace {

void sizeChildren(QDialog& dialog) {
    for (QWidget* child : dialog.findChildren<QWidget*>()) {
        if (qobject_cast<QAbstractButton*>(child) || qobject_cast<QAbstractSpinBox*>(child) ||
            qobject_cast<QComboBox*>(child) || qobject_cast<QLineEdit*>(child))
            child->setMinimumHeight(SoftkeyBar::kMinimumKeyHeight);
        if (auto* combo = qobject_cast<QComboBox*>(child)) makeTouchSizedRows(*combo);
    }
}

// QInputDialog builds its buttons only when it is shown: the sizes are applied then too.
class SizeWhenShown : public QObject {
public:
    using QObject::QObject;
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Show) sizeChildren(*static_cast<QDialog*>(watched));
        return false;
    }
};

}  // namespace

void makeTouchSized(QDialog& dialog) {
    sizeChildren(dialog);
    dialog.installEventFilter(new SizeWhenShown(&dialog));
}

}  // namespace kerf::ui
