#include "app/runner/picture_output.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <vector>

#include "app/runner/session.h"
#include "core/canon/tee_sink.h"
#include "graphics/headless/virtual_display.h"
#include "graphics/scene/machine_scene.h"
#include "graphics/scene/scene.h"
#include "graphics/stock/stock_simulation.h"
#include "graphics/toolpath/toolpath_data.h"
#include "graphics/toolpath/toolpath_lod.h"

namespace kerf::app {

namespace {

Diagnostic pictureProblem(Severity severity, const std::string& file, std::string message,
                          std::string arg = {}) {
    if (arg.empty()) return Diagnostic::make(severity, "picture", file, 0, 0, std::move(message));
    return Diagnostic::make(severity, "picture", file, 0, 0, std::move(message), std::move(arg));
}

double rounded(double value) {
    const double r = std::round(value * 1000.0) / 1000.0;
    return r == 0.0 ? 0.0 : r;
}

}  // namespace

std::optional<std::pair<int, int>> parsePictureSize(const std::string& text) {
    int width = 0;
    int height = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &tail) != 2) return std::nullopt;
    if (width < 16 || height < 16 || width > 8192 || height > 8192) return std::nullopt;
    return std::make_pair(width, height);
}

struct PictureOutput::State {
    RunOptions options;
    bool lathe = false;
    std::optional<graphics::Bounds3> limits;
    canon::TeeSink tee;
    std::unique_ptr<graphics::ToolpathCollector> toolpath;
    std::unique_ptr<graphics::StockSimulation> stock;
    std::function<graphics::MillCutter(const canon::ToolChange&)> millCutter;
    bool pictureWritten = false;
    graphics::View view = graphics::View::Iso;
    int width = 1280;
    int height = 800;
};

PictureOutput::PictureOutput(const RunOptions& options, const Session& session)
    : m_state(std::make_unique<State>()) {
    State& s = *m_state;
    s.options = options;
    if (!options.png && !options.stock) return;
    const graphics::SceneOptions machineScene = graphics::sceneOptionsFor(session.machine);
    s.lathe = machineScene.lathe;
    s.limits = machineScene.limits;
    // A machine with rotary tables: the path and the stock on the part the tables turn.
    const std::optional<machine::WorkpieceFrame> frame =
        machine::WorkpieceFrame::of(session.machine, session.workOffset);
    if (options.png) {
        graphics::ToolpathOptions toolpathOptions;
        toolpathOptions.workpieceFrame = frame;
        s.toolpath = std::make_unique<graphics::ToolpathCollector>(std::move(toolpathOptions));
        s.tee.add(*s.toolpath);
    }
    // Point angles (T-ANGLE) by tool number, copied: the canonical tool change carries L, R, R2.
    std::map<int, double> pointAngles;
    if (session.program.tools) {
        for (const tables::ToolData& row : session.program.tools->tools()) {
            if (row.index == 0) pointAngles[row.number] = row.pointAngle;
        }
    }
    s.millCutter = [pointAngles](const canon::ToolChange& tool) {
        const auto it = pointAngles.find(tool.number);
        const double pointAngle = it != pointAngles.end() ? it->second : 0.0;
        return graphics::MillCutter::fromGeometry(tool.geometry.radiusMm, tool.geometry.radius2Mm,
                                                  pointAngle);
    };
    if (options.stock) {
        graphics::StockOptions stockOptions;
        stockOptions.workpieceFrame = frame;
        stockOptions.machine =
            s.lathe ? graphics::StockMachine::Lathe : graphics::StockMachine::Mill;
        stockOptions.deriveStockFromPath = true;
        const machine::BarConfig& bar = session.machine.bar;
        if (s.lathe && bar.diameterMm > 0.0) {
            graphics::LatheBar blank;
            blank.radiusMm = bar.diameterMm / 2.0;
            blank.innerRadiusMm = bar.boreDiameterMm / 2.0;
            blank.zMax = bar.faceZMm;
            blank.zMin = bar.faceZMm - bar.lengthMm;
            stockOptions.bar = blank;
        }
        stockOptions.millCutter = s.millCutter;
        s.stock = std::make_unique<graphics::StockSimulation>(std::move(stockOptions));
        s.tee.add(*s.stock);
    }
    s.view = s.lathe ? graphics::View::LatheSection : graphics::View::Iso;
    if (options.view) {
        if (auto view = graphics::viewFromName(*options.view)) s.view = *view;
    }
    if (options.size) {
        if (auto size = parsePictureSize(*options.size)) {
            s.width = size->first;
            s.height = size->second;
        }
    }
    m_sink = &s.tee;
}

