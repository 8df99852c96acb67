#include "core/program/source_text.h"

#include <algorithm>
#include <optional>

#include "core/base/atomic_file.h"
#include "core/program/mapped_copy.h"

namespace kerf::program {

namespace {

// Strips a UTF-8 byte order mark.
std::string_view withoutBom(std::string_view text) {
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") return text.substr(3);
    return text;
}

// Whether a mapped copy holds UTF-8 text (the encoding that needs no conversion), read a piece at
// a time with the pages released behind, so that checking a long program does not make it
// resident. The same answer as detectEncoding(...) == Encoding::Utf8 on the whole text.
bool holdsUtf8(std::string_view mapped) {
    if (mapped.starts_with("\xFF\xFE") || mapped.starts_with("\xFE\xFF")) return false;  // UTF-16
    size_t at = 0;
    while (at < mapped.size()) {
        size_t end = std::min(mapped.size(), at + kTextReleaseStep);
        // Split before a character, never inside one (at most three continuation bytes).
        for (int back = 0; back < 3 && end < mapped.size() &&
                           (static_cast<unsigned char>(mapped[end]) & 0xC0) == 0x80;
             ++back) {
            --end;
        }
        if (!isValidUtf8(mapped.substr(at, end - at))) return false;
        at = end;
        releasePagesBefore(mapped, at);
    }
    return true;
}

// A long UTF-8 program as a mapped unnamed copy of the file (mapped_copy.h); nothing when it is
// short, not UTF-8 or cannot be copied.
std::optional<std::string_view> mappedCopyOf(const std::filesystem::path& path) {
    const auto mapped = mapUnnamedCopy(path);
    if (mapped && !holdsUtf8(*mapped)) {
        unmapCopy(*mapped);
        return std::nullopt;
    }
    return mapped;
}

}  // namespace

Expected<std::shared_ptr<const SourceText>> SourceText::load(const std::filesystem::path& path) {
    // A copy, never a mapping of the file: another process that truncates or replaces the file
    // while it runs cannot take the text away (a mapped page past the new end is SIGBUS). A long
    // program is copied to an unnamed file and that copy mapped, so that it is not all resident.
    if (const auto mapped = mappedCopyOf(path)) {
        std::shared_ptr<SourceText> source(new SourceText(), [mapped = *mapped](SourceText* text) {
            delete text;
            unmapCopy(mapped);
        });
        source->m_path = path.string();
        source->m_view = withoutBom(*mapped);
        return std::shared_ptr<const SourceText>(std::move(source));
    }
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
