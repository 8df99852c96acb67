#include "ui/touch/touch_size.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QDialog>
#include <QEvent>
#include <QHeaderView>
#include <QInputDialog>
#include <QLineEdit>
#include <QSize>
#include <QStyledItemDelegate>
#include <QTableView>
#include <algorithm>

namespace kerf::ui {

void makeTouchSizedRows(QComboBox& combo) {
    for (int i = 0; i < combo.count(); ++i)
        combo.setItemData(i, QSize(0, kTouchHeight), Qt::SizeHintRole);
}

namespace {

// A row at least kTouchHeight high, whatever its model says.
class TouchRowDelegate : public QStyledItemDelegate {
public:
    using QStyledItemDelegate::QStyledItemDelegate;
    QSize sizeHint(const QStyleOptionViewItem& option, const QModelIndex& index) const override {
        QSize size = QStyledItemDelegate::sizeHint(option, index);
        size.setHeight(std::max(size.height(), kTouchHeight));
        return size;
    }
};

void sizeChildren(QDialog& dialog) {
    for (QWidget* child : dialog.findChildren<QWidget*>()) {
        if (qobject_cast<QAbstractButton*>(child) || qobject_cast<QAbstractSpinBox*>(child) ||
            qobject_cast<QComboBox*>(child) || qobject_cast<QLineEdit*>(child))
            child->setMinimumHeight(kTouchHeight);
        if (auto* combo = qobject_cast<QComboBox*>(child)) makeTouchSizedRows(*combo);
    }
}

// QInputDialog and QMessageBox build or lay out their buttons only when shown: the sizes are
// applied then too.
class SizeWhenShown : public QObject {
public:
    using QObject::QObject;
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Show) sizeChildren(*static_cast<QDialog*>(watched));
        return false;
    }
};

}  // namespace

void makeTouchSizedRows(QAbstractItemView& view) {
    // A table's rows are its vertical header's sections; lists and trees ask the delegate.
    if (auto* table = qobject_cast<QTableView*>(&view)) {
        table->verticalHeader()->setMinimumSectionSize(kTouchHeight);
        table->verticalHeader()->setDefaultSectionSize(kTouchHeight);
    }
    view.setItemDelegate(new TouchRowDelegate(&view));
}

void makeTouchSized(QDialog& dialog) {
    sizeChildren(dialog);
    dialog.installEventFilter(new SizeWhenShown(&dialog));
}

QMessageBox::StandardButton askTouch(QWidget* parent, const QString& title, const QString& text,
                                     QMessageBox::StandardButtons buttons,
                                     QMessageBox::StandardButton defaultButton) {
    QMessageBox box(QMessageBox::Question, title, text, buttons, parent);
    box.setDefaultButton(defaultButton);
    makeTouchSized(box);
    return static_cast<QMessageBox::StandardButton>(box.exec());
}

bool confirmTouch(QWidget* parent, const QString& title, const QString& question) {
    return askTouch(parent, title, question, QMessageBox::Yes | QMessageBox::No, QMessageBox::No) ==
           QMessageBox::Yes;
}

void informTouch(QWidget* parent, const QString& title, const QString& text) {
    QMessageBox box(QMessageBox::Information, title, text, QMessageBox::Ok, parent);
    makeTouchSized(box);
    box.exec();
}

std::optional<QString> askTextTouch(QWidget* parent, const QString& title, const QString& label,
                                    const QString& initial) {
    QInputDialog dialog(parent);
    dialog.setWindowTitle(title);
    dialog.setLabelText(label);
    dialog.setTextValue(initial);
    makeTouchSized(dialog);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    return dialog.textValue();
}

}  // namespace kerf::ui
