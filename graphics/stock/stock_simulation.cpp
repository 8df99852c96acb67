#include "graphics/stock/stock_simulation.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "graphics/toolpath/arc_tessellation.h"

namespace kerf::graphics {

namespace {
// A cube mesh has up to six quads per cell where the height field has one: fewer cells a side.
constexpr int kMaxVoxelMeshSide = 200;
}  // namespace

StockSimulation::StockSimulation(StockOptions options) : m_options(std::move(options)) {
    if (!m_options.millCutter) {
        m_options.millCutter = [](const canon::ToolChange& tool) {
            return MillCutter::fromGeometry(tool.geometry.radiusMm, tool.geometry.radius2Mm);
        };
    }
    if (!m_options.latheInsert) {
        m_options.latheInsert = [](const canon::ToolChange& tool) {
            return LatheInsert::fromGeometry(tool.geometry);
        };
    }
    if (!(m_options.resolutionMm > 0.0) || !std::isfinite(m_options.resolutionMm)) {
        m_options.resolutionMm = 0.1;
    }
    if (m_options.machine == StockMachine::Lathe && m_options.bar) {
        createBar(*m_options.bar, "bar");
    }
}

StockSimulation::~StockSimulation() = default;

void StockSimulation::note(const std::string& text) {
    if (std::find(m_notes.begin(), m_notes.end(), text) == m_notes.end()) m_notes.push_back(text);
}

void StockSimulation::createStock(const canon::StockDefinition& definition,
                                  const std::string& source) {
    const double cell = m_options.resolutionMm;
    if (m_options.machine == StockMachine::Lathe) {
        if (const auto* cylinder = std::get_if<canon::StockCylinder>(&definition.shape)) {
            LatheBar bar;
            bar.radiusMm = cylinder->radiusMm;
            bar.innerRadiusMm = cylinder->innerRadiusMm;
            bar.zMax = cylinder->distanceMm;
            bar.zMin = cylinder->distanceMm - cylinder->lengthMm;
            createBar(bar, source);
        } else if (const auto* box = std::get_if<canon::StockBox>(&definition.shape)) {
            LatheBar bar;
            bar.radiusMm = std::max(std::fabs(box->min.x()), std::fabs(box->max.x()));
            bar.zMin = box->min.z();
            bar.zMax = box->max.z();
            createBar(bar, source);
        }
        return;
    }
    if (const auto* box = std::get_if<canon::StockBox>(&definition.shape)) {
        m_mill = std::make_unique<HeightFieldStock>(box->min, box->max, cell, m_options.maxCells);
    } else if (const auto* cylinder = std::get_if<canon::StockCylinder>(&definition.shape)) {
        const double top = cylinder->distanceMm;
        const double bottom = top - cylinder->lengthMm;
        if (cylinder->axis == Axis::Z) {
            m_mill = std::make_unique<HeightFieldStock>(
                HeightFieldStock::cylinder(0.0, 0.0, cylinder->radiusMm, cylinder->innerRadiusMm,
                                           bottom, top, cell, m_options.maxCells));
        } else if (cylinder->axis == Axis::X || cylinder->axis == Axis::Y) {
            // Lying on a rotary table (A about X, B about Y): no height field holds it.
            m_voxels = std::make_unique<VoxelStock>(VoxelStock::cylinder(
                axisIndex(cylinder->axis), cylinder->radiusMm, cylinder->innerRadiusMm, bottom, top,
                cell, m_options.maxVoxels));
            m_lyingCylinderAxis = axisIndex(cylinder->axis);
            m_initialVolumeMm3 = m_voxels->volumeMm3();
            m_voxelBaselineMm3 = m_initialVolumeMm3;
            m_removedBeforeVoxels = 0.0;
            m_source = source;
            note(std::string("stock: a cylinder lying along ") + axisLetter(cylinder->axis) +
                 ": simulated in voxels of " + std::to_string(m_voxels->cellMm()) + " mm");
        } else {
            note("stock: only cylinders along X, Y or Z are simulated on the mill");
            return;
        }
    }
    if (m_mill) {
        m_source = source;
        if (m_mill->cellMm() > cell * 1.0001) {
            note("stock: resolution coarsened to " + std::to_string(m_mill->cellMm()) +
                 " mm to stay within the cell budget");
        }
    }
}

void StockSimulation::createBar(const LatheBar& bar, const std::string& source) {
    m_lathe = std::make_unique<LatheStock>(bar, m_options.resolutionMm, m_options.maxCells);
    m_source = source;
    if (m_lathe->cellMm() > m_options.resolutionMm * 1.0001) {
        note("stock: resolution coarsened to " + std::to_string(m_lathe->cellMm()) +
             " mm to stay within the cell budget");
    }
}

void StockSimulation::createRevolved(const canon::StockRevolved& blank) {
    if (m_options.machine != StockMachine::Lathe) {
        note("stock: a turned blank (raw-stock profile) is simulated on a lathe only");
        return;
    }
    // The raw part replaces the bar as long as nothing has been cut from it: later profiles
    // describe material that earlier cuts already shaped.
    if (m_version != 0) {
        note("stock: a raw-stock profile after the first cut is not drawn as the blank");
        return;
    }
    std::vector<std::pair<double, double>> outline;
    for (const Vec3& p : blank.outline)
        outline.emplace_back(p.x(), p.z());
    const LatheBar* bar = m_lathe ? &m_lathe->bar() : (m_options.bar ? &*m_options.bar : nullptr);
    m_lathe = std::make_unique<LatheStock>(
        LatheStock::revolved(outline, {blank.materialSide.x(), blank.materialSide.z()}, bar,
                             m_options.resolutionMm, m_options.maxCells));
    m_source = "program";
    for (const Deferred& move : m_deferred)
        cutWithTool(move.from, move.to, move.axis, move.rapid, move.tool);
    m_deferred.clear();
}

void StockSimulation::switchToVoxels() {
    m_removedBeforeVoxels = m_mill->removedVolumeMm3();
    m_initialVolumeMm3 = m_mill->initialVolumeMm3();
    m_voxels =
        std::make_unique<VoxelStock>(VoxelStock::fromHeightField(*m_mill, m_options.maxVoxels));
    m_voxelBaselineMm3 = m_voxels->volumeMm3();
    m_mill.reset();
    note("stock: a tilted tool: simulated in voxels of " + std::to_string(m_voxels->cellMm()) +
         " mm");
}

void StockSimulation::cutWithTool(const Vec3& from, const Vec3& to, const Vec3& axis, bool rapid,
                                  size_t tool) {
    bool removed = false;
    if (m_mill || m_voxels) {
        if (!m_cutters[tool].cuts()) return;
        if (m_toolAxes[tool] != Axis::Z) {
            note("stock: only tool axis Z is simulated on the mill");
            return;
        }
        // The height field holds a tool along the workpiece's Z only.
        constexpr double kVertical = 1.0 - 1e-9;
        if (m_mill && axis.z() < kVertical) switchToVoxels();
        if (m_voxels) {
            removed = m_voxels->cut(from, to, axis, m_cutters[tool]);
        } else {
            removed = m_mill->cut(from, to, m_cutters[tool]);
        }
    } else if (m_lathe) {
        removed = m_lathe->cut(from.x(), from.z(), to.x(), to.z(), m_inserts[tool]);
    }
    if (removed) {
        ++m_version;
        if (rapid) ++m_rapidCuts;
    }
}

void StockSimulation::cutSegment(const Vec3& from, const Vec3& to, const Vec3& axis, bool rapid) {
    if (!from.allFinite() || !to.allFinite()) return;
    if (!rapid) {
        m_feedBounds.add(from);
        m_feedBounds.add(to);
    }
    if (!hasStock()) {
        if (!m_options.deriveStockFromPath) return;
        if (m_deferred.size() >= m_options.maxDeferredMoves) {
            m_deferOverflow = true;
            return;
        }
        m_deferred.push_back({from, to, axis, static_cast<uint32_t>(m_tool), rapid});
        return;
    }
    cutWithTool(from, to, axis, rapid, m_tool);
}

machine::ToolOnPart StockSimulation::onPart(const Pose& stream) const {
    if (m_options.workpieceFrame) return m_options.workpieceFrame->toPart(stream);
    return {stream.xyz(), Vec3::UnitZ()};
}

void StockSimulation::cutStreamLine(const Pose& from, const Pose& to, bool rapid) {
    if (!m_options.workpieceFrame) {
        cutSegment(from.xyz(), to.xyz(), Vec3::UnitZ(), rapid);
        return;
    }
    const machine::WorkpieceFrame& frame = *m_options.workpieceFrame;
    m_samples.clear();
    frame.sample(from, to, m_options.maxTableStepDeg, m_samples);
    machine::ToolOnPart last = frame.toPart(from);
    for (const machine::ToolOnPart& next : m_samples) {
        // Between two samples the tool turns by at most the step: cut with its mean direction.
        cutSegment(last.tip, next.tip, (last.axis + next.axis).normalized(), rapid);
        last = next;
    }
}

void StockSimulation::consume(const canon::Command& command) {
    const canon::CommandBody& body = command.body;
    auto line = [&](const Pose& target, bool rapid) {
        if (!finiteXyz(target)) return;
        ++m_moves;
        cutStreamLine(m_position, target, rapid);
        m_position = target;
    };
    if (const auto* rapid = std::get_if<canon::RapidMove>(&body)) {
        line(rapid->target, true);
    } else if (const auto* linear = std::get_if<canon::LinearMove>(&body)) {
        line(linear->target, false);
    } else if (const auto* synced = std::get_if<canon::SpindleSyncedMove>(&body)) {
        line(synced->target, false);
    } else if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) {
        line(probe->target, false);
    } else if (const auto* arc = std::get_if<canon::ArcMove>(&body)) {
        if (!finiteXyz(arc->target)) return;
        ++m_moves;
        m_scratch.clear();
        tessellateArc(m_position, *arc, std::max(1e-4, resolutionMm() * 0.25), 4096, m_scratch);
        // Arcs keep the tables still (docs/klartext.md): one turn maps every chord.
        Pose at = m_position;
        machine::ToolOnPart from = onPart(at);
        for (const Vec3& p : m_scratch) {
            at.setXyz(p);
            const machine::ToolOnPart to = onPart(at);
            cutSegment(from.tip, to.tip, to.axis, false);
            from = to;
        }
        m_position = arc->target;
    } else if (const auto* tool = std::get_if<canon::ToolChange>(&body)) {
        if (m_options.workpieceFrame)
            m_options.workpieceFrame->setToolLength(tool->geometry.lengthMm);
        m_cutters.push_back(m_options.millCutter(*tool));
        m_inserts.push_back(m_options.latheInsert(*tool));
        m_toolAxes.push_back(tool->toolAxis);
        m_tool = m_cutters.size() - 1;
        m_maxToolRadius = std::max(m_maxToolRadius, m_cutters.back().radiusMm);
    } else if (const auto* update = std::get_if<canon::ToolUpdate>(&body)) {
        if (m_options.workpieceFrame)
            m_options.workpieceFrame->setToolLength(update->geometry.lengthMm);
        canon::ToolChange changed;
        changed.geometry = update->geometry;
        changed.toolAxis = update->toolAxis;
        MillCutter cutter = m_options.millCutter(changed);
        if (m_cutters[m_tool].kind == CutterKind::Drill) {
            cutter.kind = CutterKind::Drill;
            cutter.pointAngleDeg = m_cutters[m_tool].pointAngleDeg;
        }
        if (m_cutters[m_tool].touchProbe) cutter = MillCutter::touchProbeStylus(cutter.radiusMm);
        m_cutters.push_back(cutter);
        m_inserts.push_back(m_options.latheInsert(changed));
        m_toolAxes.push_back(update->toolAxis);
        m_tool = m_cutters.size() - 1;
        m_maxToolRadius = std::max(m_maxToolRadius, cutter.radiusMm);
    } else if (const auto* stock = std::get_if<canon::StockDefinition>(&body)) {
        if (const auto* revolved = std::get_if<canon::StockRevolved>(&stock->shape)) {
            createRevolved(*revolved);
        } else if (!hasStock()) {
            createStock(*stock, "program");
        }
    }
}

