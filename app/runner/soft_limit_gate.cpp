#include "app/runner/soft_limit_gate.h"

#include "core/base/translate.h"

namespace kerf::app {

SoftLimitGate::SoftLimitGate(const motion::MachineModel& model) : m_checker(model) {}

void SoftLimitGate::start(const motion::AxisVector& tip, canon::Sink& machine) {
    Pose start;
    start.values = tip;
    m_checker.start(start);
    m_machine = &machine;
}

void SoftLimitGate::consume(const canon::Command& command) {
    if (m_refusedAt) return;
    if (!m_checker.accept(command)) {
        m_refusedAt = command.location;
        return;
    }
    m_held.push_back(command);
    if (m_held.size() >= kMaxHeldCommands) release();
}

void SoftLimitGate::release() {
    if (m_machine == nullptr || m_refusedAt) return;
    for (const canon::Command& command : m_held)
        m_machine->consume(command);
    m_held.clear();
}

void SoftLimitGate::resumeAt(const motion::AxisVector& tip) {
    Pose at;
    at.values = tip;
    m_checker.resumeAt(at);
}

DiagnosticList SoftLimitGate::refusal(const std::string& file, bool originAtMachineOrigin) const {
    if (!m_refusedAt) return {};
    DiagnosticList refusal = m_checker.refusal();
    for (Diagnostic& d : refusal)
        d.file = file;
    return withWorkOffsetHint(std::move(refusal), originAtMachineOrigin);
}

DiagnosticList withWorkOffsetHint(DiagnosticList refusal, bool originAtMachineOrigin) {
    DiagnosticList list;
    for (Diagnostic& d : refusal) {
        const bool softLimit = d.code == "motion.soft-limit";
        Diagnostic hint = Diagnostic::make(
            Severity::Note, "motion.work-offset", d.file, d.line, d.column,
            KERF_TR_NOOP("the workpiece origin is at the machine origin; give its machine "
                         "coordinates with --work-offset, e.g. Z-300"));
        list.push_back(std::move(d));
        if (softLimit && originAtMachineOrigin) list.push_back(std::move(hint));
    }
    return list;
}

}  // namespace kerf::app
