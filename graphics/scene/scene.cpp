#include "graphics/scene/scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCoordinate.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>

#include "graphics/scene/detail/scene_impl.h"
#include "graphics/scene/detail/tool_axis_lines.h"
#include "graphics/scene/scene_vtk.h"
#include "graphics/stock/tool_mesh.h"

namespace kerf::graphics {

namespace {

constexpr std::array<std::array<double, 3>, kMoveKindCount> kKindColours{{
    {0.95, 0.35, 0.25},  // rapid
    {0.35, 0.85, 1.00},  // feed
    {0.55, 1.00, 0.45},  // arc
    {1.00, 0.85, 0.20},  // synced
    {0.90, 0.45, 1.00},  // probe
}};

vtkSmartPointer<vtkPolyData> polylineData(const PolylineSet& set) {
    auto data = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkFloatArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetNumberOfTuples(static_cast<vtkIdType>(set.pointCount()));
    std::copy(set.xyz.begin(), set.xyz.end(), coordinates->GetPointer(0));
    vtkNew<vtkPoints> points;
    points->SetData(coordinates);
    vtkNew<vtkTypeInt32Array> offsets;
    offsets->SetNumberOfTuples(static_cast<vtkIdType>(set.offsets.size()));
    std::copy(set.offsets.begin(), set.offsets.end(), offsets->GetPointer(0));
    vtkNew<vtkTypeInt32Array> connectivity;
    connectivity->SetNumberOfTuples(static_cast<vtkIdType>(set.pointCount()));
    int32_t* ids = connectivity->GetPointer(0);
    for (size_t i = 0; i < set.pointCount(); ++i)
        ids[i] = static_cast<int32_t>(i);
    vtkNew<vtkCellArray> lines;
    lines->SetData(offsets, connectivity);
    vtkNew<vtkUnsignedCharArray> kinds;
    kinds->SetNumberOfTuples(static_cast<vtkIdType>(set.kind.size()));
    std::copy(set.kind.begin(), set.kind.end(), kinds->GetPointer(0));
    kinds->SetName("kind");
    data->SetPoints(points);
    data->SetLines(lines);
    data->GetPointData()->SetScalars(kinds);
    return data;
}

Mesh toolMesh(const ToolGlyph& tool) {
    if (const auto* cutter = std::get_if<MillCutter>(&tool.shape)) {
        return millToolMesh(*cutter, tool.axis);
    }
    if (const auto* insert = std::get_if<LatheInsert>(&tool.shape)) {
        return latheInsertMesh(*insert, 1.0);
    }
    return {};
}

}  // namespace

vtkSmartPointer<vtkPolyData> meshData(const Mesh& mesh) {
    auto data = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkFloatArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertexCount()));
    std::copy(mesh.points.begin(), mesh.points.end(), coordinates->GetPointer(0));
    vtkNew<vtkPoints> points;
    points->SetData(coordinates);
    const size_t triangles = mesh.triangleCount();
    vtkNew<vtkTypeInt32Array> offsets;
    offsets->SetNumberOfTuples(static_cast<vtkIdType>(triangles + 1));
    int32_t* off = offsets->GetPointer(0);
    for (size_t t = 0; t <= triangles; ++t)
        off[t] = static_cast<int32_t>(3 * t);
    vtkNew<vtkTypeInt32Array> connectivity;
    connectivity->SetNumberOfTuples(static_cast<vtkIdType>(3 * triangles));
    int32_t* ids = connectivity->GetPointer(0);
    for (size_t i = 0; i < 3 * triangles; ++i)
        ids[i] = static_cast<int32_t>(mesh.triangles[i]);
    vtkNew<vtkCellArray> polys;
    polys->SetData(offsets, connectivity);
    data->SetPoints(points);
    data->SetPolys(polys);
    if (mesh.normals.size() == mesh.points.size() && !mesh.normals.empty()) {
        vtkNew<vtkFloatArray> normals;
        normals->SetNumberOfComponents(3);
        normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.vertexCount()));
        std::copy(mesh.normals.begin(), mesh.normals.end(), normals->GetPointer(0));
        data->GetPointData()->SetNormals(normals);
    }
    return data;
}

const char* viewName(View view) {
    switch (view) {
        case View::Iso:
            return "3d";
        case View::Top:
            return "top";
        case View::Front:
            return "front";
        case View::Side:
            return "side";
        case View::LatheSection:
            return "section";
    }
    return "?";
}