void StockSimulation::finish() {
    if (!hasStock() && m_options.fallbackStock) createStock(*m_options.fallbackStock, "fallback");
    if (!hasStock() && m_options.deriveStockFromPath && !m_feedBounds.empty) {
        const Bounds3& f = m_feedBounds;
        if (m_options.machine == StockMachine::Lathe) {
            LatheBar bar;
            bar.radiusMm = std::max(std::fabs(f.min.x()), std::fabs(f.max.x()));
            bar.zMin = f.min.z();
            bar.zMax = std::max(0.0, f.max.z());
            createBar(bar, "derived");
        } else {
            canon::StockBox box;
            const double r = m_maxToolRadius;
            box.min = Vec3(f.min.x() - r, f.min.y() - r, f.min.z());
            box.max = Vec3(f.max.x() + r, f.max.y() + r, std::max(0.0, f.max.z()));
            if (box.max.z() - box.min.z() < 1e-6) box.min.z() -= 1.0;
            createStock(canon::StockDefinition{box}, "derived");
        }
        if (hasStock()) {
            note("stock: no blank in the program; derived from the feed path");
            for (const Deferred& move : m_deferred)
                cutWithTool(move.from, move.to, move.axis, move.rapid, move.tool);
        }
    }
    if (m_deferOverflow)
        note("stock: too many moves before a blank was known; some were not simulated");
    if (!hasStock()) note("stock: no blank defined (BLK FORM), nothing simulated");
    m_deferred.clear();
    m_deferred.shrink_to_fit();
}

