#include "core/program/source_text.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

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

// Validates a mapped file chunk by chunk and releases each chunk after it, so that checking a
// large program does not make it resident all at once.
bool isValidUtf8InChunks(std::string_view bytes, void* mapping) {
    constexpr size_t kChunk = 8u << 20;
    const auto page = static_cast<size_t>(::sysconf(_SC_PAGESIZE));
    size_t start = 0;
    while (start < bytes.size()) {
        size_t end = std::min(bytes.size(), start + kChunk);
        // Do not split a multi-byte character between chunks.
        while (end < bytes.size() && end > start &&
               (static_cast<unsigned char>(bytes[end]) & 0xC0) == 0x80) {
            --end;
        }
        if (!isValidUtf8(bytes.substr(start, end - start))) return false;
        if (end / page * page > 0) ::madvise(mapping, end / page * page, MADV_DONTNEED);
        start = end;
    }
    return true;
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
    source->m_encoding =
        isValidUtf8InChunks(bytes, source->m_mapping) ? Encoding::Utf8 : detectEncoding(bytes);
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
    source->m_owned =
        source->m_encoding == Encoding::Utf8 ? std::move(text) : toUtf8(text, source->m_encoding);
    source->m_view = withoutBom(source->m_owned);
    return source;
}

void SourceText::releaseBefore(size_t offset) const {
    if (m_mapping == nullptr) return;
    const auto page = static_cast<size_t>(::sysconf(_SC_PAGESIZE));
    const size_t begin = static_cast<size_t>(m_view.data() - static_cast<const char*>(m_mapping));
    const size_t end = std::min(begin + offset, m_mappingSize) / page * page;
    if (end > 0) ::madvise(m_mapping, end, MADV_DONTNEED);
}

uint32_t columnOf(std::string_view line, size_t byteOffset) {
    uint32_t column = 1;
    for (size_t i = 0; i < byteOffset && i < line.size(); ++i) {
        if ((static_cast<unsigned char>(line[i]) & 0xC0) != 0x80) ++column;
    }
    return column;
}

}  // namespace kerf::program
