#include "graphics/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "canon_builder.h"
#include "core/geometry/arc_math.h"
#include "graphics/headless/virtual_display.h"
#include "graphics/stock/stock_simulation.h"
#include "graphics/toolpath/toolpath_data.h"
#include "graphics/toolpath/toolpath_lod.h"

namespace kerf::graphics {
namespace {

using test::CanonBuilder;
namespace fs = std::filesystem;

const fs::path kTests = KERF_GRAPHICS_TESTS;

// Every test here renders through X: start Xvfb when the suite runs without a display.
class GraphicsEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        auto display = VirtualDisplay::ensure();
        if (display) m_display = *display;
    }
    void TearDown() override;

private:
    std::shared_ptr<VirtualDisplay> m_display;
};
const auto* const kEnvironment = ::testing::AddGlobalTestEnvironment(new GraphicsEnvironment);

fs::path outputDir() {
    fs::path dir = fs::temp_directory_path() / ("kerf_graphics_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

// The pictures stay for inspection only when a test failed.
void GraphicsEnvironment::TearDown() {
    m_display.reset();
    std::error_code error;
    if (::testing::UnitTest::GetInstance()->Passed()) fs::remove_all(outputDir(), error);
}

struct Built {
    std::shared_ptr<ToolpathData> data;
    std::shared_ptr<ToolpathGeometry> geometry;
};

Built build(const CanonBuilder& b) {
    ToolpathCollector collector;
    b.feed(collector);
    Built built;
    built.data = std::make_shared<ToolpathData>(collector.take());
    built.geometry = std::make_shared<ToolpathGeometry>(buildToolpathGeometry(*built.data));
    return built;
}

// Square 0..100 in XY at Z0: line 2 bottom edge, 3 right, 4 top, 5 left.
CanonBuilder square() {
    CanonBuilder b;
    b.rapid(0, 0, 0).line(100, 0, 0).line(100, 100, 0).line(0, 100, 0).line(0, 0, 0);
    return b;
}

// The picture fits the cutting moves (and the blank), not the rapid from the home position far
// above the part: after homing the part would be a few pixels on screen.
TEST(Scene, TheFitLeavesOutRapidsAwayFromThePart) {
    CanonBuilder b;
    b.rapid(0, 0, 400).rapid(0, 0, 2).line(0, 0, 0);
    b.line(100, 0, 0).line(100, 100, 0).line(0, 100, 0).line(0, 0, 0).rapid(0, 0, 400);
    Built built = build(b);
    Scene scene;
    scene.setToolpath(built.data, built.geometry);
    const Bounds3 box = scene.contentBounds();
    EXPECT_DOUBLE_EQ(box.max.z(), 2.0);  // the first feed move starts at Z+2
    EXPECT_DOUBLE_EQ(box.min.z(), 0.0);
    EXPECT_DOUBLE_EQ(box.max.x(), 100.0);
    EXPECT_DOUBLE_EQ(box.max.y(), 100.0);
    // Rapids only (nothing is cut): they are the picture.
    CanonBuilder rapids;
    rapids.rapid(0, 0, 400).rapid(50, 0, 10);
    Built onlyRapids = build(rapids);
    scene.setToolpath(onlyRapids.data, onlyRapids.geometry);
    EXPECT_DOUBLE_EQ(scene.contentBounds().max.z(), 400.0);
}

TEST(Scene, TopViewPicksEachEdgeOfASquare) {
    ASSERT_FALSE(checkDisplay().has_value());
    Scene scene;
    Built built = build(square());
    scene.setToolpath(built.data, built.geometry);
    scene.setViewportSize(400, 400);
    scene.setView(View::Top);
    // Content 100 x 100 fills 400 / 1.08 pixels: the edges sit 200 -+ 185.2 px from the centre.
    const double edge = 200.0 * 1.0 / 1.08;
    auto lineAt = [&](double x, double y) -> int {
        auto hit = scene.pick(x, y, 4.0);
        return hit ? static_cast<int>(hit->location.line) : -1;
    };
    EXPECT_EQ(lineAt(200, 200 + edge), 2);  // bottom: Y = 0
    EXPECT_EQ(lineAt(200 + edge, 200), 3);  // right: X = 100
    EXPECT_EQ(lineAt(200, 200 - edge), 4);  // top
    EXPECT_EQ(lineAt(200 - edge, 200), 5);  // left
    EXPECT_EQ(lineAt(200, 200), -1);        // nothing in the middle
    auto hit = scene.pick(150, 200 + edge, 4.0);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->kind, MoveKind::Feed);
    EXPECT_NEAR(hit->point.y(), 0.0, 1e-6);
    EXPECT_NEAR(hit->point.x(), 50.0 - 50.0 * 54.0 / 200.0, 0.5);  // 200/54 px per mm
}

TEST(Scene, FrontAndSideViewsOrientTheAxes) {
    CanonBuilder b;
    b.rapid(0, 0, 0).line(0, 0, 50).line(50, 0, 50).line(50, 50, 50);  // up Z, along X, along Y
    Built built = build(b);
    Scene scene;
    scene.setToolpath(built.data, built.geometry);
    scene.setViewportSize(400, 400);
    scene.setView(View::Front);  // X right, Z up: the Z line is the left edge, the X line the top
    const double edge = 200.0 / 1.08;
    EXPECT_EQ(scene.pick(200 - edge, 200, 4)->location.line, 2u);
    EXPECT_EQ(scene.pick(200, 200 - edge, 4)->location.line, 3u);
    scene.setView(View::Side);  // Y right, Z up: the Z line is on the left, the Y line on top
    EXPECT_EQ(scene.pick(200 - edge, 200, 4)->location.line, 2u);
    EXPECT_EQ(scene.pick(200, 200 - edge, 4)->location.line, 4u);
    scene.setView(View::LatheSection);  // Z right, X up: the Z line at the bottom, the X line right
    EXPECT_EQ(scene.pick(200, 200 + edge, 4)->location.line, 2u);
    EXPECT_EQ(scene.pick(200 + edge, 200, 4)->location.line, 3u);
}

// The colour class of the most saturated pixel within 2 px of (x, y): 'r' red (rapid), 'c' cyan
// (feed), 'g' green (arc), '-' background.
char colourNear(const std::vector<uint8_t>& rgb, int width, int x, int y) {
    int best = 0;
    char kind = '-';
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            const size_t i = (static_cast<size_t>(y + dy) * static_cast<size_t>(width) +
                              static_cast<size_t>(x + dx)) *
                             3;
            const int r = rgb[i];
            const int g = rgb[i + 1];
            const int b = rgb[i + 2];
            const int spread = std::max({r, g, b}) - std::min({r, g, b});
            if (spread <= best) continue;
            best = spread;
            kind = r > g && r > b ? 'r' : (b > r && b >= g ? 'c' : (g > r && g > b ? 'g' : '?'));
        }
    }
    return best > 80 ? kind : '-';
}

