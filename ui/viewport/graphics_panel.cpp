#include "ui/viewport/graphics_panel.h"

#include <QEvent>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

#include "graphics/scene/machine_scene.h"
#include "graphics/stock/progressive_stock.h"
#include "ui/common/block_name.h"
#include "ui/viewport/viewport_widget.h"

namespace kerf::ui {

namespace {

constexpr std::array<TestRunSpeed, 4> kSpeeds{TestRunSpeed::Real, TestRunSpeed::Times10,
                                              TestRunSpeed::Times100, TestRunSpeed::Max};

// VTK's widget needs OpenGL on a real (or virtual) X display.
bool canRender3d() {
    const QString platform = QGuiApplication::platformName();
    return platform != QLatin1String("offscreen") && platform != QLatin1String("minimal");
}

}  // namespace

GraphicsPanel::GraphicsPanel(TestRunController& testRun, const machine::MachineConfig& machine,
                             QWidget* parent)
    : QWidget(parent),
      m_playback(&testRun),
      m_lathe(machine.kind == machine::MachineKind::Lathe),
      m_scene(std::make_unique<graphics::Scene>(graphics::sceneOptionsFor(machine))) {
    setObjectName(QStringLiteral("graphicsPanel"));
    setMinimumWidth(200);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    if (canRender3d()) {
        m_viewport = new ViewportWidget(this);
        layout->addWidget(m_viewport, 1);
        m_viewport->setScene(m_scene.get());
        if (m_lathe) m_viewport->setView(graphics::View::LatheSection);
        // A mill has no half section; a lathe is seen in 3D or in its XZ section.
        for (graphics::View view : {graphics::View::Top, graphics::View::Front,
                                    graphics::View::Side, graphics::View::LatheSection}) {
            const bool shown = m_lathe == (view == graphics::View::LatheSection);
            m_viewport->viewButton(view)->setVisible(shown);
        }
        m_fitTimer = new QTimer(this);
        m_fitTimer->setInterval(100);
        connect(m_fitTimer, &QTimer::timeout, this, &GraphicsPanel::fitWhenStockShown);
        connect(m_viewport, &ViewportWidget::segmentPicked, this,
                [this](quint32 fileId, quint32 line, quint32, qint64) {
                    if (fileId == 0) emit blockPicked(static_cast<int>(line));
                });
    } else {
        m_noDisplay = new QLabel(this);
        m_noDisplay->setAlignment(Qt::AlignCenter);
        m_noDisplay->setWordWrap(true);
        m_noDisplay->setFrameShape(QFrame::StyledPanel);
        layout->addWidget(m_noDisplay, 1);
    }

    auto* strip = new QHBoxLayout();
    strip->setContentsMargins(4, 0, 4, 4);
    m_time = new QLabel(this);
    m_time->setObjectName(QStringLiteral("machiningTime"));
    m_time->setMinimumHeight(48);
    // Two lines rather than clipped (or a panel pushed wider) where the language is long.
    m_time->setWordWrap(true);
    strip->addWidget(m_time, 1);
    m_speedTitle = new QLabel(this);
    strip->addWidget(m_speedTitle);
    for (size_t i = 0; i < kSpeeds.size(); ++i) {
        auto* button = new QToolButton(this);
        button->setCheckable(true);
        button->setAutoExclusive(true);
        button->setMinimumSize(56, 48);  // finger-sized
        button->setText(speedText(kSpeeds[i]));
        const TestRunSpeed speed = kSpeeds[i];
        connect(button, &QToolButton::clicked, this,
                [this, speed] { m_playback->setSpeed(speed); });
        strip->addWidget(button);
        m_speedButtons[i] = button;
    }
    layout->addLayout(strip);

    connectPlayback();
    retranslate();
}

GraphicsPanel::~GraphicsPanel() {
    // The viewport refers to the scene: detach it before the scene goes.
    if (m_viewport != nullptr) {
        m_viewport->followStock(nullptr);
        m_viewport->setScene(nullptr);
    }
}

void GraphicsPanel::connectPlayback() {
    for (const QMetaObject::Connection& c : m_playbackConnections)
        disconnect(c);
    m_playbackConnections = {
        connect(m_playback, &TestRunController::programReady, this, &GraphicsPanel::onProgramReady),
        connect(m_playback, &TestRunController::progressChanged, this, &GraphicsPanel::onProgress),
        connect(m_playback, &TestRunController::stateChanged, this, &GraphicsPanel::onProgress),
        connect(m_playback, &TestRunController::stockReplaced, this,
                &GraphicsPanel::onStockReplaced),
        connect(m_playback, &TestRunController::speedChanged, this,
                [this] {
                    for (size_t i = 0; i < kSpeeds.size(); ++i)
                        m_speedButtons[i]->setChecked(kSpeeds[i] == m_playback->speed());
                }),
    };
    for (size_t i = 0; i < kSpeeds.size(); ++i)
        m_speedButtons[i]->setChecked(kSpeeds[i] == m_playback->speed());
}

void GraphicsPanel::showPlayback(TestRunController& playback) {
    if (&playback == m_playback) return;
    m_playback = &playback;
    connectPlayback();
    onStockReplaced(m_playback->stock());
    onProgramReady();
}

void GraphicsPanel::onStockReplaced(const graphics::ProgressiveStock* stock) {
    m_scene->setStockMesh(nullptr);
    if (m_viewport != nullptr) m_viewport->followStock(stock);
}

QToolButton* GraphicsPanel::speedButton(TestRunSpeed speed) const {
    for (size_t i = 0; i < kSpeeds.size(); ++i) {
        if (kSpeeds[i] == speed) return m_speedButtons[i];
    }
    return nullptr;
}

QString GraphicsPanel::formatDuration(double seconds) {
    if (!std::isfinite(seconds)) return QStringLiteral("-:--:--");  // an override at 0 %
    const auto total = static_cast<long long>(std::ceil(std::max(0.0, seconds) - 1e-9));
    return QStringLiteral("%1:%2:%3")
        .arg(total / 3600)
        .arg((total / 60) % 60, 2, 10, QLatin1Char('0'))
        .arg(total % 60, 2, 10, QLatin1Char('0'));
}

void GraphicsPanel::highlightLine(int line) {
    m_highlightedLine = line;
    if (line <= 0) {
        m_scene->clearHighlight();
    } else {
        m_scene->highlightBlock(0, static_cast<uint32_t>(line));
    }
    if (m_viewport != nullptr) m_viewport->render();
}

void GraphicsPanel::onProgramReady() {
    auto program = m_playback->program();
    m_scene->setStockMesh(nullptr);
    if (!program) {
        // The test run forgot its program: nothing of it stays on screen.
        m_scene->setToolpath(nullptr, nullptr);
        retranslate();
        if (m_viewport != nullptr) m_viewport->render();
        return;
    }
    m_scene->setToolpath(program->toolpath, program->geometry);
    m_shownTool = nullptr;
    if (m_highlightedLine > 0) m_scene->highlightBlock(0, static_cast<uint32_t>(m_highlightedLine));
    scheduleFit();
    onProgress();
}

void GraphicsPanel::scheduleFit() {
    if (m_viewport == nullptr) return;
    m_fitTimer->start();
}

bool GraphicsPanel::fitPending() const {
    return m_fitTimer != nullptr && m_fitTimer->isActive();
}

void GraphicsPanel::fitWhenStockShown() {
    // The blank comes from the stock worker a moment after the program: fit once it is drawn,
    // or when there is none to draw (no blank, or one derived only at the end), or after 2 s.
    const auto* stock = m_playback->stock();
    const auto latest = stock != nullptr ? stock->latest() : nullptr;
    const bool noBlank =
        latest == nullptr ||
        (latest->sequence > 0 && (!latest->mesh || latest->mesh->triangleCount() == 0));
    if (m_scene->stats().stockTriangles == 0 && !noBlank && ++m_fitWaits < 20) return;
    m_fitTimer->stop();
    m_fitWaits = 0;
    m_viewport->setView(m_scene->view());  // fits with the viewport's current size
    emit viewFitted();
}

void GraphicsPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    scheduleFit();
}

