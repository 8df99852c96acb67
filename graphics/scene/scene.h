#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string_view>
#include <variant>
#include <vector>

#include "core/base/expected.h"
#include "core/base/source_location.h"
#include "graphics/stock/cutter.h"
#include "graphics/stock/mesh.h"
#include "graphics/toolpath/toolpath_data.h"
#include "graphics/toolpath/toolpath_lod.h"

// The graphics facade: no VTK type appears here. The UI and the runner build a Scene from the
// canonical stream's toolpath and stock models and show it in a viewport (ui/viewport, through
// graphics/scene/scene_vtk.h) or render it off screen (OffscreenRenderer).
namespace kerf::graphics {

enum class View : uint8_t { Iso, Top, Front, Side, LatheSection };
const char* viewName(View view);
// "3d", "top", "front", "side", "section" (lathe XZ half section).
std::optional<View> viewFromName(std::string_view name);

struct SceneOptions {
    bool lathe = false;
    std::optional<Bounds3> limits;  // soft limits, drawn as a box (lathe: X radius, Z)
    bool showAxes = true;
    bool gradientBackground = false;     // costs frame rate on software OpenGL
    double lodErrorPx = 0.75;            // level of detail while the view is still
    double interactiveLodErrorPx = 3.0;  // while the user drags (setInteractive)
};

// The tool drawn at the current position.
struct ToolGlyph {
    std::variant<std::monostate, MillCutter, LatheInsert> shape;
    Axis axis = Axis::Z;
};

struct PickHit {
    uint32_t move = 0;
    SourceLocation location;
    MoveKind kind = MoveKind::Feed;
    Vec3 point;  // nearest point of the segment, mm
    double distancePx = 0.0;
};

struct SceneStats {
    size_t chunks = 0;
    size_t segmentsFull = 0;       // at full detail
    size_t segmentsSelected = 0;   // in the levels chosen at the last render (culling aside)
    std::vector<int> chunkLevels;  // level chosen per chunk at the last render
    size_t highlightedSegments = 0;
    size_t executedSegments = 0;
    size_t stockTriangles = 0;
    size_t toolAxisLines = 0;  // drawn along tilted moves
};

class Scene {
public:
    explicit Scene(SceneOptions options = {});
    ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    // The toolpath: the collected data (picking, highlighting) and its level-of-detail geometry
    // (built with buildToolpathGeometry, typically on a worker thread). Both must describe the
    // same path; either may be null to clear it.
    void setToolpath(std::shared_ptr<const ToolpathData> data,
                     std::shared_ptr<const ToolpathGeometry> geometry);
    // Shaded stock (null or empty: none).
    void setStockMesh(std::shared_ptr<const Mesh> mesh);
    void setTool(const ToolGlyph& tool);
    // The tool's tip and its direction on the workpiece (unit, from the tip up the tool: a rotary
    // table tilts it); the glyph, built along its axis, is turned from Z onto `axis`.
    void setToolPosition(const Vec3& position, const Vec3& axis = Vec3::UnitZ());
    // The part of the toolpath already executed, drawn over the path in its own colour: the
    // path's points [fromPoint, toPoint) and then `tip` (where the run is along the next
    // segment). Moving on only appends; an empty range clears it.
    void setExecutedPath(size_t fromPoint, size_t toPoint, const Vec3& tip);
    void clearExecutedPath();

    // Camera presets; each fits the content (toolpath and stock) into the viewport.
    void setView(View view);
    View view() const;
    void fit();
    // Zooms about the view centre (factor > 1 magnifies) and turns the camera about the view-up
    // axis and the horizontal axis, in degrees (the viewport's buttons and tests use these).
    void zoom(double factor);
    void rotate(double azimuthDeg, double elevationDeg);
    // Pixel size of the viewport the scene is shown in (set by the renderer or widget).
    void setViewportSize(int width, int height);
    // Coarser level of detail while the user rotates, zooms or pans.
    void setInteractive(bool interactive);

    // The move whose segment is nearest the pixel (x right, y down from the top-left corner),
    // within `tolerancePx`; nothing if none is.
    std::optional<PickHit> pick(double x, double y, double tolerancePx = 6.0) const;
    // Highlights every segment of the moves from this source line (the block selected in the
    // editor); returns how many segments that is.
    size_t highlightBlock(uint32_t fileId, uint32_t line);
    size_t highlightMoves(const std::vector<uint32_t>& moves);
    void clearHighlight();

    Bounds3 contentBounds() const;
    SceneStats stats() const;

    struct Impl;
    Impl& impl() { return *m_impl; }
    const Impl& impl() const { return *m_impl; }

private:
    std::unique_ptr<Impl> m_impl;
};

// Renders scenes into an off-screen window of a fixed size (needs an X display: see
// VirtualDisplay). Main thread only.
class OffscreenRenderer {
public:
    OffscreenRenderer(int width, int height);
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    // Renders once and returns the picture as RGB rows, top row first.
    std::vector<uint8_t> renderRgb(Scene& scene);
    MaybeError renderToPng(Scene& scene, const std::filesystem::path& file);
    // Frames per second rendering `frames` frames while the camera turns about the view-up
    // axis by `degreesPerFrame` (after one warm-up frame).
    double measureFps(Scene& scene, int frames, double degreesPerFrame = 2.0);
    int width() const { return m_width; }
    int height() const { return m_height; }

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    int m_width;
    int m_height;
};

// Checks that an X display can be opened (VTK aborts the process when it cannot).
MaybeError checkDisplay();

// Writes RGB rows (top first) as a PNG, and reads one back (tests, baselines).
MaybeError writePng(const std::filesystem::path& file, const std::vector<uint8_t>& rgb, int width,
                    int height);
Expected<std::vector<uint8_t>> readPng(const std::filesystem::path& file, int& width, int& height);

}  // namespace kerf::graphics