PictureOutput::~PictureOutput() = default;

void PictureOutput::setStart(const Pose& start) {
    if (m_state->toolpath) m_state->toolpath->setStart(start);
    if (m_state->stock) m_state->stock->setStart(start);
}

void PictureOutput::finish(bool programRan, DiagnosticList& problems) {
    State& s = *m_state;
    if (!active()) return;
    if (s.stock) {
        s.stock->finish();
        for (const std::string& note : s.stock->notes()) {
            problems.push_back(
                pictureProblem(Severity::Warning, s.options.program.string(), "{1}", note));
        }
    }
    if (!s.options.png) return;
    const std::string file = s.options.png->string();
    if (!programRan) {
        problems.push_back(pictureProblem(Severity::Error, file,
                                          KERF_TR_NOOP("no picture: the program did not run")));
        return;
    }
    auto display = graphics::VirtualDisplay::ensure();
    if (!display) {
        Diagnostic error = display.error();
        error.file = file;
        problems.push_back(std::move(error));
        return;
    }
    if (auto error = graphics::checkDisplay()) {
        error->file = file;
        problems.push_back(std::move(*error));
        return;
    }
    graphics::SceneOptions sceneOptions;
    sceneOptions.lathe = s.lathe;
    sceneOptions.limits = s.limits;
    graphics::Scene scene(sceneOptions);
    auto data = std::make_shared<graphics::ToolpathData>(s.toolpath->take());
    auto geometry =
        std::make_shared<graphics::ToolpathGeometry>(graphics::buildToolpathGeometry(*data));
    if (!s.lathe && !data->tools.empty()) {
        graphics::ToolGlyph glyph;
        glyph.shape = s.millCutter(data->tools.back().tool);
        glyph.axis = data->tools.back().tool.toolAxis;
        scene.setTool(glyph);
    }
    scene.setToolpath(data, geometry);
    if (s.stock && s.stock->hasStock()) {
        scene.setStockMesh(std::make_shared<graphics::Mesh>(s.stock->mesh()));
    }
    {
        graphics::OffscreenRenderer renderer(s.width, s.height);
        scene.setViewportSize(s.width, s.height);
        scene.setView(s.view);
        if (auto error = renderer.renderToPng(scene, *s.options.png)) {
            problems.push_back(std::move(*error));
            return;
        }
    }
    s.pictureWritten = true;
}

void PictureOutput::addToReport(nlohmann::json& report) const {
    const State& s = *m_state;
    if (s.stock) {
        nlohmann::json notes = nlohmann::json::array();
        for (const std::string& note : s.stock->notes())
            notes.push_back(note);
        report["stock"] = {{"removed_volume_mm3", rounded(s.stock->removedVolumeMm3())},
                           {"initial_volume_mm3", rounded(s.stock->initialVolumeMm3())},
                           {"resolution_mm", rounded(s.stock->resolutionMm())},
                           {"source", s.stock->stockSource()},
                           {"moves", s.stock->movesSimulated()},
                           {"rapid_cuts", s.stock->rapidCuts()},
                           {"notes", notes}};
    }
    if (s.options.png) {
        report["picture"] = {{"file", s.options.png->string()},
                             {"written", s.pictureWritten},
                             {"view", graphics::viewName(s.view)},
                             {"width", s.width},
                             {"height", s.height}};
    }
}

}  // namespace kerf::app