TEST(SceneImage, RapidFeedAndArcMovesHaveTheirOwnColours) {
    // Top view, 400 x 400: the feed moves (X 25..100, Y 0..100; the fit leaves the rapids out)
    // fill 400 / 1.08 px in Y, 3.704 px per mm about (62.5, 50). Bottom edge a rapid, right edge
    // a feed, a circle of radius 25 about (50, 50).
    CanonBuilder b;
    b.rapid(0, 0, 0)
        .rapid(100, 0, 0)
        .line(100, 100, 0)
        .line(75, 50, 0)
        .arc(75, 50, 0, 50, 50, 2 * kPi);
    Built built = build(b);
    SceneOptions options;
    options.showAxes = false;
    Scene scene(options);
    scene.setToolpath(built.data, built.geometry);
    OffscreenRenderer renderer(400, 400);
    scene.setViewportSize(400, 400);
    scene.setView(View::Top);
    const auto rgb = renderer.renderRgb(scene);
    const double pxPerMm = 200.0 / 54.0;
    auto px = [&](double mm) {
        return static_cast<int>(std::lround(200.0 + (mm - 62.5) * pxPerMm));
    };
    auto py = [&](double mm) {
        return static_cast<int>(std::lround(200.0 - (mm - 50.0) * pxPerMm));
    };
    EXPECT_EQ(colourNear(rgb, 400, px(50), py(0)), 'r');         // bottom edge, Y = 0 (y down)
    EXPECT_EQ(colourNear(rgb, 400, px(100), py(50) - 60), 'c');  // right edge
    EXPECT_EQ(colourNear(rgb, 400, px(25), py(50)), 'g');        // left of the circle
    EXPECT_EQ(colourNear(rgb, 400, px(50), py(50) + 30), '-');   // inside the circle: nothing
}

