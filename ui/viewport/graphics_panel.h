#pragma once

#include <QWidget>
#include <array>
#include <memory>
#include <vector>

#include "core/machine/machine_config.h"
#include "graphics/scene/scene.h"
#include "ui/testrun/test_run_controller.h"

class QLabel;
class QTimer;
class QToolButton;

namespace kerf::ui {

class ViewportWidget;

// The graphics panel of the workspace: the toolpath and stock of the test run in a 3D viewport
// (views, zoom, rotate, pan by mouse and touch), the tool at the playback position, the machining
// time and the playback speed. Shown a playback that follows the machine (Program run), it shows
// the tool where the machine is, the part of the path executed in its own colour, and instead
// of the time and the speed the block, the part done and the time remaining. A click
// on the path names its block; the block at the editor's cursor lights up. Without an X display
// (the offscreen platform) the 3D view is replaced by a note and everything else keeps working.
// UI thread only.
class GraphicsPanel : public QWidget {
    Q_OBJECT

public:
    GraphicsPanel(TestRunController& testRun, const machine::MachineConfig& machine,
                  QWidget* parent = nullptr);
    ~GraphicsPanel() override;

    // Null when there is no display to render on.
    ViewportWidget* viewport() const { return m_viewport; }
    graphics::Scene& scene() { return *m_scene; }
    QLabel* timeLabel() const { return m_time; }
    QToolButton* speedButton(TestRunSpeed speed) const;
    // Shows another playback (the test run, or Program run following the machine); the panel's
    // first one is the constructor's.
    void showPlayback(TestRunController& playback);
    TestRunController& playback() const { return *m_playback; }

    // A fit of the view is waiting for the blank or for the viewport's size (see scheduleFit).
    bool fitPending() const;

    // "0:01:05": hours, minutes, seconds (rounded up, so a started second counts).
    static QString formatDuration(double seconds);

public slots:
    // The block at the editor's cursor (a line of the main program; 0 clears).
    void highlightLine(int line);

signals:
    // A click on the toolpath picked a segment of this line of the main program.
    void blockPicked(int line);
    // The view was fitted to the content; fitPending() is false now.
    void viewFitted();

protected:
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void onProgramReady();
    void onProgress();
    void onStockReplaced(const graphics::ProgressiveStock* stock);
    void connectPlayback();
    void retranslate();
    // Fits the view to the content once the viewport has its size and the blank is in.
    void scheduleFit();
    void fitWhenStockShown();

    TestRunController* m_playback;
    std::vector<QMetaObject::Connection> m_playbackConnections;
    bool m_lathe = false;
    std::unique_ptr<graphics::Scene> m_scene;
    ViewportWidget* m_viewport = nullptr;
    QLabel* m_noDisplay = nullptr;
    QLabel* m_time = nullptr;
    QLabel* m_speedTitle = nullptr;
    std::array<QToolButton*, 4> m_speedButtons{};
    const canon::ToolChange* m_shownTool = nullptr;
    int m_highlightedLine = 0;
    QTimer* m_fitTimer = nullptr;
    int m_fitWaits = 0;
};

}  // namespace kerf::ui