std::optional<View> viewFromName(std::string_view name) {
    for (View v : {View::Iso, View::Top, View::Front, View::Side, View::LatheSection}) {
        if (name == viewName(v)) return v;
    }
    if (name == "iso") return View::Iso;
    return std::nullopt;
}

Scene::Impl::Impl(SceneOptions sceneOptions) : options(sceneOptions) {
    view = options.lathe ? View::LatheSection : View::Iso;
    renderer->SetGradientBackground(options.gradientBackground);
    renderer->SetBackground(options.gradientBackground ? 0.10 : 0.15,
                            options.gradientBackground ? 0.11 : 0.17,
                            options.gradientBackground ? 0.14 : 0.21);
    renderer->SetBackground2(0.26, 0.29, 0.36);
    renderer->GetActiveCamera()->ParallelProjectionOn();
    lookupTable->SetNumberOfTableValues(kMoveKindCount);
    for (int k = 0; k < kMoveKindCount; ++k) {
        const auto& c = kKindColours[static_cast<size_t>(k)];
        lookupTable->SetTableValue(k, c[0], c[1], c[2], 1.0);
    }
    lookupTable->SetTableRange(0.0, kMoveKindCount - 1);
    lookupTable->Build();

    lodCallback->SetClientData(this);
    lodCallback->SetCallback([](vtkObject*, unsigned long, void* client, void*) {
        static_cast<Scene::Impl*>(client)->updateLevels();
    });
    renderer->AddObserver(vtkCommand::StartEvent, lodCallback);

    stockColours->SetHueRange(0.58, 0.58);
    stockColours->SetSaturationRange(0.10, 0.06);
    stockColours->SetValueRange(0.40, 0.85);
    stockColours->Build();
    stockMapper->SetLookupTable(stockColours);
    stockMapper->UseLookupTableScalarRangeOff();
    stockMapper->SetScalarModeToUsePointData();
    stockMapper->SetResolveCoincidentTopologyToPolygonOffset();
    stockMapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(2.0, 8.0);
    stockActor->SetMapper(stockMapper);
    stockActor->GetProperty()->SetColor(0.72, 0.75, 0.80);
    stockActor->GetProperty()->SetAmbient(0.15);
    stockActor->GetProperty()->SetDiffuse(0.8);
    stockActor->GetProperty()->SetSpecular(0.1);
    stockActor->GetProperty()->SetSpecularPower(20.0);
    stockActor->VisibilityOff();
    renderer->AddActor(stockActor);

    toolMapper->ScalarVisibilityOff();
    toolActor->SetMapper(toolMapper);
    toolActor->GetProperty()->SetColor(0.95, 0.78, 0.30);
    // Opaque: a translucent prop costs software OpenGL a depth-peeling pass over the whole frame.
    toolActor->GetProperty()->SetOpacity(1.0);
    toolActor->VisibilityOff();
    renderer->AddActor(toolActor);

    toolAxesMapper->ScalarVisibilityOff();
    toolAxesActor->SetMapper(toolAxesMapper);
    toolAxesActor->GetProperty()->SetColor(0.85, 0.55, 0.95);
    toolAxesActor->GetProperty()->LightingOff();
    toolAxesActor->PickableOff();
    toolAxesActor->VisibilityOff();
    renderer->AddActor(toolAxesActor);

    highlightMapper->ScalarVisibilityOff();
    highlightMapper->SetResolveCoincidentTopologyToPolygonOffset();
    highlightMapper->SetRelativeCoincidentTopologyLineOffsetParameters(0.0, -20.0);
    highlightActor->SetMapper(highlightMapper);
    highlightActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
    highlightActor->GetProperty()->SetLineWidth(4.0f);
    highlightActor->GetProperty()->LightingOff();
    highlightActor->VisibilityOff();
    renderer->AddActor(highlightActor);
    renderer->AddActor(executed.actor());

    if (options.limits && !options.limits->empty) {
        const Bounds3& b = *options.limits;
        vtkNew<vtkPoints> points;
        for (int k = 0; k < 8; ++k) {
            points->InsertNextPoint((k & 1) != 0 ? b.max.x() : b.min.x(),
                                    (k & 2) != 0 ? b.max.y() : b.min.y(),
                                    (k & 4) != 0 ? b.max.z() : b.min.z());
        }
        vtkNew<vtkCellArray> lines;
        const int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                  {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
        for (const auto& e : edges) {
            const vtkIdType ids[2] = {e[0], e[1]};
            lines->InsertNextCell(2, ids);
        }
        vtkNew<vtkPolyData> box;
        box->SetPoints(points);
        box->SetLines(lines);
        vtkNew<vtkPolyDataMapper> mapper;
        mapper->SetInputData(box);
        limitsActor->SetMapper(mapper);
        // Dim but opaque (see the tool): the look of 60 % grey over the background.
        limitsActor->GetProperty()->SetColor(0.40, 0.41, 0.45);
        limitsActor->GetProperty()->LightingOff();
        limitsActor->PickableOff();
        renderer->AddActor(limitsActor);
    }
    if (options.showAxes) {
        axesMapper->SetScalarModeToUseCellData();
        axesMapper->SetColorModeToDirectScalars();
        axesActor->SetMapper(axesMapper);
        axesActor->GetProperty()->SetLineWidth(2.0f);
        axesActor->GetProperty()->LightingOff();
        axesActor->PickableOff();
        renderer->AddActor(axesActor);
        const char* names[3] = {"X", "Y", "Z"};
        for (int a = 0; a < 3; ++a) {
            if (options.lathe && a == 1) continue;
            vtkNew<vtkTextActor> label;
            label->SetInput(names[a]);
            label->GetPositionCoordinate()->SetCoordinateSystemToWorld();
            label->GetTextProperty()->SetFontSize(14);
            label->GetTextProperty()->SetColor(a == 0 ? 1.0 : 0.4, a == 1 ? 1.0 : 0.4,
                                               a == 2 ? 1.0 : 0.4);
            label->GetTextProperty()->BoldOn();
            label->GetTextProperty()->ShadowOff();
            label->PickableOff();
            renderer->AddActor2D(label);
            axisLabels.push_back(label);
        }
        updateAxesScale();
    }
}

Scene::Impl::~Impl() {
    renderer->RemoveObserver(lodCallback);
    renderer->RemoveAllViewProps();
}

void Scene::Impl::updateLevels() {
    if (!geometry) return;
    vtkCamera* camera = renderer->GetActiveCamera();
    int height = viewportHeight;
    if (vtkRenderWindow* window = renderer->GetRenderWindow()) {
        const int* size = renderer->GetSize();
        if (size != nullptr && size[1] > 0) height = size[1];
        (void)window;
    }
    height = std::max(height, 1);
    const double error = interactive ? options.interactiveLodErrorPx : options.lodErrorPx;
    double position[3];
    camera->GetPosition(position);
    double direction[3];
    camera->GetDirectionOfProjection(direction);
    const bool parallel = camera->GetParallelProjection() != 0;
    const double viewAngle = camera->GetViewAngle() * std::acos(-1.0) / 180.0;
    for (size_t c = 0; c < chunks.size(); ++c) {
        const ToolpathChunk& chunk = geometry->chunks[c];
        double mmPerPixel = 0.0;
        if (parallel) {
            mmPerPixel = 2.0 * camera->GetParallelScale() / height;
        } else {
            const Vec3 centre = chunk.bounds.centre();
            const double depth = (centre.x() - position[0]) * direction[0] +
                                 (centre.y() - position[1]) * direction[1] +
                                 (centre.z() - position[2]) * direction[2];
            // The nearest part of the chunk sets the detail.
            const double nearest = std::max(depth - 0.5 * chunk.bounds.diagonal(), 1e-6);
            mmPerPixel = 2.0 * nearest * std::tan(viewAngle / 2.0) / height;
        }
        int level = chooseLevel(geometry->tolerances, mmPerPixel, error);
        level = std::min(level, static_cast<int>(chunk.levels.size()) - 1);
        level = std::max(level, 0);
        ChunkActor& actor = chunks[c];
        if (actor.level != level) {
            actor.mapper->SetInputData(actor.levels[static_cast<size_t>(level)]);
            actor.level = level;
        }
    }
}

Scene::Scene(SceneOptions options) : m_impl(std::make_unique<Impl>(options)) {}
Scene::~Scene() = default;

vtkRenderer* vtkRendererOf(Scene& scene) {
    return scene.impl().renderer;
}

void Scene::setToolpath(std::shared_ptr<const ToolpathData> data,
                        std::shared_ptr<const ToolpathGeometry> geometry) {
    Impl& d = *m_impl;
    for (auto& chunk : d.chunks)
        d.renderer->RemoveActor(chunk.actor);
    d.chunks.clear();
    d.data = std::move(data);
    d.geometry = std::move(geometry);
    clearHighlight();
    d.executed.clear();
    if (!d.geometry) return;
    d.chunks.reserve(d.geometry->chunks.size());
    for (const ToolpathChunk& chunk : d.geometry->chunks) {
        Impl::ChunkActor actor;
        for (const PolylineSet& set : chunk.levels)
            actor.levels.push_back(polylineData(set));
        actor.mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
        actor.mapper->SetLookupTable(d.lookupTable);
        actor.mapper->UseLookupTableScalarRangeOn();
        actor.mapper->SetColorModeToMapScalars();
        actor.mapper->SetScalarModeToUsePointData();
        actor.mapper->InterpolateScalarsBeforeMappingOff();
        actor.mapper->SetInputData(actor.levels.back());
        actor.mapper->StaticOn();  // inputs are set explicitly, never re-executed
        actor.level = static_cast<int>(actor.levels.size()) - 1;
        actor.actor = vtkSmartPointer<vtkActor>::New();
        actor.actor->SetMapper(actor.mapper);
        actor.actor->GetProperty()->LightingOff();
        actor.actor->GetProperty()->SetLineWidth(1.0f);
        d.renderer->AddActor(actor.actor);
        d.chunks.push_back(std::move(actor));
    }
    if (d.data && !d.tool.has_value()) {
        // Default glyph: the last tool of the program at the end of the path.
        if (!d.data->tools.empty()) {
            const canon::ToolChange& last = d.data->tools.back().tool;
            ToolGlyph glyph;
            glyph.axis = last.toolAxis;
            if (d.options.lathe) {
                LatheInsert insert = LatheInsert::fromGeometry(last.geometry);
                if (insert.kind == LatheToolKind::Turning) {
                    // The tool table gives the nose and the tip code; drawn as a rhombic insert
                    // of its NOSEA, or the common 80 degree one, so that it shows which way it
                    // cuts.
                    const double noseAngle = last.geometry.noseAngleDeg;
                    insert.noseRadiusMm = std::max(0.4, last.geometry.radiusMm);
                    insert.includedAngleDeg =
                        noseAngle > 0.0 && noseAngle < 180.0 ? noseAngle : 80.0;
                    insert.edgeLengthMm = 8.0;
                }
                glyph.shape = insert;
            } else {
                glyph.shape =
                    MillCutter::fromGeometry(last.geometry.radiusMm, last.geometry.radius2Mm);
            }
            setTool(glyph);
            d.tool.reset();
        }
    }
    // The tool's direction where a table tilts it, a fifth of the cutting moves' extent long.
    constexpr size_t kMaxToolAxisLines = 400;
    vtkSmartPointer<vtkPolyData> axes;
    if (d.data) {
        const double length = std::clamp(0.2 * d.data->feedBounds.diagonal(), 2.0, 50.0);
        axes = toolAxisLines(*d.data, kMaxToolAxisLines, length);
    }
    d.toolAxisLines = axes ? static_cast<size_t>(axes->GetNumberOfLines()) : 0;
    if (axes) {
        d.toolAxesMapper->SetInputData(axes);
        d.toolAxesActor->VisibilityOn();
    } else {
        d.toolAxesMapper->RemoveAllInputs();
        d.toolAxesActor->VisibilityOff();
    }
    if (d.data && d.data->pointCount() > 0) {
        const size_t last = d.data->pointCount() - 1;
        setToolPosition(d.data->point(last), d.data->toolAxisAt(last));
    }
    d.updateAxesScale();
}

void Scene::setStockMesh(std::shared_ptr<const Mesh> mesh) {
    Impl& d = *m_impl;
    d.stock = std::move(mesh);
    if (!d.stock || d.stock->triangleCount() == 0) {
        d.stockActor->VisibilityOff();
        d.stockMapper->RemoveAllInputs();
        return;
    }
    // Shade by depth below the blank's top as well as by light, so floors seen face-on (top
    // view) still stand apart from the top face.
    vtkSmartPointer<vtkPolyData> polyData = meshData(*d.stock);
    vtkNew<vtkFloatArray> depth;
    depth->SetName("height");
    depth->SetNumberOfTuples(static_cast<vtkIdType>(d.stock->vertexCount()));
    // A turned part (lathe about Z, a cylinder lying on a rotary table about X or Y) is shaded by
    // the distance from its axis.
    const int about = d.options.lathe ? 2 : d.stock->shadeAboutAxis;
    for (size_t i = 0; i < d.stock->vertexCount(); ++i) {
        const float* p = &d.stock->points[3 * i];
        const float value = about >= 0 ? std::hypot(p[(about + 1) % 3], p[(about + 2) % 3]) : p[2];
        depth->SetValue(static_cast<vtkIdType>(i), value);
    }
    polyData->GetPointData()->SetScalars(depth);
    // Colour range: mill from the deepest upward-facing surface (the lowest floor) to the top,
    // so cuts stand out whatever the blank's height; a turned part from half the radius outwards.
    double low = 0.0;
    double high = 1.0;
    if (d.options.lathe) {
        high = std::max(std::fabs(d.stock->bounds.min.x()), d.stock->bounds.max.x());
        low = 0.5 * high;
    } else if (about >= 0) {
        const Bounds3& b = d.stock->bounds;
        high = 0.0;
        for (const int axis : {(about + 1) % 3, (about + 2) % 3})
            high = std::max({high, std::fabs(b.min[axis]), std::fabs(b.max[axis])});
        low = 0.5 * high;
    } else {
        high = d.stock->bounds.max.z();
        low = high;
        for (size_t i = 0; i < d.stock->vertexCount(); ++i) {
            if (d.stock->normals.size() == d.stock->points.size() &&
                d.stock->normals[3 * i + 2] > 0.5f) {
                low = std::min(low, double{d.stock->points[3 * i + 2]});
            }
        }
    }
    if (!(high > low)) low = high - 1.0;
    d.stockColours->SetTableRange(low, high);
    d.stockMapper->SetInputData(polyData);
    d.stockMapper->SetScalarRange(low, high);
    // The lathe's half section reads best in one colour: the cut face is its profile.
    d.stockMapper->SetScalarVisibility(d.options.lathe ? 0 : 1);
    d.stockActor->VisibilityOn();
    d.updateAxesScale();
}

void Scene::setTool(const ToolGlyph& tool) {
    Impl& d = *m_impl;
    d.tool = tool;
    Mesh mesh = toolMesh(tool);
    if (mesh.triangleCount() == 0) {
        d.toolActor->VisibilityOff();
        return;
    }
    d.toolMapper->SetInputData(meshData(mesh));
    d.toolActor->VisibilityOn();
}

void Scene::setToolPosition(const Vec3& position, const Vec3& axis) {
    if (!position.allFinite()) return;
    vtkActor* tool = m_impl->toolActor;
    tool->SetPosition(position.x(), position.y(), position.z());
    const double norm = axis.norm();
    if (!axis.allFinite() || norm < 1e-12) return;
    // The turn from Z onto the axis, about the tip (the glyph's origin).
    const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis / norm);
    const Eigen::AngleAxisd angleAxis(turn);
    tool->SetOrientation(0.0, 0.0, 0.0);
    if (angleAxis.angle() > 1e-12) {
        tool->RotateWXYZ(angleAxis.angle() * 180.0 / std::numbers::pi, angleAxis.axis().x(),
                         angleAxis.axis().y(), angleAxis.axis().z());
    }
}