TEST(Scene, HighlightsTheSegmentsOfABlock) {
    CanonBuilder b;
    b.rapid(10, 0, 0).arc(10, 0, 0, 0, 0, 2 * kPi).line(20, 0, 0);
    Built built = build(b);
    Scene scene;
    scene.setToolpath(built.data, built.geometry);
    const auto [begin, end] = built.data->pointsOfMove(1);
    EXPECT_EQ(scene.highlightBlock(0, 2), end - begin);
    EXPECT_GT(end - begin, 100u);
    EXPECT_EQ(scene.stats().highlightedSegments, end - begin);
    EXPECT_EQ(scene.highlightBlock(0, 3), 1u);
    EXPECT_EQ(scene.highlightBlock(0, 99), 0u);
    EXPECT_EQ(scene.highlightBlock(7, 2), 0u);  // another file
    scene.clearHighlight();
    EXPECT_EQ(scene.stats().highlightedSegments, 0u);
}

TEST(Scene, LetsGoOfItsToolpathAndStock) {
    std::weak_ptr<const ToolpathData> data;
    std::weak_ptr<const ToolpathGeometry> geometry;
    std::weak_ptr<const Mesh> mesh;
    {
        Built built = build(square());
        auto stock = std::make_shared<Mesh>();
        stock->addTriangle(stock->addVertex(Vec3(0, 0, 0), Vec3(0, 0, 1)),
                           stock->addVertex(Vec3(1, 0, 0), Vec3(0, 0, 1)),
                           stock->addVertex(Vec3(0, 1, 0), Vec3(0, 0, 1)));
        data = built.data;
        geometry = built.geometry;
        mesh = stock;
        Scene scene;
        scene.setToolpath(built.data, built.geometry);
        scene.setStockMesh(stock);
        built = {};
        stock.reset();
        EXPECT_FALSE(data.expired());
        scene.setStockMesh(nullptr);  // replacing drops the old one at once
        EXPECT_TRUE(mesh.expired());
    }
    EXPECT_TRUE(data.expired());
    EXPECT_TRUE(geometry.expired());
}

TEST(Scene, LevelOfDetailFollowsTheZoom) {
    CanonBuilder b;
    for (int row = 0; row < 200; ++row) {
        for (int i = 0; i <= 500; ++i) {
            const double x = row % 2 == 0 ? i * 0.2 : (500 - i) * 0.2;
            b.line(x, row * 0.5, 0.3 * std::sin(x / 5.0));
        }
    }
    Built built = build(b);
    Scene scene;
    scene.setToolpath(built.data, built.geometry);
    OffscreenRenderer renderer(640, 400);
    scene.setView(View::Iso);
    (void)renderer.renderRgb(scene);
    const SceneStats whole = scene.stats();
    EXPECT_EQ(whole.segmentsFull, built.data->segmentCount());
    EXPECT_LT(whole.segmentsSelected, whole.segmentsFull / 3);
    scene.zoom(64.0);
    (void)renderer.renderRgb(scene);
    const SceneStats close = scene.stats();
    EXPECT_GT(close.segmentsSelected, whole.segmentsSelected);
    for (size_t c = 0; c < close.chunkLevels.size(); ++c) {
        EXPECT_LE(close.chunkLevels[c], whole.chunkLevels[c]);
    }
}

