#include "ui/editor/program_file.h"

#include "core/base/atomic_file.h"

namespace kerf::ui {

Expected<ProgramText> readProgramFile(const std::filesystem::path& path) {
    auto bytes = readWholeFile(path);
    if (!bytes) return bytes.error();
    ProgramText program;
    program.encoding = program::detectEncoding(*bytes);
    const size_t firstBreak = bytes->find('\n');
    program.crlf =
        firstBreak != std::string::npos && firstBreak > 0 && (*bytes)[firstBreak - 1] == '\r';
    QString text = QString::fromStdString(program::toUtf8(*bytes, program.encoding));
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