void GraphicsPanel::onProgress() {
    retranslate();
    auto program = m_playback->program();
    if (!program) return;
    const canon::ToolChange* tool = program->toolAt(m_playback->playbackTimeS());
    if (tool != m_shownTool && tool != nullptr) {
        graphics::ToolGlyph glyph;
        glyph.axis = tool->toolAxis;
        if (m_lathe) {
            glyph.shape = graphics::LatheInsert::fromGeometry(tool->geometry);
        } else if (program->stockOptions.millCutter) {
            glyph.shape = program->stockOptions.millCutter(*tool);
        }
        m_scene->setTool(glyph);
    }
    m_shownTool = tool;
    m_scene->setToolPosition(m_playback->toolPosition(), m_playback->toolAxis());
    const TestRunController::ExecutedPart executed = m_playback->executedPart();
    m_scene->setExecutedPath(executed.fromPoint, executed.reached.pointsDone, executed.reached.tip);
    if (m_viewport != nullptr) m_viewport->render();
}

void GraphicsPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void GraphicsPanel::retranslate() {
    if (m_noDisplay != nullptr) m_noDisplay->setText(tr("The 3D graphics need a display"));
    m_speedTitle->setText(tr("Speed"));
    m_speedButtons.back()->setText(speedText(TestRunSpeed::Max));
    // Following the machine: where it is and what is left, not the playback's speed.
    const bool machine = m_playback->followsMachine();
    m_speedTitle->setVisible(!machine);
    for (QToolButton* button : m_speedButtons)
        button->setVisible(!machine);
    if (!machine) {
        // The two times stay together on one line when the text wraps.
        m_time->setText(tr("Machining time %1")
                            .arg(QStringLiteral("%1\u00a0/\u00a0%2")
                                     .arg(formatDuration(m_playback->playbackTimeS()),
                                          formatDuration(m_playback->machiningTimeS()))));
        return;
    }
    if (!m_playback->program()) return m_time->clear();
    const std::optional<SourceLocation> block = m_playback->currentBlock();
    const QString name =
        block ? blockName(block->blockNumber, static_cast<int>(block->line), m_playback->dialect())
              : QStringLiteral("-");
    m_time->setText(tr("%1   %2 % done   %3 remaining")
                        .arg(name, QString::number(m_playback->progressPercent(), 'f', 0),
                             formatDuration(m_playback->remainingTimeS())));
}

}  // namespace kerf::ui
