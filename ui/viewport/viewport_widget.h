#pragma once

#include <QWidget>
#include <cstdint>
#include <memory>

#include "core/base/source_location.h"
#include "graphics/scene/scene.h"

class QVTKOpenGLNativeWidget;
class QTimer;
class QToolButton;

namespace kerf::graphics {
class ProgressiveStock;
}

namespace kerf::ui {

// The toolpath and stock viewport for the HMI: a VTK render widget showing a graphics::Scene,
// mouse and touch navigation (left drag or one finger: rotate; middle or shift drag, two
// fingers: pan; wheel or pinch: zoom), view buttons (3D, top, front, side, lathe section, fit),
// picking (a click emits the source location of the nearest segment) and highlighting of the
// block selected in the editor. Material removal shown progressively from a ProgressiveStock
// polled on a timer: the UI thread only swaps finished meshes in. UI thread only.
class ViewportWidget : public QWidget {
    Q_OBJECT
public:
    explicit ViewportWidget(QWidget* parent = nullptr);
    ~ViewportWidget() override;

    // The scene shown (not owned; must outlive the widget or be replaced first). Null clears.
    void setScene(graphics::Scene* scene);
    graphics::Scene* scene() const { return m_scene; }
    // Follows a running simulation's stock (not owned); null stops following.
    void followStock(const graphics::ProgressiveStock* stock);
    // The sequence number of the followed stock's mesh in the scene (0: none of it yet).
    uint64_t shownStockSequence() const { return m_stockSequence; }

    void setView(graphics::View view);
    void zoomBy(double factor);
    void render();
    // The view buttons, for tests and for the HMI's soft keys.
    QToolButton* viewButton(graphics::View view) const;
    QWidget* renderArea() const;

public slots:
    // The block selected in the editor; returns nothing, the count is in scene()->stats().
    void highlightBlock(quint32 fileId, quint32 line);
    void clearHighlight();

signals:
    // A click picked a segment of the toolpath.
    void segmentPicked(quint32 fileId, quint32 line, quint32 column, qint64 blockNumber);
    // A newer mesh of the followed stock is in the scene.
    void stockShown();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void pollStock();
    void updateViewportSize();

    struct Vtk;
    std::unique_ptr<Vtk> m_vtk;
    QVTKOpenGLNativeWidget* m_renderWidget = nullptr;
    graphics::Scene* m_scene = nullptr;
    const graphics::ProgressiveStock* m_stock = nullptr;
    uint64_t m_stockSequence = 0;
    QTimer* m_stockTimer = nullptr;
    QToolButton* m_fitButton = nullptr;
    QPoint m_pressPosition;
    bool m_pressed = false;
};

}  // namespace kerf::ui
