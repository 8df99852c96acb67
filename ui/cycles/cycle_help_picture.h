#pragma once

#include <QRectF>
#include <QString>
#include <QWidget>

#include "ui/cycles/help_drawing.h"

namespace kerf::ui {

// The help graphic beside the cycle dialog: the group's schematic, drawn by our own code, with
// the dimension of the parameter being entered highlighted in orange.
class CycleHelpPicture : public QWidget {
    Q_OBJECT

public:
    explicit CycleHelpPicture(QWidget* parent = nullptr);

    void setCycle(const cycles::CycleDescriptor& cycle);
    // A drawing made for the caller's own fields (the FAGOR cycles), shown as it is.
    void setDrawing(HelpDrawing drawing);
    // The field being entered ("Q200", "ROT"...); the picture highlights its dimension if it has
    // one.
    void setField(const QString& label);

    // The highlighted dimension's bounds in widget coordinates; empty if none is highlighted.
    QRectF highlightRect() const;

    QSize sizeHint() const override { return {380, 380}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QTransform toWidget() const;

    HelpDrawing m_drawing;
    QString m_field;
};

}  // namespace kerf::ui
