#pragma once

#include <memory>

#include "core/task/motion_port.h"

namespace kerf::workpiece {
class RemovedMaterial;
}

namespace kerf::task {

// The machine seen from a workpiece origin moved by `shift` (workpiece coordinates of the
// machine connection's own origin, the machine file's preset): what the operator sets by entry
// in Manual operation. Targets going to the machine get the shift added; positions coming back
// lose it. The machine connection itself never changes: its origin is fixed when it starts.
// Task thread only, like the port it wraps.
class ShiftedMotionPort final : public MotionPort {
public:
    explicit ShiftedMotionPort(std::unique_ptr<MotionPort> machine);

    const Pose& shift() const { return m_shift; }
    void setShift(const Pose& shift) { m_shift = shift; }

    // The blank (BLK FORM) the last program defined, as programmed, the shift it was passed on
    // with (where the part clamped for it lies) and what that program cut out of it (in the
    // same coordinates): manual probing touches it.
    struct PassedBlank {
        canon::StockDefinition stock;
        Pose shift;
        std::shared_ptr<const workpiece::RemovedMaterial> removed;
    };
    const std::optional<PassedBlank>& lastBlank() const { return m_lastBlank; }
    // The cuts of the program whose stream comes next (Interpreter::removedMaterial): a blank
    // it passes on keeps them.
    void setProgramCuts(std::shared_ptr<const workpiece::RemovedMaterial> removed) {
        m_programCuts = std::move(removed);
    }

    bool submit(const canon::Command& command) override;
    bool hasRoom() const override { return m_machine->hasRoom(); }
    void flush() override { m_machine->flush(); }
    void pump() override { m_machine->pump(); }
    bool drained() const override { return m_machine->drained(); }
    interp::WorldSnapshot world() const override;
    Progress progress() const override { return m_machine->progress(); }
    bool latchesProbe() const override { return m_machine->latchesProbe(); }

    void cycleStart() override { m_machine->cycleStart(); }
    void feedHold() override { m_machine->feedHold(); }
    void quickStop() override { m_machine->quickStop(); }
    void emergencyStop() override { m_machine->emergencyStop(); }
    bool machineOn() override { return m_machine->machineOn(); }
    bool setEmergencyStopButton(bool pressed) override {
        return m_machine->setEmergencyStopButton(pressed);
    }
    void setSingleBlock(bool on) override { m_machine->setSingleBlock(on); }
    void setSingleBlockEveryBlock(bool on) override { m_machine->setSingleBlockEveryBlock(on); }

    void setFeedOverride(double fraction) override { m_machine->setFeedOverride(fraction); }
    void setRapidOverride(double fraction) override { m_machine->setRapidOverride(fraction); }
    void setSpindleOverride(double fraction) override { m_machine->setSpindleOverride(fraction); }
    bool jogContinuous(Axis axis, double fraction) override {
        return m_machine->jogContinuous(axis, fraction);
    }
    bool jogStop(Axis axis) override { return m_machine->jogStop(axis); }
    bool jogIncrement(Axis axis, double distance) override {
        return m_machine->jogIncrement(axis, distance);
    }
    bool home(std::optional<Axis> axis) override { return m_machine->home(axis); }
    bool manualSpindle(const canon::SpindleControl& spindle) override {
        return m_machine->manualSpindle(spindle);
    }
    bool manualCoolant(const canon::CoolantControl& coolant) override {
        return m_machine->manualCoolant(coolant);
    }
    MachineStatus status() const override;

private:
    std::unique_ptr<MotionPort> m_machine;
    Pose m_shift{};
    std::optional<PassedBlank> m_lastBlank;
    std::shared_ptr<const workpiece::RemovedMaterial> m_programCuts;
};

}  // namespace kerf::task
