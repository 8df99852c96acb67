#include "core/workpiece/simulated_part.h"

namespace kerf::workpiece {

canon::StockDefinition simulationBlank(const machine::MachineConfig& machine) {
    const machine::SimulationBlankConfig& b = machine.simulationBlank;
    return canon::StockDefinition{
        canon::StockBox{Vec3(b.minXMm, b.minYMm, b.minZMm), Vec3(b.maxXMm, b.maxYMm, b.maxZMm)}};
}

Vec3 machineFilePresetIn(const machine::MachineConfig& machine, const Pose& presetInMachine) {
    Pose filePreset = presetInMachine;
    for (const machine::AxisConfig& axis : machine.axes) {
        if (const auto a = axisFromLetter(axis.letter)) filePreset[*a] = axis.presetPosition;
    }
    return filePreset.xyz() - presetInMachine.xyz();
}

SimulatedWorkpiece simulatedPart(const machine::MachineConfig* machine,
                                 const std::vector<Solid>& blank, const Vec3& origin) {
    Placement placement;
    placement.origin = origin;
    if (machine != nullptr) {
        const machine::SetupErrorConfig& e = machine->setupError;
        placement.shift = Vec3(e.shiftXMm, e.shiftYMm, e.shiftZMm);
        placement.rotationDeg = e.rotationDeg;
    }
    SimulatedWorkpiece part(placement);
    for (const Solid& solid : blank)
        part.add(solid);
    if (machine != nullptr && machine->calibrationSphere.radiusMm > 0.0) {
        const machine::CalibrationSphereConfig& sphere = machine->calibrationSphere;
        const Vec3 centre(sphere.centreXMm, sphere.centreYMm, sphere.centreZMm);
        part.add({Sphere{centre, sphere.radiusMm}, true});
    }
    return part;
}

}  // namespace kerf::workpiece
