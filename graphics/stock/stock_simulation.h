#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/canon/commands.h"
#include "core/machine/workpiece_frame.h"
#include "graphics/stock/cutter.h"
#include "graphics/stock/height_field_stock.h"
#include "graphics/stock/lathe_stock.h"
#include "graphics/stock/voxel_stock.h"

namespace kerf::graphics {

enum class StockMachine : uint8_t { Mill, Lathe };

struct StockOptions {
    StockMachine machine = StockMachine::Mill;
    double resolutionMm = 0.1;
    size_t maxCells = 25'000'000;  // the cell size grows beyond this (reported in notes())
    // Tool shapes from a tool change; by default R and R2 of the canonical geometry (no point
    // angle: the runner adds T-ANGLE from the tool table) and an insert of nose radius R with the
    // offset's tip location code (3 when the tool change carries none).
    std::function<MillCutter(const canon::ToolChange&)> millCutter;
    std::function<LatheInsert(const canon::ToolChange&)> latheInsert;
    // Blank used when the program defines none (mill) or instead of the program's (lathe bar).
    std::optional<canon::StockDefinition> fallbackStock;
    std::optional<LatheBar> bar;
    // Without any blank: derive one from the feed path at the end (finish()), replaying the
    // moves: mill box over the feed path and tool radius from the lowest feed Z up to Z0,
    // lathe bar of the largest feed radius from the lowest feed Z to Z0.
    bool deriveStockFromPath = false;
    size_t maxDeferredMoves = 5'000'000;
    // A machine with rotary tables: the stream's positions are mapped onto the turned workpiece,
    // and the first cut with the tool not along the workpiece's Z moves the mill stock from the
    // height field into voxels (at most `maxVoxels`; the cell grows beyond).
    std::optional<machine::WorkpieceFrame> workpieceFrame;
    size_t maxVoxels = 64'000'000;
    // The most a table turns between two cuts of a simultaneous move.
    double maxTableStepDeg = 1.0;
};

// Material removal driven by the canonical stream: a height field for the mill (voxels once a
// tool stands tilted on the workpiece), a revolved 2D profile for the lathe. Feed and rapid moves
// cut (rapids into material are counted); arcs are split into chords of a quarter cell. Consume on
// one thread (the mesh worker or the runner).
class StockSimulation final : public canon::Sink {
public:
    explicit StockSimulation(StockOptions options = {});
    ~StockSimulation() override;
    StockSimulation(const StockSimulation&) = delete;
    StockSimulation& operator=(const StockSimulation&) = delete;

    void setStart(const Pose& start) { m_position = start; }
    void consume(const canon::Command& command) override;
    // End of the stream: builds a derived blank and replays the moves if needed.
    void finish();

    bool hasStock() const { return m_mill != nullptr || m_voxels != nullptr || m_lathe != nullptr; }
    // The mill stock: a height field until a tool stands tilted, then voxels (one of them).
    const HeightFieldStock* millStock() const { return m_mill.get(); }
    const VoxelStock* voxelStock() const { return m_voxels.get(); }
    const LatheStock* latheStock() const { return m_lathe.get(); }
    double removedVolumeMm3() const;
    double initialVolumeMm3() const;
    double resolutionMm() const;
    // Increments whenever material is removed (for progressive display).
    uint64_t version() const { return m_version; }
    size_t movesSimulated() const { return m_moves; }
    size_t rapidCuts() const { return m_rapidCuts; }
    const std::string& stockSource() const { return m_source; }  // program, bar, derived, none
    // Warnings for the report: missing blank, unsupported tool axis, coarsened grid ...
    const std::vector<std::string>& notes() const { return m_notes; }
    // Shaded solid of the current stock (empty without stock).
    Mesh mesh(int maxSide = 512) const;

private:
    struct Deferred {
        Vec3 from;
        Vec3 to;
        Vec3 axis;
        uint32_t tool;
        bool rapid;
    };
    void createStock(const canon::StockDefinition& definition, const std::string& source);
    void createBar(const LatheBar& bar, const std::string& source);
    void createRevolved(const canon::StockRevolved& blank);
    void cutSegment(const Vec3& from, const Vec3& to, const Vec3& axis, bool rapid);
    void cutWithTool(const Vec3& from, const Vec3& to, const Vec3& axis, bool rapid, size_t tool);
    // A straight move of the stream: on the workpiece, in steps while the tables turn.
    void cutStreamLine(const Pose& from, const Pose& to, bool rapid);
    void switchToVoxels();
    machine::ToolOnPart onPart(const Pose& stream) const;
    void note(const std::string& text);

    StockOptions m_options;
    Pose m_position{};
    std::unique_ptr<HeightFieldStock> m_mill;
    std::unique_ptr<VoxelStock> m_voxels;
    double m_removedBeforeVoxels = 0.0;  // by the height field before the switch
    double m_voxelBaselineMm3 = 0.0;     // voxel volume at the switch
    double m_initialVolumeMm3 = 0.0;
    int m_lyingCylinderAxis = -1;  // a cylinder blank along X (0) or Y (1)
    std::unique_ptr<LatheStock> m_lathe;
    std::vector<MillCutter> m_cutters{MillCutter{}};
    std::vector<LatheInsert> m_inserts{LatheInsert{}};
    std::vector<Axis> m_toolAxes{Axis::Z};
    size_t m_tool = 0;
    std::vector<Deferred> m_deferred;
    bool m_deferOverflow = false;
    Bounds3 m_feedBounds;
    double m_maxToolRadius = 0.0;
    uint64_t m_version = 0;
    size_t m_moves = 0;
    size_t m_rapidCuts = 0;
    std::string m_source = "none";
    std::vector<std::string> m_notes;
    std::vector<Vec3> m_scratch;
    std::vector<machine::ToolOnPart> m_samples;
};

}  // namespace kerf::graphics
