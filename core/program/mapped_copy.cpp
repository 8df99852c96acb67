#include "core/program/mapped_copy.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <mutex>
#include <vector>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/sendfile.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/base/open_beneath.h"

namespace kerf::program {

namespace {

// The live copies, so that releasing pages never touches memory that is not a mapped copy
// (MADV_DONTNEED would zero a heap string).
std::mutex g_mappedMutex;
std::vector<std::string_view> g_mapped;

bool copyAll(int from, int to) {
    off_t offset = 0;
    for (;;) {
        const ssize_t n = ::sendfile(to, from, &offset, size_t{1} << 30);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return false;
        if (n == 0) return true;  // read to the end, also when the file grew meanwhile
    }
}

}  // namespace

std::optional<std::string_view> mapUnnamedCopy(const std::filesystem::path& file) {
    // O_NONBLOCK: a FIFO must not block the open; it is not regular and is left to the caller.
    FileDescriptor fd(::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY));
    struct stat original {};
    if (fd.get() < 0 || ::fstat(fd.get(), &original) != 0 || !S_ISREG(original.st_mode) ||
        static_cast<size_t>(original.st_size) < kMappedCopyMinBytes) {
        return std::nullopt;
    }
    const std::filesystem::path folder = file.parent_path();
    const std::filesystem::path where = folder.empty() ? std::filesystem::path(".") : folder;
    FileDescriptor copy(::open(where.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600));
    if (copy.get() < 0 || !copyAll(fd.get(), copy.get())) return std::nullopt;
    struct stat info {};
    if (::fstat(copy.get(), &info) != 0 || info.st_size == 0) return std::nullopt;
    const auto size = static_cast<size_t>(info.st_size);
    void* data = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, copy.get(), 0);
    if (data == MAP_FAILED) return std::nullopt;
    // The mapping keeps the unnamed file alive; its blocks are freed when it is unmapped.
    const std::string_view mapped(static_cast<const char*>(data), size);
    std::lock_guard lock(g_mappedMutex);
    g_mapped.push_back(mapped);
    return mapped;
}

void unmapCopy(std::string_view mapped) {
    {
        std::lock_guard lock(g_mappedMutex);
        std::erase_if(g_mapped, [&](std::string_view m) { return m.data() == mapped.data(); });
    }
    ::munmap(const_cast<char*>(mapped.data()), mapped.size());
}

void releasePagesBefore(std::string_view text, size_t offset) {
    const auto start = reinterpret_cast<uintptr_t>(text.data());
    bool mapped = false;
    {
        std::lock_guard lock(g_mappedMutex);
        mapped = std::any_of(g_mapped.begin(), g_mapped.end(), [&](std::string_view m) {
            const auto begin = reinterpret_cast<uintptr_t>(m.data());
            return start >= begin && start < begin + m.size();
        });
    }
    if (!mapped) return;
    static const auto page = static_cast<uintptr_t>(::sysconf(_SC_PAGESIZE));
    const uintptr_t from = start / page * page;
    const uintptr_t to = (start + std::min(offset, text.size())) / page * page;
    // Pages of a read-only private file mapping are never changed, so dropping them loses
    // nothing: the next read faults them in from the copy again.
    if (to > from) ::madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
}

}  // namespace kerf::program
