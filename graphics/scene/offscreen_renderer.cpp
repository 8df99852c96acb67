#include <chrono>
#include <cstdlib>
#include <cstring>

#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include "core/base/translate.h"
#include "graphics/scene/detail/scene_impl.h"
#include "graphics/scene/detail/x_display.h"
#include "graphics/scene/scene.h"

namespace kerf::graphics {

namespace {

Diagnostic renderError(const std::string& file, std::string message) {
    return Diagnostic::make(Severity::Error, "render", file, 0, 0, std::move(message));
}

}  // namespace

MaybeError checkDisplay() {
    if (detail::canOpenXDisplay()) return std::nullopt;
    const char* name = std::getenv("DISPLAY");
    const bool set = name != nullptr && *name != '\0';
    return renderError("", set ? KERF_TR_NOOP("cannot open the X display (DISPLAY is set)")
                               : KERF_TR_NOOP("no X display: DISPLAY is not set"));
}

struct OffscreenRenderer::Impl {
    vtkNew<vtkRenderWindow> window;
    vtkRenderer* attached = nullptr;

    void attach(Scene& scene, int width, int height) {
        vtkRenderer* renderer = scene.impl().renderer;
        if (attached != renderer) {
            if (attached != nullptr) window->RemoveRenderer(attached);
            window->AddRenderer(renderer);
            attached = renderer;
        }
        scene.setViewportSize(width, height);
    }
    void detach() {
        if (attached != nullptr) window->RemoveRenderer(attached);
        attached = nullptr;
    }
};

OffscreenRenderer::OffscreenRenderer(int width, int height)
    : m_impl(std::make_unique<Impl>()),
      m_width(std::max(16, width)),
      m_height(std::max(16, height)) {
    m_impl->window->SetOffScreenRendering(1);
    m_impl->window->SetMultiSamples(0);
    m_impl->window->SetSize(m_width, m_height);
}

OffscreenRenderer::~OffscreenRenderer() {
    m_impl->detach();
    m_impl->window->Finalize();
}

std::vector<uint8_t> OffscreenRenderer::renderRgb(Scene& scene) {
    m_impl->attach(scene, m_width, m_height);
    m_impl->window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(m_impl->window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkImageData* image = grab->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    std::vector<uint8_t> rgb(static_cast<size_t>(m_width) * static_cast<size_t>(m_height) * 3, 0);
    auto* scalars = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
    if (scalars == nullptr || dims[0] != m_width || dims[1] != m_height) return rgb;
    const uint8_t* source = scalars->GetPointer(0);
    const size_t rowBytes = static_cast<size_t>(m_width) * 3;
    // VTK's first row is the bottom one.
    for (int y = 0; y < m_height; ++y) {
        std::memcpy(&rgb[static_cast<size_t>(m_height - 1 - y) * rowBytes],
                    source + static_cast<size_t>(y) * rowBytes, rowBytes);
    }
    return rgb;
}

MaybeError OffscreenRenderer::renderToPng(Scene& scene, const std::filesystem::path& file) {
    const std::vector<uint8_t> rgb = renderRgb(scene);
    return writePng(file, rgb, m_width, m_height);
}

double OffscreenRenderer::measureFps(Scene& scene, int frames, double degreesPerFrame) {
    m_impl->attach(scene, m_width, m_height);
    m_impl->window->Render();  // warm-up: buffers uploaded
    vtkCamera* camera = scene.impl().renderer->GetActiveCamera();
    const auto start = std::chrono::steady_clock::now();
    for (int f = 0; f < frames; ++f) {
        camera->Azimuth(degreesPerFrame);
        m_impl->window->Render();
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return seconds > 0.0 ? frames / seconds : 0.0;
}

MaybeError writePng(const std::filesystem::path& file, const std::vector<uint8_t>& rgb, int width,
                    int height) {
    if (width <= 0 || height <= 0 ||
        rgb.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 3) {
        return renderError(file.string(), KERF_TR_NOOP("picture has the wrong size"));
    }
    vtkNew<vtkImageData> image;
    image->SetDimensions(width, height, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* target = static_cast<uint8_t*>(image->GetScalarPointer());
    const size_t rowBytes = static_cast<size_t>(width) * 3;
    for (int y = 0; y < height; ++y) {
        std::memcpy(target + static_cast<size_t>(height - 1 - y) * rowBytes,
                    &rgb[static_cast<size_t>(y) * rowBytes], rowBytes);
    }
    // Write next to the target, then rename, so a reader never sees half a file.
    std::filesystem::path temporary = file;
    temporary += ".part";
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(temporary.c_str());
    writer->SetInputData(image);
    writer->Write();
    std::error_code error;
    if (writer->GetErrorCode() != 0 || !std::filesystem::exists(temporary, error)) {
        std::filesystem::remove(temporary, error);
        return renderError(file.string(), KERF_TR_NOOP("cannot write the picture"));
    }
    std::filesystem::rename(temporary, file, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        return renderError(file.string(), KERF_TR_NOOP("cannot write the picture"));
    }
    return std::nullopt;
}

Expected<std::vector<uint8_t>> readPng(const std::filesystem::path& file, int& width, int& height) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error)) {
        return renderError(file.string(), KERF_TR_NOOP("no such picture"));
    }
    vtkNew<vtkPNGReader> reader;
    if (reader->CanReadFile(file.c_str()) == 0) {
        return renderError(file.string(), KERF_TR_NOOP("not a PNG file"));
    }
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    width = dims[0];
    height = dims[1];
    const int components = image->GetNumberOfScalarComponents();
    std::vector<uint8_t> rgb(static_cast<size_t>(width) * static_cast<size_t>(height) * 3, 0);
    const auto* source = static_cast<const uint8_t*>(image->GetScalarPointer());
    if (source == nullptr || components < 3) return rgb;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t from = (static_cast<size_t>(height - 1 - y) * static_cast<size_t>(width) +
                                 static_cast<size_t>(x)) *
                                static_cast<size_t>(components);
            const size_t to =
                (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
            rgb[to] = source[from];
            rgb[to + 1] = source[from + 1];
            rgb[to + 2] = source[from + 2];
        }
    }
    return rgb;
}

}  // namespace kerf::graphics
