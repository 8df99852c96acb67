#include "core/program/source_text.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace kerf::program {

namespace {

Diagnostic openError(const std::filesystem::path& path) {
    return Diagnostic::make(Severity::Error, "io", path.string(), 0, 0,
                            KERF_TR_NOOP("cannot read the program: {1}"), std::strerror(errno));
}

// Strips a UTF-8 byte order mark.
std::string_view withoutBom(std::string_view text) {
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") return text.substr(3);
    return text;
}

}  // namespace

SourceText::~SourceText() {
    if (m_mapping != nullptr) ::munmap(m_mapping, m_mappingSize);
}

Expected<std::shared_ptr<const SourceText>> SourceText::load(const std::filesystem::path& path) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return openError(path);
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        if (errno == 0) errno = EISDIR;
        Diagnostic error = openError(path);
        ::close(fd);
        return error;
    }
    std::shared_ptr<SourceText> source(new SourceText());
    source->m_path = path.string();
    auto size = static_cast<size_t>(info.st_size);
    if (size > 0) {
        void* mapping = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
        if (mapping == MAP_FAILED) {
            Diagnostic error = openError(path);
            ::close(fd);
            return error;
        }
        ::madvise(mapping, size, MADV_SEQUENTIAL);
        source->m_mapping = mapping;
        source->m_mappingSize = size;
    }
    ::close(fd);
    std::string_view bytes(static_cast<const char*>(source->m_mapping), size);
    source->m_encoding = detectEncoding(bytes);
    if (source->m_encoding == Encoding::Utf8) {
        source->m_view = withoutBom(bytes);
    } else {
        source->m_owned = toUtf8(bytes, source->m_encoding);
        ::munmap(source->m_mapping, source->m_mappingSize);
        source->m_mapping = nullptr;
        source->m_view = source->m_owned;
    }
    return std::shared_ptr<const SourceText>(std::move(source));
}

std::shared_ptr<const SourceText> SourceText::fromString(std::string text, std::string path) {
    std::shared_ptr<SourceText> source(new SourceText());
    source->m_path = std::move(path);
    source->m_encoding = detectEncoding(text);
    source->m_owned = source->m_encoding == Encoding::Utf8 ? std::move(text)
                                                           : toUtf8(text, source->m_encoding);
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
