#include "core/interp/tnciso/tnciso.h"

#include "core/interp/tnciso/iso_block_syntax.h"

namespace kerf::tnciso {

void enableIso(klartext::KlartextSettings& settings, bool mainProgramIso) {
    settings.isoSyntax = [](klartext::FormulaEnvironment* environment) {
        return std::make_unique<IsoBlockSyntax>(environment);
    };
    settings.mainProgramIso = mainProgramIso;
}

}  // namespace kerf::tnciso
