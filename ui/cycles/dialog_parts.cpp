#include "ui/cycles/dialog_parts.h"

#include <QBoxLayout>
#include <QDialog>
#include <QLabel>
#include <QPushButton>

namespace kerf::ui {

QLabel* addRefusalLine(QDialog& dialog, QBoxLayout& layout, const char* objectName) {
    auto* label = new QLabel(&dialog);
    label->setObjectName(objectName);
    label->setWordWrap(true);
    label->setStyleSheet(QStringLiteral("color: #b00000; font-weight: bold;"));
    layout.addWidget(label);
    return label;
}

void addOkCancel(QDialog& dialog, QBoxLayout& layout, QPushButton*& ok, QPushButton*& cancel) {
    auto* buttons = new QHBoxLayout;
    ok = new QPushButton(&dialog);
    cancel = new QPushButton(&dialog);
    for (QPushButton* button : {ok, cancel}) {
        button->setAutoDefault(false);
        button->setDefault(false);
        button->setMinimumHeight(kTouchHeight);
        button->setMinimumWidth(120);
        buttons->addWidget(button);
    }
    buttons->addStretch(1);
    QObject::connect(ok, &QPushButton::clicked, &dialog, &QDialog::accept);
    QObject::connect(cancel, &QPushButton::clicked, &dialog, &QDialog::reject);
    layout.addLayout(buttons);
}

void sizeToWindow(QDialog& dialog) {
    const QWidget* parent = dialog.parentWidget();
    if (parent != nullptr) dialog.resize(parent->window()->size() * 0.9);
}

}  // namespace kerf::ui