void Scene::setExecutedPath(size_t fromPoint, size_t toPoint, const Vec3& tip) {
    Impl& d = *m_impl;
    if (!d.data) return d.executed.clear();
    d.executed.show(*d.data, fromPoint, toPoint, tip);
}

void Scene::clearExecutedPath() {
    m_impl->executed.clear();
}

void Scene::Impl::updateAxesScale() {
    if (!options.showAxes) return;
    const Bounds3 bounds = contentBounds();
    const double size = bounds.empty ? 10.0 : std::max(1.0, 0.12 * bounds.diagonal());
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(3);
    points->InsertNextPoint(0.0, 0.0, 0.0);
    size_t label = 0;
    for (int a = 0; a < 3; ++a) {
        if (options.lathe && a == 1) continue;
        double tip[3] = {0.0, 0.0, 0.0};
        tip[a] = size;
        const vtkIdType ids[2] = {0, points->InsertNextPoint(tip)};
        lines->InsertNextCell(2, ids);
        const unsigned char rgb[3] = {static_cast<unsigned char>(a == 0 ? 235 : 60),
                                      static_cast<unsigned char>(a == 1 ? 220 : 60),
                                      static_cast<unsigned char>(a == 2 ? 255 : 60)};
        colours->InsertNextTypedTuple(rgb);
        if (label < axisLabels.size()) {
            axisLabels[label++]->GetPositionCoordinate()->SetValue(tip[0] * 1.08, tip[1] * 1.08,
                                                                   tip[2] * 1.08);
        }
    }
    vtkNew<vtkPolyData> axes;
    axes->SetPoints(points);
    axes->SetLines(lines);
    axes->GetCellData()->SetScalars(colours);
    axesMapper->SetInputData(axes);
}