// Mean absolute difference (0-255) and share of pixels off by more than 48 in any channel.
struct Difference {
    double mean = 0.0;
    double badShare = 0.0;
};
Difference compare(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    Difference d;
    if (a.size() != b.size() || a.empty()) return {255.0, 1.0};
    size_t bad = 0;
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); i += 3) {
        int worst = 0;
        for (size_t c = 0; c < 3; ++c) {
            const int diff = std::abs(int{a[i + c]} - int{b[i + c]});
            sum += diff;
            worst = std::max(worst, diff);
        }
        if (worst > 48) ++bad;
    }
    d.mean = sum / static_cast<double>(a.size());
    d.badShare = static_cast<double>(bad) / static_cast<double>(a.size() / 3);
    return d;
}

// Compares with tests/graphics/baselines/NAME.png. llvmpipe renders the same picture bit for bit
// on every run, with xvfb-run's X server or the one VirtualDisplay starts (no anti-aliasing, no
// multisampling, fixed window size), so the thresholds only leave room for a Mesa or FreeType
// update moving edge pixels and glyphs: a mean difference of at most 1.0 (a background or shading
// change over the picture is several units) and at most 0.1 % of the pixels off by more than 48
// in a channel (64 pixels at 320x200, where one drilled hole covers some 60).
// KERF_UPDATE_BASELINES=1 rewrites the baseline instead.
void expectMatchesBaseline(const std::string& name, const std::vector<uint8_t>& rgb, int w, int h) {
    const fs::path baseline = kTests / "baselines" / (name + ".png");
    const fs::path actual = outputDir() / (name + ".png");
    ASSERT_FALSE(writePng(actual, rgb, w, h).has_value());
    if (std::getenv("KERF_UPDATE_BASELINES") != nullptr) {
        fs::create_directories(baseline.parent_path());
        fs::copy_file(actual, baseline, fs::copy_options::overwrite_existing);
        GTEST_SKIP() << "baseline rewritten: " << baseline;
    }
    int bw = 0;
    int bh = 0;
    auto expected = readPng(baseline, bw, bh);
    ASSERT_TRUE(expected.ok()) << "missing baseline " << baseline << " (actual: " << actual << ")";
    ASSERT_EQ(bw, w);
    ASSERT_EQ(bh, h);
    const Difference d = compare(rgb, *expected);
    EXPECT_LE(d.mean, 1.0) << "actual picture: " << actual;
    EXPECT_LE(d.badShare, 0.001) << "actual picture: " << actual;
}

TEST(SceneImage, DrilledBlockBaseline) {
    StockOptions options;
    options.millCutter = [](const canon::ToolChange& t) {
        return MillCutter::fromGeometry(t.geometry.radiusMm, 0.0, 118.0);
    };
    StockSimulation stock(options);
    CanonBuilder b;
    b.box(Vec3(0, 0, -20), Vec3(60, 40, 0)).tool(1, 2.5).rapid(0, 0, 5);
    for (double x : {15.0, 30.0, 45.0})
        b.rapid(x, 20, 5).line(x, 20, -10).rapid(x, 20, 5);
    b.feed(stock);
    stock.finish();
    Built built = build(b);
    Scene scene;
    ToolGlyph glyph;
    glyph.shape = MillCutter::fromGeometry(2.5, 0.0, 118.0);
    scene.setTool(glyph);
    scene.setToolpath(built.data, built.geometry);
    scene.setStockMesh(std::make_shared<Mesh>(stock.mesh()));
    OffscreenRenderer renderer(320, 200);
    scene.setViewportSize(320, 200);
    scene.setView(View::Iso);
    const auto rgb = renderer.renderRgb(scene);
    // Geometry first: the stock fills the middle of the picture (not the background).
    const size_t centre = (100 * 320 + 160) * 3;
    EXPECT_GT(rgb[centre] + rgb[centre + 1] + rgb[centre + 2], 3 * 70);
    expectMatchesBaseline("drilled_block_iso", rgb, 320, 200);
}

