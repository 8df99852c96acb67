#include "ui/status/override_controls.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>

namespace kerf::ui {

OverrideControls::OverrideControls(QWidget* parent) : QWidget(parent) {
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    m_feed = addRow(0, 0, 150, &OverrideControls::feedOverrideChanged);
    m_rapid = addRow(1, 0, 100, &OverrideControls::rapidOverrideChanged);
    m_spindle = addRow(2, 50, 150, &OverrideControls::spindleOverrideChanged);
    m_feed.slider->setObjectName("feedOverride");
    m_rapid.slider->setObjectName("rapidOverride");
    m_spindle.slider->setObjectName("spindleOverride");
    grid->setColumnStretch(2, 1);
    retranslate();
}

OverrideControls::Row OverrideControls::addRow(int row, int minimum, int maximum,
                                               void (OverrideControls::*changed)(double)) {
    auto* grid = static_cast<QGridLayout*>(layout());
    Row r;
    r.name = new QLabel(this);
    r.slider = new QSlider(Qt::Horizontal, this);
    r.slider->setRange(minimum, maximum);
    r.slider->setValue(100);
    r.slider->setPageStep(kStepPercent);
    r.slider->setMinimumHeight(kMinimumHeight);
    r.value = new QLabel(QStringLiteral("100 %"), this);
    r.value->setMinimumWidth(56);
    auto* less = new QPushButton(QStringLiteral("-"), this);
    auto* more = new QPushButton(QStringLiteral("+"), this);
    for (QPushButton* key : {less, more}) {
        key->setMinimumSize(kMinimumHeight, kMinimumHeight);
        key->setFocusPolicy(Qt::NoFocus);
    }
    QSlider* slider = r.slider;
    QLabel* value = r.value;
    connect(less, &QPushButton::clicked, slider,
            [slider] { slider->setValue(slider->value() - kStepPercent); });
    connect(more, &QPushButton::clicked, slider,
            [slider] { slider->setValue(slider->value() + kStepPercent); });
    connect(slider, &QSlider::valueChanged, this, [this, value, changed](int percent) {
        value->setText(QStringLiteral("%1 %").arg(percent));
        emit(this->*changed)(percent / 100.0);
    });
    grid->addWidget(r.name, row, 0);
    grid->addWidget(less, row, 1);
    grid->addWidget(r.slider, row, 2);
    grid->addWidget(more, row, 3);
    grid->addWidget(r.value, row, 4);
    return r;
}

void OverrideControls::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void OverrideControls::retranslate() {
    m_feed.name->setText(tr("Feed"));
    m_rapid.name->setText(tr("Rapid"));
    m_spindle.name->setText(tr("Spindle"));
}

}  // namespace kerf::ui
