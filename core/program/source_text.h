#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "core/base/expected.h"
#include "core/program/encoding.h"

namespace kerf::program {

// The text of one program file, as UTF-8: in memory, or for a long one a mapped unnamed copy
// (mapped_copy.h); never a mapping of the file, so a file truncated or replaced while it runs
// changes nothing (docs/files.md). Other encodings are converted once, into memory.
class SourceText {
public:
    static Expected<std::shared_ptr<const SourceText>> load(const std::filesystem::path& path);
    static std::shared_ptr<const SourceText> fromString(std::string text, std::string path);

    SourceText(const SourceText&) = delete;
    SourceText& operator=(const SourceText&) = delete;

    std::string_view text() const { return m_view; }
    const std::string& path() const { return m_path; }
    Encoding encoding() const { return m_encoding; }

private:
    SourceText() = default;

    std::string m_path;
    std::string m_owned;
    std::string_view m_view;
    Encoding m_encoding = Encoding::Utf8;
};

// 1-based column of a byte offset in a line, counting UTF-8 characters.
uint32_t columnOf(std::string_view line, size_t byteOffset);

}  // namespace kerf::program