TEST(SceneImage, LatheSectionBaseline) {
    StockOptions options;
    options.machine = StockMachine::Lathe;
    LatheBar bar;
    bar.radiusMm = 20;
    bar.zMin = -60;
    bar.zMax = 0;
    options.bar = bar;
    StockSimulation stock(options);
    CanonBuilder b;
    b.tool(1, 0.8).rapid(25, 0, 2);
    for (double x = 18; x >= 12; x -= 2)
        b.rapid(x, 0, 2).line(x, 0, -30).line(x + 1, 0, -30).rapid(x + 1, 0, 2);
    b.rapid(10, 0, 2)
        .line(10, 0, -10)
        .arc(14, 0, -14, -14, 10, kPi / 2, Plane::ZX)
        .rapid(25, 0, -14);
    b.feed(stock);
    stock.finish();
    Built built = build(b);
    SceneOptions sceneOptions;
    sceneOptions.lathe = true;
    Scene scene(sceneOptions);
    ToolGlyph glyph;
    LatheInsert insert;
    insert.noseRadiusMm = 0.8;
    insert.includedAngleDeg = 80;
    insert.edgeLengthMm = 8;
    glyph.shape = insert;
    scene.setTool(glyph);
    scene.setToolpath(built.data, built.geometry);
    scene.setStockMesh(std::make_shared<Mesh>(stock.mesh()));
    OffscreenRenderer renderer(320, 200);
    scene.setViewportSize(320, 200);
    scene.setView(View::LatheSection);
    const auto rgb = renderer.renderRgb(scene);
    expectMatchesBaseline("lathe_section", rgb, 320, 200);
    EXPECT_GT(stock.removedVolumeMm3(), 0.0);
}

TEST(SceneImage, EmptySceneRenders) {
    Scene scene;
    OffscreenRenderer renderer(64, 48);
    scene.setView(View::Top);
    const auto rgb = renderer.renderRgb(scene);
    EXPECT_EQ(rgb.size(), 64u * 48u * 3u);
    EXPECT_FALSE(scene.pick(32, 24).has_value());
    scene.setToolpath(nullptr, nullptr);
    scene.setStockMesh(nullptr);
    EXPECT_EQ(scene.stats().chunks, 0u);
}

// --- kerf run --png / --stock -----------------------------------------------------------------