Bounds3 Scene::Impl::contentBounds() const {
    // The blank and the cutting moves fill the picture, as on the control: the rapids from the
    // home position (Z+400 over a 20 mm part) would shrink the part to a few pixels.
    Bounds3 bounds;
    if (stock) bounds.add(stock->bounds);
    if (data) bounds.add(data->feedBounds);
    if (bounds.empty && geometry) bounds.add(geometry->bounds);
    return bounds;
}

Bounds3 Scene::contentBounds() const {
    return m_impl->contentBounds();
}

View Scene::view() const {
    return m_impl->view;
}

void Scene::setView(View view) {
    m_impl->view = view;
    fit();
}

void Scene::setViewportSize(int width, int height) {
    m_impl->viewportWidth = std::max(1, width);
    m_impl->viewportHeight = std::max(1, height);
}

void Scene::setInteractive(bool interactive) {
    m_impl->interactive = interactive;
}

void Scene::fit() {
    Impl& d = *m_impl;
    vtkCamera* camera = d.renderer->GetActiveCamera();
    Vec3 direction(0, 0, -1);  // from the camera towards the scene
    Vec3 up(0, 1, 0);
    switch (d.view) {
        case View::Iso:
            direction = Vec3(-1.0, 1.0, -0.8).normalized();
            up = Vec3(0, 0, 1);
            if (d.options.lathe) {
                direction = Vec3(-0.6, -1.0, -0.5).normalized();
                up = Vec3(1, 0, 0);
            }
            break;
        case View::Top:
            direction = Vec3(0, 0, -1);
            up = Vec3(0, 1, 0);
            break;
        case View::Front:
            direction = Vec3(0, 1, 0);
            up = Vec3(0, 0, 1);
            break;
        case View::Side:
            direction = Vec3(-1, 0, 0);
            up = Vec3(0, 0, 1);
            break;
        case View::LatheSection:
            direction = Vec3(0, -1, 0);  // from +Y: Z to the right, X up
            up = Vec3(1, 0, 0);
            break;
    }
    Bounds3 bounds = d.contentBounds();
    if (bounds.empty) {
        bounds.add(Vec3(-10, -10, -10));
        bounds.add(Vec3(10, 10, 10));
    }
    const Vec3 centre = bounds.centre();
    const Vec3 right = direction.cross(up).normalized();
    const Vec3 trueUp = right.cross(direction).normalized();
    double hExtent = 0.0;
    double vExtent = 0.0;
    for (int k = 0; k < 8; ++k) {
        const Vec3 corner((k & 1) != 0 ? bounds.max.x() : bounds.min.x(),
                          (k & 2) != 0 ? bounds.max.y() : bounds.min.y(),
                          (k & 4) != 0 ? bounds.max.z() : bounds.min.z());
        hExtent = std::max(hExtent, std::fabs((corner - centre).dot(right)));
        vExtent = std::max(vExtent, std::fabs((corner - centre).dot(trueUp)));
    }
    int width = d.viewportWidth;
    int height = d.viewportHeight;
    if (d.renderer->GetRenderWindow() != nullptr) {
        const int* size = d.renderer->GetSize();
        if (size != nullptr && size[0] > 1 && size[1] > 1) {
            width = size[0];
            height = size[1];
        }
    }
    const double aspect = static_cast<double>(std::max(width, 1)) / std::max(height, 1);
    double scale = std::max(vExtent, hExtent / aspect) * 1.08;
    if (!(scale > 1e-6) || !std::isfinite(scale)) scale = 1.0;
    const double distance = std::max(bounds.diagonal(), 1.0) * 2.0;
    const Vec3 position = centre - direction * distance;
    camera->SetFocalPoint(centre.x(), centre.y(), centre.z());
    camera->SetPosition(position.x(), position.y(), position.z());
    camera->SetViewUp(trueUp.x(), trueUp.y(), trueUp.z());
    camera->ParallelProjectionOn();
    camera->SetParallelScale(scale);
    d.renderer->ResetCameraClippingRange();
    // Clipping range from the content alone, so huge limit boxes do not cost depth precision.
    const double margin = std::max(bounds.diagonal(), 1.0);
    camera->SetClippingRange(std::max(1e-3, distance - 2.0 * margin), distance + 2.0 * margin);
}

