#include "ui/viewport/viewport_widget.h"

#include <QApplication>
#include <QImage>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>
#include <QTranslator>
#include <chrono>
#include <filesystem>
#include <memory>

#include <QVTKOpenGLNativeWidget.h>
#include <gtest/gtest.h>

#include "graphics/stock/progressive_stock.h"
#include "graphics/toolpath/toolpath_data.h"
#include "graphics/toolpath/toolpath_lod.h"
#include "tests/graphics/canon_builder.h"
#include "tests/ui/viewport/viewport_test_app.h"

namespace kerf::ui {
namespace {

using graphics::test::CanonBuilder;

struct Fixture {
    graphics::Scene scene;
    std::shared_ptr<graphics::ToolpathData> data;
    ViewportWidget widget;
    explicit Fixture(const CanonBuilder& b) {
        graphics::ToolpathCollector collector;
        b.feed(collector);
        data = std::make_shared<graphics::ToolpathData>(collector.take());
        scene.setToolpath(data, std::make_shared<graphics::ToolpathGeometry>(
                                    graphics::buildToolpathGeometry(*data)));
        widget.resize(640, 520);
        widget.show();
        EXPECT_TRUE(QTest::qWaitForWindowExposed(&widget));
        widget.setScene(&scene);
        QApplication::processEvents();
    }
};

// Square 0..100 at Z0; line 2 its bottom edge (Y = 0).
CanonBuilder square() {
    CanonBuilder b;
    b.rapid(0, 0, 0).line(100, 0, 0).line(100, 100, 0).line(0, 100, 0).line(0, 0, 0);
    return b;
}

// Translates the view buttons the way kerf_de.ts does.
class GermanViews : public QTranslator {
public:
    QString translate(const char* context, const char* source, const char* disambiguation,
                      int n) const override {
        (void)disambiguation;
        (void)n;
        if (QString::fromUtf8(context) != QLatin1String("kerf::ui::ViewportWidget")) return {};
        const QString text = QString::fromUtf8(source);
        if (text == QLatin1String("Top")) return QStringLiteral("Draufsicht");
        if (text == QLatin1String("Fit")) return QStringLiteral("Einpassen");
        return {};
    }
    bool isEmpty() const override { return false; }
};

// The buttons are made before the language is chosen (--language, the Language key, MOD): they
// stayed "Top", "Fit" in every language.
TEST(ViewportWidget, TheViewButtonsFollowTheLanguageChosenAfterwards) {
    test::viewportTestApp();
    ViewportWidget widget;
    GermanViews german;
    QCoreApplication::installTranslator(&german);
    QApplication::processEvents();  // LanguageChange reaches the widget
    const QString top = widget.viewButton(graphics::View::Top)->text();
    const auto* fit = widget.findChild<QToolButton*>(QStringLiteral("fitView"));
    const QString fitText = fit != nullptr ? fit->text() : QString();
    QCoreApplication::removeTranslator(&german);
    QApplication::processEvents();
    EXPECT_EQ(top, QStringLiteral("Draufsicht"));
    EXPECT_EQ(fitText, QStringLiteral("Einpassen"));
    EXPECT_EQ(widget.viewButton(graphics::View::Top)->text(), QStringLiteral("Top"));
}

TEST(ViewportWidget, ShowsTheToolpathAndPicksTheClickedBlock) {
    test::viewportTestApp();
    Fixture f(square());
    f.widget.viewButton(graphics::View::Top)->click();
    QApplication::processEvents();
    auto* area = f.widget.renderArea();
    const int w = area->width();
    const int h = area->height();
    // Top view: the content fills the height (1/1.08) around the centre: Y = 0 is the lower edge.
    const double scale = h / 2.0 / 1.08 / 50.0;  // pixels per mm
    const QPoint bottomEdge(w / 2, static_cast<int>(h / 2.0 + 50.0 * scale));
    QSignalSpy picked(&f.widget, &ViewportWidget::segmentPicked);
    QTest::mouseClick(area, Qt::LeftButton, Qt::NoModifier, bottomEdge);
    ASSERT_EQ(picked.count(), 1);
    EXPECT_EQ(picked.at(0).at(1).toUInt(), 2u);
    // A click on empty space picks nothing.
    QTest::mouseClick(area, Qt::LeftButton, Qt::NoModifier, QPoint(w / 2, h / 2));
    EXPECT_EQ(picked.count(), 1);

    // The picture shows the feed colour along the edge and the background in the middle.
    auto* vtkWidget = qobject_cast<QVTKOpenGLNativeWidget*>(area);
    ASSERT_NE(vtkWidget, nullptr);
    f.widget.render();
    const QImage image = vtkWidget->grabFramebuffer();
    ASSERT_FALSE(image.isNull());
    image.save(QString::fromStdString(
        (std::filesystem::temp_directory_path() / "kerf_viewport_top.png").string()));
    const QColor centre = image.pixelColor(image.width() / 2, image.height() / 2);
    bool found = false;
    const int y = static_cast<int>(bottomEdge.y() * image.height() / static_cast<double>(h));
    for (int dy = -2; dy <= 2 && !found; ++dy) {
        const QColor c = image.pixelColor(image.width() / 3, y + dy);
        found = c.blue() > 180 && c.green() > 150 && c.red() < 150;  // feed: light blue
    }
    EXPECT_TRUE(found);
    EXPECT_LT(centre.blue(), 100);
}

TEST(ViewportWidget, HighlightsAndZoomsAndFollowsTheStock) {
    test::viewportTestApp();
    CanonBuilder b = square();
    b.box(Vec3(-10, -10, -10), Vec3(110, 110, 0)).tool(1, 4.0).rapid(50, 50, 5).line(50, 50, -3);
    Fixture f(b);
    f.widget.highlightBlock(0, 3);
    EXPECT_EQ(f.scene.stats().highlightedSegments, 1u);
    f.widget.clearHighlight();
    EXPECT_EQ(f.scene.stats().highlightedSegments, 0u);

    graphics::ProgressiveStock stock(graphics::StockOptions{}, 128, std::chrono::milliseconds(20));
    f.widget.followStock(&stock);
    for (const auto& command : b.commands)
        stock.push(command);
    stock.finish();
    EXPECT_TRUE(QTest::qWaitFor(
        [&] { return f.scene.stats().stockTriangles > 0 && stock.latest()->finished; }, 20000));
    EXPECT_NEAR(stock.latest()->removedVolumeMm3, 3.14159265 * 16 * 3, 0.03 * 3.14159265 * 16 * 3);
    f.widget.followStock(nullptr);

    // Zooming in moves the edges off screen: the bottom edge is no longer under the old point.
    f.widget.setView(graphics::View::Top);
    f.widget.zoomBy(4.0);
    auto* area = f.widget.renderArea();
    QSignalSpy picked(&f.widget, &ViewportWidget::segmentPicked);
    QTest::mouseClick(area, Qt::LeftButton, Qt::NoModifier,
                      QPoint(area->width() / 2, area->height() - 5));
    EXPECT_EQ(picked.count(), 0);
}

}  // namespace
}  // namespace kerf::ui
