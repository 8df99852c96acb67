#include "core/interp/klartext/program_file.h"

#include <type_traits>
#include <vector>

#include "core/cycles/cycle_registry.h"
#include "core/cycles/legacy/legacy_cycles.h"
#include "core/cycles/probing/probing_cycle.h"
#include "core/cycles/probing/single_touch.h"
#include "core/interp/klartext/block_parser.h"
#include "core/interp/klartext/block_reader.h"
#include "core/interp/klartext/contour_labels.h"
#include "core/interp/klartext/cursor.h"
#include "core/interp/klartext/cycle_definition_check.h"
#include "core/interp/klartext/program_check.h"
#include "core/interp/klartext/statement_axes.h"

namespace kerf::klartext {

const LabelPosition* ProgramFile::findLabel(int number) const {
    auto it = numberedLabels.find(number);
    return it == numberedLabels.end() ? nullptr : &it->second;
}

const LabelPosition* ProgramFile::findLabel(const std::string& name) const {
    auto it = namedLabels.find(name);
    return it == namedLabels.end() ? nullptr : &it->second;
}

std::unique_ptr<BlockSyntax> makeSyntax(const ProgramFile& program,
                                        FormulaEnvironment* environment) {
    if (program.syntax != nullptr && *program.syntax) return (*program.syntax)(environment);
    return std::make_unique<BlockParser>(environment);
}

std::string cycle12Program(std::string_view rest) {
    Cursor c(rest);
    c.acceptKeyword("PGM");
    std::string_view path = c.restUntilComment();
    if (path.size() >= 2 && path.front() == '"' && path.back() == '"') {
        path = path.substr(1, path.size() - 2);
    }
    return std::string(path);
}

bool programUsesInch(const ProgramFile& program) {
    auto parser = makeSyntax(program, nullptr);
    BlockReader reader(program.source->text(), parser.get());
    program::LogicalLine line;
    ParsedBlock block;
    while (reader.next(line)) {
        if (!parser->parse(line, block)) return false;
        if (std::holds_alternative<Empty>(block.statement)) continue;
        const auto* begin = std::get_if<BeginPgm>(&block.statement);
        return begin != nullptr && begin->inch;
    }
    return false;
}

void checkProgram(ProgramFile& program) {
    ProgramCheck check(program);
    check.finish();
}

}  // namespace kerf::klartext