int runKerf(const std::string& arguments) {
    const std::string command = std::string("\"") + KERF_BINARY + "\" run " + arguments;
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

nlohmann::json readJson(const fs::path& file) {
    std::ifstream in(file);
    return nlohmann::json::parse(in, nullptr, false);
}

TEST(KerfRun, ThreeDrilledHolesPictureAndVolume) {
    const fs::path dir = outputDir();
    const fs::path png = dir / "drill3.png";
    const fs::path report = dir / "drill3.json";
    const fs::path program = kTests / "programs" / "drill3.H";
    ASSERT_EQ(runKerf(program.string() + " --png " + png.string() + " --stock --report " +
                      report.string() + " --size 640x400"),
              0);
    int w = 0;
    int h = 0;
    auto rgb = readPng(png, w, h);
    ASSERT_TRUE(rgb.ok());
    EXPECT_EQ(w, 640);
    EXPECT_EQ(h, 400);
    const nlohmann::json r = readJson(report);
    // Three holes D5, 118 degree point, 10 mm deep: 3 x (pi r^2 (10 - c) + pi r^2 c / 3),
    // c = r / tan(59 deg).
    const double c = 2.5 / std::tan(degToRad(59.0));
    const double expected = 3 * kPi * 6.25 * (10 - c + c / 3);
    EXPECT_NEAR(r["stock"]["removed_volume_mm3"].get<double>(), expected, 0.02 * expected);
    EXPECT_EQ(r["picture"]["written"], true);
    EXPECT_EQ(r["picture"]["view"], "3d");
}

TEST(KerfRun, HeldOutPocketRendersFromTheTopAndMatchesItsVolume) {
    const fs::path dir = outputDir();
    const fs::path png = dir / "pocket.png";
    const fs::path report = dir / "pocket.json";
    const fs::path program = kTests / "programs" / "heldout_pocket.H";
    ASSERT_EQ(runKerf(program.string() + " --png " + png.string() + " --view top --size 400x300 " +
                      "--stock --report " + report.string()),
              0);
    const nlohmann::json r = readJson(report);
    // Circular pocket: D10 mill, circle of radius 10 about (30, 20), then radius 5: a disc of
    // radius 15, 4 mm deep; plus a 20 mm slot 2 mm deep: (2 r L + pi r^2) d.
    const double expected = kPi * 15 * 15 * 4 + (2 * 5 * 20 + kPi * 25) * 2;
    EXPECT_NEAR(r["stock"]["removed_volume_mm3"].get<double>(), expected, 0.02 * expected);
    int w = 0;
    int h = 0;
    auto rgb = readPng(png, w, h);
    ASSERT_TRUE(rgb.ok());
    expectMatchesBaseline("heldout_pocket_top", *rgb, w, h);
}

TEST(KerfRun, LatheWithoutBlankTurnsTheConfiguredBar) {
    const fs::path dir = outputDir();
    const fs::path report = dir / "face_bar.json";
    const fs::path program = kTests / "programs" / "face_bar.pim";
    ASSERT_EQ(
        runKerf(program.string() + " --machine lathe --stock --png " +
                (dir / "face_bar.png").string() + " --size 320x200 --report " + report.string()),
        0);
    const nlohmann::json r = readJson(report);
    // The built-in lathe's bar: D60, 120 mm long, face at Z0; the sharp tool (no offset table:
    // R 0, location code 0) faces it 1 mm deep from X70 to the axis: a disc of radius 30, 1 mm
    // thick, and at most one 0.1 mm cell more, as a sharp tool's cut may reach one cell further.
    EXPECT_EQ(r["stock"]["source"], "bar");
    EXPECT_NEAR(r["stock"]["initial_volume_mm3"].get<double>(), kPi * 30 * 30 * 120, 1.0);
    const double removed = r["stock"]["removed_volume_mm3"].get<double>();
    EXPECT_GE(removed, kPi * 30 * 30 * 1.0 * 0.999);
    EXPECT_LE(removed, kPi * 30 * 30 * 1.1 * 1.001);
}

TEST(KerfRun, StartsItsOwnXvfbWhenNoDisplayIsSet) {
    const fs::path png = outputDir() / "own_display.png";
    const fs::path program = kTests / "programs" / "drill3.H";
    const std::string command = "env -u DISPLAY \"" + std::string(KERF_BINARY) + "\" run " +
                                program.string() + " --png " + png.string() + " --size 64x48";
    const int status = std::system(command.c_str());
    ASSERT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0);
    int w = 0;
    int h = 0;
    ASSERT_TRUE(readPng(png, w, h).ok());
    EXPECT_EQ(w, 64);
    EXPECT_EQ(h, 48);
}

TEST(KerfRun, BadOptionsAndMissingXvfbFailClearly) {
    const fs::path dir = outputDir();
    const fs::path program = kTests / "programs" / "drill3.H";
    EXPECT_EQ(runKerf(program.string() + " --png " + (dir / "x.png").string() +
                      " --view bottom 2>/dev/null"),
              2);
    EXPECT_EQ(runKerf(program.string() + " --png " + (dir / "x.png").string() +
                      " --size 10x 2>/dev/null"),
              2);
    // No DISPLAY and no Xvfb on the PATH: a clear message, exit code 1, no picture.
    const fs::path log = dir / "noxvfb.log";
    const fs::path none = dir / "none.png";
    const std::string command = "env -u DISPLAY PATH=/nonexistent \"" + std::string(KERF_BINARY) +
                                "\" run " + program.string() + " --png " + none.string() + " 2>" +
                                log.string();
    const int status = std::system(command.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1);
    std::ifstream in(log);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("Xvfb is not installed"), std::string::npos) << text;
    EXPECT_FALSE(fs::exists(none));
}

}  // namespace
}  // namespace kerf::graphics