void Scene::zoom(double factor) {
    if (!(factor > 0.0) || !std::isfinite(factor)) return;
    vtkCamera* camera = m_impl->renderer->GetActiveCamera();
    camera->SetParallelScale(camera->GetParallelScale() / factor);
    if (camera->GetParallelProjection() == 0) camera->Zoom(factor);
}

void Scene::rotate(double azimuthDeg, double elevationDeg) {
    vtkCamera* camera = m_impl->renderer->GetActiveCamera();
    if (std::isfinite(azimuthDeg)) camera->Azimuth(azimuthDeg);
    if (std::isfinite(elevationDeg)) camera->Elevation(elevationDeg);
    camera->OrthogonalizeViewUp();
    m_impl->renderer->ResetCameraClippingRange();
}

std::optional<PickHit> Scene::pick(double x, double y, double tolerancePx) const {
    const Impl& d = *m_impl;
    if (!d.data || d.data->pointCount() < 2) return std::nullopt;
    int width = d.viewportWidth;
    int height = d.viewportHeight;
    if (d.renderer->GetRenderWindow() != nullptr) {
        const int* size = d.renderer->GetSize();
        if (size != nullptr && size[0] > 1 && size[1] > 1) {
            width = size[0];
            height = size[1];
        }
    }
    const double aspect = static_cast<double>(width) / std::max(height, 1);
    vtkMatrix4x4* m =
        d.renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
    double mat[16];
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c)
            mat[4 * r + c] = m->GetElement(r, c);
    }
    auto project = [&](const Vec3& p, double& sx, double& sy, double& depth) {
        const double X = mat[0] * p.x() + mat[1] * p.y() + mat[2] * p.z() + mat[3];
        const double Y = mat[4] * p.x() + mat[5] * p.y() + mat[6] * p.z() + mat[7];
        const double Z = mat[8] * p.x() + mat[9] * p.y() + mat[10] * p.z() + mat[11];
        double W = mat[12] * p.x() + mat[13] * p.y() + mat[14] * p.z() + mat[15];
        if (std::fabs(W) < 1e-300) W = 1e-300;
        sx = (X / W + 1.0) * 0.5 * width;
        sy = (1.0 - (Y / W + 1.0) * 0.5) * height;
        depth = Z / W;
    };
    const ToolpathData& data = *d.data;
    double best = tolerancePx;
    double bestDepth = std::numeric_limits<double>::infinity();
    size_t bestSegment = 0;
    Vec3 bestPoint(0.0, 0.0, 0.0);
    const size_t chunkSize = 4096;
    for (size_t first = 1; first < data.pointCount(); first += chunkSize) {
        const size_t last = std::min(data.pointCount() - 1, first + chunkSize - 1);
        // Reject a run of segments when its projected box misses the pick point.
        Bounds3 box;
        for (size_t i = first - 1; i <= last; ++i)
            box.add(data.point(i));
        double x0 = std::numeric_limits<double>::infinity();
        double x1 = -x0;
        double y0 = x0;
        double y1 = -x0;
        for (int k = 0; k < 8; ++k) {
            const Vec3 corner((k & 1) != 0 ? box.max.x() : box.min.x(),
                              (k & 2) != 0 ? box.max.y() : box.min.y(),
                              (k & 4) != 0 ? box.max.z() : box.min.z());
            double sx = 0.0;
            double sy = 0.0;
            double depth = 0.0;
            project(corner, sx, sy, depth);
            x0 = std::min(x0, sx);
            x1 = std::max(x1, sx);
            y0 = std::min(y0, sy);
            y1 = std::max(y1, sy);
        }
        if (x < x0 - best || x > x1 + best || y < y0 - best || y > y1 + best) continue;
        double ax = 0.0;
        double ay = 0.0;
        double az = 0.0;
        project(data.point(first - 1), ax, ay, az);
        for (size_t s = first; s <= last; ++s) {
            double bx = 0.0;
            double by = 0.0;
            double bz = 0.0;
            project(data.point(s), bx, by, bz);
            const double dx = bx - ax;
            const double dy = by - ay;
            const double len2 = dx * dx + dy * dy;
            double t = len2 > 0.0 ? ((x - ax) * dx + (y - ay) * dy) / len2 : 0.0;
            t = std::clamp(t, 0.0, 1.0);
            const double dist = std::hypot(x - ax - t * dx, y - ay - t * dy);
            const double depth = az + t * (bz - az);
            if (dist < best - 1e-9 || (dist <= best + 1e-9 && depth < bestDepth)) {
                best = std::min(best, dist);
                bestDepth = depth;
                bestSegment = s;
                bestPoint = data.point(s - 1) + t * (data.point(s) - data.point(s - 1));
            }
            ax = bx;
            ay = by;
            az = bz;
        }
    }
    if (bestSegment == 0) return std::nullopt;
    const auto move = data.moveOfSegment(bestSegment);
    if (!move) return std::nullopt;
    PickHit hit;
    hit.move = *move;
    hit.location = data.locations[*move];
    hit.kind = data.kinds[*move];
    hit.point = bestPoint;
    hit.distancePx = best;
    return hit;
}

