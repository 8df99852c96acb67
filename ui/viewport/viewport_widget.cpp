#include "ui/viewport/viewport_widget.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QMouseEvent>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <array>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkCallbackCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleMultiTouchCamera.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include "graphics/scene/scene_vtk.h"
#include "graphics/stock/progressive_stock.h"

namespace kerf::ui {

namespace {

constexpr std::array<graphics::View, 5> kViews{graphics::View::Iso, graphics::View::Top,
                                               graphics::View::Front, graphics::View::Side,
                                               graphics::View::LatheSection};

QString viewLabel(graphics::View view) {
    switch (view) {
        case graphics::View::Iso:
            return ViewportWidget::tr("3D");
        case graphics::View::Top:
            return ViewportWidget::tr("Top");
        case graphics::View::Front:
            return ViewportWidget::tr("Front");
        case graphics::View::Side:
            return ViewportWidget::tr("Side");
        case graphics::View::LatheSection:
            return ViewportWidget::tr("Section");
    }
    return {};
}

}  // namespace

struct ViewportWidget::Vtk {
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    vtkNew<vtkInteractorStyleMultiTouchCamera> style;
    vtkNew<vtkCallbackCommand> interaction;
    vtkRenderer* attached = nullptr;
    std::array<QToolButton*, kViews.size()> buttons{};
};

ViewportWidget::ViewportWidget(QWidget* parent) : QWidget(parent), m_vtk(std::make_unique<Vtk>()) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    auto* buttons = new QHBoxLayout();
    buttons->setContentsMargins(4, 4, 4, 0);
    for (size_t i = 0; i < kViews.size(); ++i) {
        auto* button = new QToolButton(this);
        button->setMinimumSize(56, 40);  // finger-sized
        const graphics::View view = kViews[i];
        connect(button, &QToolButton::clicked, this, [this, view] { setView(view); });
        buttons->addWidget(button);
        m_vtk->buttons[i] = button;
    }
    auto* fit = new QToolButton(this);
    fit->setMinimumSize(56, 40);
    fit->setObjectName(QStringLiteral("fitView"));
    m_fitButton = fit;
    connect(fit, &QToolButton::clicked, this, [this] {
        if (m_scene != nullptr) m_scene->fit();
        render();
    });
    buttons->addWidget(fit);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    retranslate();

    m_renderWidget = new QVTKOpenGLNativeWidget(this);
    m_renderWidget->setRenderWindow(m_vtk->window);
    m_renderWidget->setAttribute(Qt::WA_AcceptTouchEvents);
    m_renderWidget->grabGesture(Qt::PinchGesture);
    m_renderWidget->grabGesture(Qt::PanGesture);
    m_renderWidget->installEventFilter(this);
    layout->addWidget(m_renderWidget, 1);
    m_vtk->window->SetMultiSamples(0);  // software OpenGL: multisampling halves the frame rate

    vtkRenderWindowInteractor* interactor = m_vtk->window->GetInteractor();
    if (interactor != nullptr) interactor->SetInteractorStyle(m_vtk->style);
    // Coarser level of detail while the camera moves.
    m_vtk->interaction->SetClientData(this);
    m_vtk->interaction->SetCallback([](vtkObject*, unsigned long event, void* client, void*) {
        auto* self = static_cast<ViewportWidget*>(client);
        if (self->m_scene != nullptr) {
            self->m_scene->setInteractive(event == vtkCommand::StartInteractionEvent);
        }
    });
    m_vtk->style->AddObserver(vtkCommand::StartInteractionEvent, m_vtk->interaction);
    m_vtk->style->AddObserver(vtkCommand::EndInteractionEvent, m_vtk->interaction);

    m_stockTimer = new QTimer(this);
    m_stockTimer->setInterval(100);
    connect(m_stockTimer, &QTimer::timeout, this, &ViewportWidget::pollStock);
}

ViewportWidget::~ViewportWidget() {
    m_vtk->style->RemoveObserver(m_vtk->interaction);
    if (m_vtk->attached != nullptr) m_vtk->window->RemoveRenderer(m_vtk->attached);
}

