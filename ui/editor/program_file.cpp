#include "ui/editor/program_file.h"

#include "core/base/atomic_file.h"
#include "core/base/translate.h"
#include "core/program/line_reader.h"

namespace kerf::ui {

namespace {

// The first line longer than a block may be (1-based), or 0. Qt lays out and shapes a line as a
// whole: a 10 MB line kept the panel busy for minutes, and no dialect runs such a block.
uint32_t firstOverlongLine(std::string_view text) {
    // LF, CRLF and CR-only line ends: a line ends at either character; the lines are counted
    // at LF, or at CR in a file without LF.
    const bool crOnly = text.find('\n') == std::string_view::npos;
    uint32_t line = 1;
    size_t start = 0;
    for (;;) {
        const size_t end = text.find_first_of("\r\n", start);
        const size_t length = (end == std::string_view::npos ? text.size() : end) - start;
        if (length > program::kMaxBlockCharacters) return line;
        if (end == std::string_view::npos) return 0;
        if (text[end] == '\n' || crOnly) ++line;
        start = end + 1;
    }
}

}  // namespace

Expected<ProgramText> readProgramFile(const std::filesystem::path& path) {
    auto bytes = readWholeFile(path);
    if (!bytes) return bytes.error();
    ProgramText program;
    program.encoding = program::detectEncoding(*bytes);
    // Line ends are looked for in the converted text: in UTF-16 a CR is not the byte before LF.
    const std::string utf8 = program::toUtf8(*bytes, program.encoding);
    if (const uint32_t line = firstOverlongLine(utf8)) {
        return Diagnostic::make(Severity::Error, "syntax", path.string(), line,
                                program::kMaxBlockCharacters + 1,
                                KERF_TR_NOOP("the block is longer than 60000 characters"));
    }
    const size_t firstBreak = utf8.find('\n');
    program.crlf =
        firstBreak != std::string::npos && firstBreak > 0 && utf8[firstBreak - 1] == '\r';
    QString text = QString::fromStdString(utf8);
    if (program.crlf) text.remove(QLatin1Char('\r'));
    program.text = std::move(text);
    return program;
}

MaybeError writeProgramFile(const program::NcRoot& root, const std::filesystem::path& path,
                            const ProgramText& program) {
    QString text = program.text;
    if (program.crlf) text.replace(QLatin1Char('\n'), QStringLiteral("\r\n"));
    return root.replace(path, program::fromUtf8(text.toStdString(), program.encoding));
}

}  // namespace kerf::ui
