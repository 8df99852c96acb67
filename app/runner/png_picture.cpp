#include "app/runner/png_picture.h"

#include <functional>

#include "app/runner/session.h"
#include "app/runner/stock_output.h"
#include "core/canon/tee_sink.h"
#include "graphics/headless/virtual_display.h"
#include "graphics/scene/machine_scene.h"
#include "graphics/scene/scene.h"
#include "graphics/stock/machine_stock_options.h"
#include "graphics/stock/stock_simulation.h"
#include "graphics/toolpath/toolpath_data.h"
#include "graphics/toolpath/toolpath_lod.h"

namespace kerf::app {

namespace {

Diagnostic pictureError(const std::string& file, std::string message) {
    return Diagnostic::make(Severity::Error, "picture", file, 0, 0, std::move(message));
}

class PngPicture final : public PictureOutput {
public:
    PngPicture(const RunOptions& options, const Session& session)
        : m_file(options.png->string()),
          m_millCutter(graphics::millCutterFromToolTable(session.program.tools.get())) {
        const graphics::SceneOptions machineScene = graphics::sceneOptionsFor(session.machine);
        m_lathe = machineScene.lathe;
        m_limits = machineScene.limits;
        // A machine with rotary tables: the path on the part the tables turn.
        graphics::ToolpathOptions toolpathOptions;
        toolpathOptions.workpieceFrame =
            machine::WorkpieceFrame::of(session.machine, session.workOffset);
        m_toolpath = std::make_unique<graphics::ToolpathCollector>(std::move(toolpathOptions));
        m_view = m_lathe ? graphics::View::LatheSection : graphics::View::Iso;
        if (options.view) {
            if (auto view = graphics::viewFromName(*options.view)) m_view = *view;
        }
        if (options.size) {
            if (auto size = parsePictureSize(*options.size)) {
                m_width = size->first;
                m_height = size->second;
            }
        }
    }

    canon::Sink& sink() override { return *m_toolpath; }
    void setStart(const Pose& start) override { m_toolpath->setStart(start); }

    void finish(bool programRan, const StockOutput& stock, DiagnosticList& problems) override {
        if (!programRan) {
            problems.push_back(
                pictureError(m_file, KERF_TR_NOOP("no picture: the program did not run")));
            return;
        }
        auto display = graphics::VirtualDisplay::ensure();
        if (!display) {
            Diagnostic error = display.error();
            error.file = m_file;
            problems.push_back(std::move(error));
            return;
        }
        if (auto error = graphics::checkDisplay()) {
            error->file = m_file;
            problems.push_back(std::move(*error));
            return;
        }
        graphics::SceneOptions sceneOptions;
        sceneOptions.lathe = m_lathe;
        sceneOptions.limits = m_limits;
        graphics::Scene scene(sceneOptions);
        auto data = std::make_shared<graphics::ToolpathData>(m_toolpath->take());
        auto geometry =
            std::make_shared<graphics::ToolpathGeometry>(graphics::buildToolpathGeometry(*data));
        if (!m_lathe && !data->tools.empty()) {
            graphics::ToolGlyph glyph;
            glyph.shape = m_millCutter(data->tools.back().tool);
            glyph.axis = data->tools.back().tool.toolAxis;
            scene.setTool(glyph);
        }
        scene.setToolpath(data, geometry);
        if (const graphics::StockSimulation* simulation = stock.simulation();
            simulation != nullptr && simulation->hasStock()) {
            scene.setStockMesh(std::make_shared<graphics::Mesh>(simulation->mesh()));
        }
        graphics::OffscreenRenderer renderer(m_width, m_height);
        scene.setViewportSize(m_width, m_height);
        scene.setView(m_view);
        if (auto error = renderer.renderToPng(scene, m_file)) {
            problems.push_back(std::move(*error));
            return;
        }
        m_written = true;
    }

    void addToReport(nlohmann::json& report) const override {
        report["picture"] = {{"file", m_file},
                             {"written", m_written},
                             {"view", graphics::viewName(m_view)},
                             {"width", m_width},
                             {"height", m_height}};
    }

private:
    std::string m_file;
    std::function<graphics::MillCutter(const canon::ToolChange&)> m_millCutter;
    bool m_lathe = false;
    std::optional<graphics::Bounds3> m_limits;
    std::unique_ptr<graphics::ToolpathCollector> m_toolpath;
    graphics::View m_view = graphics::View::Iso;
    int m_width = 1280;
    int m_height = 800;
    bool m_written = false;
};

}  // namespace

std::unique_ptr<PictureOutput> makePngPicture(const RunOptions& options, const Session& session) {
    return std::make_unique<PngPicture>(options, session);
}

}  // namespace kerf::app
