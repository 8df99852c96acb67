#pragma once

// Private: the VTK objects behind Scene (scene.cpp, offscreen_renderer.cpp).

#include <memory>
#include <optional>
#include <vector>

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include "graphics/scene/detail/executed_path.h"
#include "graphics/scene/scene.h"

namespace kerf::graphics {

vtkSmartPointer<vtkPolyData> meshData(const Mesh& mesh);

struct Scene::Impl {
    explicit Impl(SceneOptions sceneOptions);
    ~Impl();
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;

    void updateLevels();
    void updateAxesScale();
    Bounds3 contentBounds() const;

    struct ChunkActor {
        std::vector<vtkSmartPointer<vtkPolyData>> levels;
        vtkSmartPointer<vtkPolyDataMapper> mapper;
        vtkSmartPointer<vtkActor> actor;
        int level = 0;
    };

    SceneOptions options;
    View view = View::Iso;
    int viewportWidth = 1280;
    int viewportHeight = 800;
    bool interactive = false;
    std::shared_ptr<const ToolpathData> data;
    std::shared_ptr<const ToolpathGeometry> geometry;
    std::shared_ptr<const Mesh> stock;
    std::optional<ToolGlyph> tool;
    size_t highlighted = 0;

    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkLookupTable> lookupTable;
    vtkNew<vtkCallbackCommand> lodCallback;
    std::vector<ChunkActor> chunks;
    vtkNew<vtkLookupTable> stockColours;
    vtkNew<vtkPolyDataMapper> stockMapper;
    vtkNew<vtkActor> stockActor;
    vtkNew<vtkPolyDataMapper> toolMapper;
    vtkNew<vtkActor> toolActor;
    vtkNew<vtkPolyDataMapper> toolAxesMapper;
    vtkNew<vtkActor> toolAxesActor;  // the tool's direction along tilted moves
    size_t toolAxisLines = 0;
    vtkNew<vtkPolyDataMapper> highlightMapper;
    vtkNew<vtkActor> highlightActor;
    ExecutedPath executed;
    vtkNew<vtkActor> limitsActor;
    vtkNew<vtkActor> axesActor;  // three coloured lines from the origin
    vtkNew<vtkPolyDataMapper> axesMapper;
    std::vector<vtkSmartPointer<vtkTextActor>> axisLabels;
};

}  // namespace kerf::graphics
