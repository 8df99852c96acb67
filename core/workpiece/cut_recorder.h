#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "core/canon/commands.h"
#include "core/machine/machine_config.h"
#include "core/workpiece/removed_material.h"
#include "core/workpiece/simulated_tool_probe.h"
#include "core/workpiece/simulated_workpiece.h"

namespace kerf::workpiece {

// Follows the canonical stream on its way out of an interpreter and records the volume each
// feed move's cutter sweeps (rapids cut nothing, and one into the blank is a collision), so the
// simulated part the probe touches is the blank as machined so far. The tool comes from ToolChange
// / ToolUpdate (radius, R2, length, tool axis z); a touch probe removes nothing. Qt- and VTK-free.
class CutRecorder final : public canon::Sink {
public:
    CutRecorder() : m_removed(std::make_shared<RemovedMaterial>()) {}

    void setTarget(canon::Sink* target) { m_target = target; }
    void consume(const canon::Command& command) override;

    // Where the tool tip is (the start of a run); nothing: not known, the next move only
    // arrives there (after the operator moved the machine at a stop).
    void setPosition(std::optional<Vec3> tip) { m_at = tip; }
    // Tool numbers that are touch probes: they cut nothing when called.
    void addProbeTool(int number) { m_probeTools.insert(number); }
    // The tool as it really is (the simulation's tool error included): it cuts with this
    // radius, and its tip lies (stream length - real length) below where the stream says.
    void setRealTool(int number, const RealTool& real) { m_realTools[number] = real; }
    // The tool in the spindle is a touch probe (a probing cycle runs with it): it cuts nothing
    // from now on, and neither does a later call of it.
    void activeToolIsProbe();

    // The machine whose [simulation.setup] places the blank a StockDefinition passes on (for
    // the collision check of rapids); without one the blank lies where it was programmed.
    void setMachine(const machine::MachineConfig* machine) { m_machine = machine; }
    // Where rapids since the last call took material of the blank (SimulatedWorkpiece::
    // rapidTakesMaterial), one entry per source line: collisions.
    std::vector<SourceLocation> takeCollisions() { return std::exchange(m_collisions, {}); }

    std::shared_ptr<const RemovedMaterial> removed() const { return m_removed; }
    // True once when the removed material stopped growing (RemovedMaterial::kMaxSweeps).
    bool takeOverflowNotice() {
        const bool notice = m_removed->overflowed() && !m_overflowNoticed;
        m_overflowNoticed = m_overflowNoticed || notice;
        return notice;
    }

private:
    void setTool(const canon::ToolGeometry& geometry, Axis toolAxis);
    void moveTo(const Pose& target);
    void checkRapid(const canon::Command& command, const Pose& target);

    canon::Sink* m_target = nullptr;
    std::shared_ptr<RemovedMaterial> m_removed;
    std::optional<Vec3> m_at;
    std::set<int> m_probeTools;
    std::map<int, RealTool> m_realTools;
    int m_toolNumber = -1;
    Cutter m_cutter;                  // radius 0: cuts nothing
    Vec3 m_tipOffset{0.0, 0.0, 0.0};  // the real tip from the stream's
    bool m_overflowNoticed = false;
    const machine::MachineConfig* m_machine = nullptr;
    std::optional<SimulatedWorkpiece> m_part;  // the program's blank (BLK FORM) as machined
    std::vector<SourceLocation> m_collisions;
};

}  // namespace kerf::workpiece
