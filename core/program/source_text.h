#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "core/base/expected.h"
#include "core/program/encoding.h"

namespace kerf::program {

// The text of one program file, as UTF-8. Large UTF-8/ASCII files are memory-mapped rather than
// copied so that a million-block program costs no heap; other encodings are converted once.
class SourceText {
public:
    static Expected<std::shared_ptr<const SourceText>> load(const std::filesystem::path& path);
    static std::shared_ptr<const SourceText> fromString(std::string text, std::string path);

    ~SourceText();
    SourceText(const SourceText&) = delete;
    SourceText& operator=(const SourceText&) = delete;

    std::string_view text() const { return m_view; }
    const std::string& path() const { return m_path; }
    Encoding encoding() const { return m_encoding; }

    // Tells the kernel the text before `offset` is not needed soon, so a large program streams
    // through memory instead of staying resident. Reading it again (a jump back) still works: the
    // pages come back from the file.
    void releaseBefore(size_t offset) const;

private:
    SourceText() = default;

    std::string m_path;
    std::string m_owned;
    void* m_mapping = nullptr;
    size_t m_mappingSize = 0;
    std::string_view m_view;
    Encoding m_encoding = Encoding::Utf8;
};

// 1-based column of a byte offset in a line, counting UTF-8 characters.
uint32_t columnOf(std::string_view line, size_t byteOffset);

}  // namespace kerf::program
