#include "ui/editor/program_file.h"

#include "core/base/atomic_file.h"

namespace kerf::ui {

Expected<ProgramText> readProgramFile(const std::filesystem::path& path) {
    auto bytes = readWholeFile(path);
    if (!bytes) return bytes.error();
    ProgramText program;
    program.encoding = program::detectEncoding(*bytes);
    // Line ends are looked for in the converted text: in UTF-16 a CR is not the byte before LF.
    const std::string utf8 = program::toUtf8(*bytes, program.encoding);
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
