#pragma once

// The VTK side of the facade, for ui/viewport only (the one UI folder that may include VTK).
class vtkRenderer;

namespace kerf::graphics {

class Scene;
// The renderer holding the scene's actors, to add to a render window (one at a time).
vtkRenderer* vtkRendererOf(Scene& scene);

}  // namespace kerf::graphics
