#pragma once

#include <QWidget>

class QLabel;
class QSlider;

namespace kerf::ui {

// Feed, rapid and spindle override for a finger: a slider and -/+ keys per override (each at
// least 48 px high), the value in percent. Changes go out at once; motion changes speed within
// its jerk limits, so a jump of the slider still moves the axes smoothly.
class OverrideControls : public QWidget {
    Q_OBJECT

public:
    static constexpr int kMinimumHeight = 48;
    static constexpr int kStepPercent = 5;  // per touch of - or +

    explicit OverrideControls(QWidget* parent = nullptr);

    QSlider* feedSlider() const { return m_feed.slider; }
    QSlider* rapidSlider() const { return m_rapid.slider; }
    QSlider* spindleSlider() const { return m_spindle.slider; }

signals:
    // Fractions: 1 = 100 %.
    void feedOverrideChanged(double fraction);
    void rapidOverrideChanged(double fraction);
    void spindleOverrideChanged(double fraction);

protected:
    void changeEvent(QEvent* event) override;

private:
    struct Row {
        QLabel* name = nullptr;
        QSlider* slider = nullptr;
        QLabel* value = nullptr;
    };
    Row addRow(int row, int minimum, int maximum, void (OverrideControls::*changed)(double));
    void retranslate();

    Row m_feed;
    Row m_rapid;
    Row m_spindle;
};

}  // namespace kerf::ui
