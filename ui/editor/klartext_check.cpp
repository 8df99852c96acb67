#include "ui/editor/klartext_check.h"

#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/tnciso/tnciso.h"
#include "core/program/source_registry.h"

namespace kerf::ui {

DiagnosticList checkKlartextText(std::string text, const std::string& path,
                                 const machine::MachineConfig& machine,
                                 const std::filesystem::path& ncRoot, bool iso) {
    program::SourceRegistry sources;
    klartext::KlartextSettings settings;
    tnciso::enableIso(settings, iso);
    settings.machine = &machine;
    settings.ncRoot = ncRoot;
    klartext::KlartextInterpreter interpreter(sources, settings);
    interpreter.loadText(std::move(text), path);
    return interpreter.diagnostics();
}

}  // namespace kerf::ui
