#include "app/runner/output_guard.h"

#include <optional>
#include <utility>

#include "core/base/atomic_file.h"

namespace kerf::app {

DiagnosticList outputsOverwritingInputs(const RunOptions& options,
                                        const std::vector<std::filesystem::path>& inputs) {
    const std::pair<const char*, const std::optional<std::filesystem::path>*> outputs[] = {
        {"--trace", &options.traceFile},
        {"--samples", &options.samples},
        {"--report", &options.reportFile},
        {"--png", &options.png},
        {"--can-trace", &options.canTrace}};
    DiagnosticList refused;
    for (const auto& [option, path] : outputs) {
        if (!*path || **path == "-") continue;
        for (const std::filesystem::path& input : inputs) {
            if (!sameFile(**path, input)) continue;
            refused.push_back(
                Diagnostic::make(Severity::Error, "output", (*path)->string(), 0, 0,
                                 KERF_TR_NOOP("{1} would overwrite '{2}', which the run reads"),
                                 option, input.string()));
            break;
        }
    }
    return refused;
}

}  // namespace kerf::app
