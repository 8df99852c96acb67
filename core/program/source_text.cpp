#include "core/program/source_text.h"

#include "core/base/atomic_file.h"

namespace kerf::program {

namespace {

// Strips a UTF-8 byte order mark.
std::string_view withoutBom(std::string_view text) {
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") return text.substr(3);
    return text;
}

}  // namespace

Expected<std::shared_ptr<const SourceText>> SourceText::load(const std::filesystem::path& path) {
    // A copy in memory, not a mapping: another process that truncates or replaces the file while
    // it runs cannot take the text away (a mapped page past the new end is SIGBUS).
    auto bytes = readWholeFile(path);
    if (!bytes) return bytes.error();
    return std::shared_ptr<const SourceText>(fromString(std::move(*bytes), path.string()));
}

std::shared_ptr<const SourceText> SourceText::fromString(std::string text, std::string path) {
    std::shared_ptr<SourceText> source(new SourceText());
    source->m_path = std::move(path);
    source->m_encoding = detectEncoding(text);
    source->m_owned =
        source->m_encoding == Encoding::Utf8 ? std::move(text) : toUtf8(text, source->m_encoding);
    source->m_view = withoutBom(source->m_owned);
    return source;
}

uint32_t columnOf(std::string_view line, size_t byteOffset) {
    uint32_t column = 1;
    for (size_t i = 0; i < byteOffset && i < line.size(); ++i) {
        if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) ++column;
    }
    return column;
}

}  // namespace kerf::program