size_t Scene::highlightBlock(uint32_t fileId, uint32_t line) {
    const Impl& d = *m_impl;
    std::vector<uint32_t> moves;
    if (d.data) {
        for (size_t m = 0; m < d.data->moveCount(); ++m) {
            const SourceLocation& loc = d.data->locations[m];
            if (loc.fileId == fileId && loc.line == line) moves.push_back(static_cast<uint32_t>(m));
        }
    }
    return highlightMoves(moves);
}

size_t Scene::highlightMoves(const std::vector<uint32_t>& moves) {
    Impl& d = *m_impl;
    d.highlighted = 0;
    if (!d.data || moves.empty()) {
        d.highlightActor->VisibilityOff();
        return 0;
    }
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    std::vector<vtkIdType> ids;
    for (uint32_t m : moves) {
        auto [begin, end] = d.data->pointsOfMove(m);
        if (end <= begin || begin == 0) continue;
        ids.clear();
        for (size_t i = begin - 1; i < end; ++i) {
            const Vec3 p = d.data->point(i);
            ids.push_back(points->InsertNextPoint(p.x(), p.y(), p.z()));
        }
        lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
        d.highlighted += end - begin;
    }
    if (d.highlighted == 0) {
        d.highlightActor->VisibilityOff();
        return 0;
    }
    vtkNew<vtkPolyData> polyData;
    polyData->SetPoints(points);
    polyData->SetLines(lines);
    d.highlightMapper->SetInputData(polyData);
    d.highlightActor->VisibilityOn();
    return d.highlighted;
}

void Scene::clearHighlight() {
    m_impl->highlighted = 0;
    m_impl->highlightActor->VisibilityOff();
    m_impl->highlightMapper->RemoveAllInputs();
}

SceneStats Scene::stats() const {
    const Impl& d = *m_impl;
    SceneStats stats;
    stats.chunks = d.chunks.size();
    if (d.geometry) stats.segmentsFull = d.geometry->segmentCount(0);
    for (size_t c = 0; c < d.chunks.size(); ++c) {
        stats.chunkLevels.push_back(d.chunks[c].level);
        stats.segmentsSelected +=
            d.geometry->chunks[c].levels[static_cast<size_t>(d.chunks[c].level)].segmentCount();
    }
    stats.highlightedSegments = d.highlighted;
    stats.executedSegments = d.executed.segments();
    stats.stockTriangles = d.stock ? d.stock->triangleCount() : 0;
    stats.toolAxisLines = d.toolAxisLines;
    return stats;
}

}  // namespace kerf::graphics
