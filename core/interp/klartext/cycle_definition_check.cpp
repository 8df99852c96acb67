#include "core/interp/klartext/cycle_definition_check.h"

#include <algorithm>

#include "core/cycles/cycle_registry.h"
#include "core/cycles/parameter_check.h"
#include "core/cycles/probing/probing_14xx.h"
#include "core/cycles/probing/probing_cycle.h"

namespace kerf::klartext {

namespace {

void report(const cycles::CycleError& error, const std::string& file, uint32_t line,
            uint32_t column, DiagnosticList& out) {
    Diagnostic d =
        Diagnostic::make(Severity::Error, error.code, file, line, column, error.messageTemplate);
    d.args = error.args;
    appendDiagnostic(out, std::move(d));
}

}  // namespace

void checkCycleParameters(const CycleDefinition& def, const program::LogicalLine& line,
                          const std::string& file, DiagnosticList& out) {
    if (def.subNumber >= 0) return;
    std::span<const cycles::ParameterDescriptor> parameters;
    std::string owner;
    if (def.probe) {
        const auto* probe = cycles::probing::findProbingCycle(def.number);
        if (probe == nullptr) return;
        parameters = probe->parameters;
        owner = "touch probe cycle " + std::to_string(def.number);
    } else {
        const cycles::CycleDescriptor* cycle = cycles::findCycle(def.number);
        if (cycle == nullptr || cycle->oldStyle) return;
        parameters = cycle->parameters;
        owner = "cycle " + std::to_string(def.number);
    }
    for (const cycles::ParameterDescriptor& d : parameters) {
        // The run takes the last of repeated parameters.
        auto it = std::find_if(def.parameters.rbegin(), def.parameters.rend(),
                               [&](const CycleParameter& p) { return p.q == d.q; });
        if (it == def.parameters.rend()) {
            if (auto missing = cycles::missingParameterError(owner, d)) {
                report(*missing, file, line.firstLine, 1, out);
            }
            continue;
        }
        const bool nominalPosition =
            def.probe && cycles::probing::takesActualPosition(def.number, d.q);
        if ((it->actual || it->unknown) && !nominalPosition) {
            report(it->unknown ? cycles::probing::unknownPositionError(owner, d)
                               : cycles::probing::actualPositionError(owner, d),
                   file, line.lineAt(it->actualOffset), line.columnAt(it->actualOffset), out);
            continue;
        }
        if (it->unknown) continue;
        if (it->isString || d.unit == cycles::Unit::Text || !it->literal) continue;
        if (auto outside = cycles::parameterValueError(owner, d, *it->value)) {
            report(*outside, file, line.lineAt(it->offset), line.columnAt(it->offset), out);
        } else if (it->actual) {
            if (auto actual = cycles::parameterValueError(owner, d, *it->actual)) {
                report(*actual, file, line.lineAt(it->actualOffset),
                       line.columnAt(it->actualOffset), out);
            }
        }
    }
}

}  // namespace kerf::klartext
