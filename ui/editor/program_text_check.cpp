#include "ui/editor/program_text_check.h"

#include "core/task/program_loader.h"

namespace kerf::ui {

DiagnosticList checkProgramText(std::string text, const std::string& path, program::Dialect dialect,
                                const machine::MachineConfig& machine,
                                const std::filesystem::path& ncRoot) {
    task::ProgramRequest request;
    request.text = std::move(text);
    request.path = path;
    request.dialect = dialect;
    request.ncRoot = ncRoot;
    return task::loadProgram(machine, request).diagnostics();
}

}  // namespace kerf::ui