void ViewportWidget::setScene(graphics::Scene* scene) {
    if (m_vtk->attached != nullptr) m_vtk->window->RemoveRenderer(m_vtk->attached);
    m_vtk->attached = nullptr;
    m_scene = scene;
    if (m_scene != nullptr) {
        m_vtk->attached = graphics::vtkRendererOf(*m_scene);
        m_vtk->window->AddRenderer(m_vtk->attached);
        updateViewportSize();
        m_scene->fit();
    }
    render();
}

void ViewportWidget::followStock(const graphics::ProgressiveStock* stock) {
    m_stock = stock;
    m_stockSequence = 0;
    if (m_stock != nullptr) {
        m_stockTimer->start();
    } else {
        m_stockTimer->stop();
    }
}

void ViewportWidget::pollStock() {
    if (m_stock == nullptr || m_scene == nullptr) return;
    // latest() takes a lock only for a pointer copy; the mesh was built on the worker.
    auto snapshot = m_stock->latest();
    if (snapshot->sequence == m_stockSequence) return;
    m_stockSequence = snapshot->sequence;
    m_scene->setStockMesh(snapshot->mesh);
    render();
    if (snapshot->finished) m_stockTimer->stop();
    emit stockShown();
}

void ViewportWidget::setView(graphics::View view) {
    if (m_scene == nullptr) return;
    updateViewportSize();
    m_scene->setView(view);
    render();
}

void ViewportWidget::zoomBy(double factor) {
    if (m_scene == nullptr) return;
    m_scene->zoom(factor);
    render();
}

void ViewportWidget::render() {
    if (m_renderWidget->isVisible()) m_vtk->window->Render();
    m_renderWidget->update();
}

QToolButton* ViewportWidget::viewButton(graphics::View view) const {
    for (size_t i = 0; i < kViews.size(); ++i) {
        if (kViews[i] == view) return m_vtk->buttons[i];
    }
    return nullptr;
}

QWidget* ViewportWidget::renderArea() const {
    return m_renderWidget;
}

void ViewportWidget::highlightBlock(quint32 fileId, quint32 line) {
    if (m_scene == nullptr) return;
    m_scene->highlightBlock(fileId, line);
    render();
}

void ViewportWidget::clearHighlight() {
    if (m_scene == nullptr) return;
    m_scene->clearHighlight();
    render();
}

void ViewportWidget::updateViewportSize() {
    if (m_scene == nullptr) return;
    const qreal ratio = m_renderWidget->devicePixelRatioF();
    m_scene->setViewportSize(static_cast<int>(m_renderWidget->width() * ratio),
                             static_cast<int>(m_renderWidget->height() * ratio));
}

void ViewportWidget::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    updateViewportSize();
}

void ViewportWidget::changeEvent(QEvent* event) {
    // The language chosen at start or in the settings comes after the buttons were made.
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void ViewportWidget::retranslate() {
    for (size_t i = 0; i < kViews.size(); ++i)
        m_vtk->buttons[i]->setText(viewLabel(kViews[i]));
    m_fitButton->setText(tr("Fit"));
}

bool ViewportWidget::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_renderWidget && m_scene != nullptr) {
        if (event->type() == QEvent::Resize) updateViewportSize();
        if (event->type() == QEvent::MouseButtonPress) {
            auto* mouse = static_cast<QMouseEvent*>(event);
            m_pressed = mouse->button() == Qt::LeftButton;
            m_pressPosition = mouse->pos();
        } else if (event->type() == QEvent::MouseButtonRelease && m_pressed) {
            auto* mouse = static_cast<QMouseEvent*>(event);
            m_pressed = false;
            // A click, not a drag: pick the segment under the pointer.
            if ((mouse->pos() - m_pressPosition).manhattanLength() <= 3) {
                const qreal ratio = m_renderWidget->devicePixelRatioF();
                updateViewportSize();
                if (auto hit = m_scene->pick(mouse->pos().x() * ratio, mouse->pos().y() * ratio,
                                             6.0 * ratio)) {
                    emit segmentPicked(hit->location.fileId, hit->location.line,
                                       hit->location.column, hit->location.blockNumber);
                }
            }
        }
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace kerf::ui