double StockSimulation::removedVolumeMm3() const {
    if (m_mill) return m_mill->removedVolumeMm3();
    if (m_voxels) return m_removedBeforeVoxels + m_voxelBaselineMm3 - m_voxels->volumeMm3();
    if (m_lathe) return m_lathe->removedVolumeMm3();
    return 0.0;
}

double StockSimulation::initialVolumeMm3() const {
    if (m_mill) return m_mill->initialVolumeMm3();
    if (m_voxels) return m_initialVolumeMm3;
    if (m_lathe) return m_lathe->initialVolumeMm3();
    return 0.0;
}

double StockSimulation::resolutionMm() const {
    if (m_mill) return m_mill->cellMm();
    if (m_voxels) return m_voxels->cellMm();
    if (m_lathe) return m_lathe->cellMm();
    return m_options.resolutionMm;
}

Mesh StockSimulation::mesh(int maxSide) const {
    if (m_mill) return m_mill->mesh(maxSide);
    if (m_voxels) {
        Mesh mesh = m_voxels->mesh(std::min(maxSide, kMaxVoxelMeshSide));
        mesh.shadeAboutAxis = m_lyingCylinderAxis;
        return mesh;
    }
    if (m_lathe) return m_lathe->mesh(180.0, 48, maxSide);
    return {};
}

}  // namespace kerf::graphics
