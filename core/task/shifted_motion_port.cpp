#include "core/task/shifted_motion_port.h"

#include <variant>

namespace kerf::task {

namespace {

Pose plus(Pose pose, const Pose& shift) {
    for (size_t i = 0; i < pose.values.size(); ++i)
        pose.values[i] += shift.values[i];
    return pose;
}

Pose minus(Pose pose, const Pose& shift) {
    for (size_t i = 0; i < pose.values.size(); ++i)
        pose.values[i] -= shift.values[i];
    return pose;
}

// The surface a probe move carries, seen from the machine's origin: the tips the machine tests
// lose the shift before the surface (in the stream's coordinates) is asked.
class ShiftedSurface final : public canon::ProbeSurface {
public:
    ShiftedSurface(std::shared_ptr<const canon::ProbeSurface> surface, const Vec3& shift)
        : m_surface(std::move(surface)), m_shift(shift) {}
    bool touches(const Vec3& tip) const override { return m_surface->touches(tip - m_shift); }

private:
    std::shared_ptr<const canon::ProbeSurface> m_surface;
    Vec3 m_shift;
};

}  // namespace

ShiftedMotionPort::ShiftedMotionPort(std::unique_ptr<MotionPort> machine)
    : m_machine(std::move(machine)) {}

bool ShiftedMotionPort::submit(const canon::Command& command) {
    if (const auto* stock = std::get_if<canon::StockDefinition>(&command.body))
        m_lastBlank = PassedBlank{*stock, m_shift, m_programCuts};
    if (m_shift == Pose{}) return m_machine->submit(command);
    canon::Command shifted = command;
    // Every position in the stream: move targets, the arc centre and the blank.
    std::visit(
        [this](auto& body) {
            using T = std::decay_t<decltype(body)>;
            if constexpr (std::is_same_v<T, canon::RapidMove> ||
                          std::is_same_v<T, canon::LinearMove> ||
                          std::is_same_v<T, canon::SpindleSyncedMove> ||
                          std::is_same_v<T, canon::ProbeMove>) {
                body.target = plus(body.target, m_shift);
                if constexpr (std::is_same_v<T, canon::ProbeMove>) {
                    if (body.surface) {
                        body.surface =
                            std::make_shared<ShiftedSurface>(body.surface, m_shift.xyz());
                    }
                }
            } else if constexpr (std::is_same_v<T, canon::ArcMove>) {
                body.target = plus(body.target, m_shift);
                body.center += m_shift.xyz();
            } else if constexpr (std::is_same_v<T, canon::StockDefinition>) {
                if (auto* box = std::get_if<canon::StockBox>(&body.shape)) {
                    box->min += m_shift.xyz();
                    box->max += m_shift.xyz();
                } else if (auto* revolved = std::get_if<canon::StockRevolved>(&body.shape)) {
                    for (Vec3& p : revolved->outline)
                        p += m_shift.xyz();
                }
            }
        },
        shifted.body);
    return m_machine->submit(shifted);
}

interp::WorldSnapshot ShiftedMotionPort::world() const {
    interp::WorldSnapshot world = m_machine->world();
    world.position = minus(world.position, m_shift);
    world.probePosition = minus(world.probePosition, m_shift);
    return world;
}

MachineStatus ShiftedMotionPort::status() const {
    MachineStatus status = m_machine->status();
    // Machine coordinates (REF), the lag and the distance to go do not depend on the origin.
    for (size_t i = 0; i < status.axes.size(); ++i) {
        status.axes[i].nominal -= m_shift.values[i];
        status.axes[i].actual -= m_shift.values[i];
    }
    return status;
}

}  // namespace kerf::task
