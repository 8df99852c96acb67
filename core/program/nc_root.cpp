#include "core/program/nc_root.h"

#include <algorithm>
#include <string>

#include <fcntl.h>

#include "core/base/atomic_file.h"
#include "core/base/open_beneath.h"

namespace kerf::program {

namespace fs = std::filesystem;

namespace {

bool startsWithNoCase(std::string_view text, std::string_view prefix) {
    if (text.size() < prefix.size()) return false;
    for (size_t i = 0; i < prefix.size(); ++i) {
        char a = text[i];
        if (a >= 'a' && a <= 'z') a = static_cast<char>(a - 'a' + 'A');
        if (a != prefix[i]) return false;
    }
    return true;
}

}  // namespace

namespace {

// weakly_canonical without exceptions: on an error (a name too long, a loop of links) the
// lexically normal path stands in, which contains() then judges by its text.
fs::path canonicalOrNormal(const fs::path& path) {
    std::error_code error;
    fs::path absolute = fs::absolute(path, error);
    if (error) return path.lexically_normal();
    fs::path real = fs::weakly_canonical(absolute, error);
    return error ? absolute.lexically_normal() : real;
}

// The path with every link resolved. weakly_canonical stops at the first name that does not
// exist, and a dangling link does not "exist": it would be judged by its own name although
// writing to it creates its target. So a link left in the canonical path is followed by hand.
fs::path withLinksResolved(const fs::path& path) {
    constexpr int kMaxLinks = 40;  // as the kernel's ELOOP limit
    fs::path current = canonicalOrNormal(path);
    for (int hops = 0; hops < kMaxLinks; ++hops) {
        fs::path prefix;
        fs::path followed;
        for (auto it = current.begin(); it != current.end(); ++it) {
            prefix /= *it;
            std::error_code ignored;
            if (!followed.empty()) {
                followed /= *it;
            } else if (fs::is_symlink(fs::symlink_status(prefix, ignored))) {
                fs::path target = fs::read_symlink(prefix, ignored);
                followed = target.is_absolute() ? target : prefix.parent_path() / target;
            }
        }
        if (followed.empty()) return current;
        current = canonicalOrNormal(followed);
    }
    return current;  // a loop of links: nothing can be opened through it anyway
}

Diagnostic pathError(const char* messageTemplate, const fs::path& path) {
    return Diagnostic::make(Severity::Error, "path", path.string(), 0, 0, messageTemplate,
                            path.string());
}

}  // namespace

NcRoot::NcRoot(fs::path root) : m_root(canonicalOrNormal(root)) {}

bool NcRoot::contains(const fs::path& path) const {
    fs::path real = withLinksResolved(path);
    auto rootIt = m_root.begin();
    auto it = real.begin();
    for (; rootIt != m_root.end(); ++rootIt, ++it) {
        if (rootIt->empty()) continue;  // trailing separator
        if (it == real.end() || *it != *rootIt) return false;
    }
    return true;
}

MaybeError NcRoot::admit(const fs::path& finalPath) const {
    if (!contains(finalPath)) {
        return pathError(KERF_TR_NOOP("'{1}' is outside the NC root"), finalPath);
    }
    return std::nullopt;
}

Expected<FileDescriptor> NcRoot::openResolved(const fs::path& finalPath, int flags) const {
    // The name with its links resolved is opened without following any link and without
    // leaving the root: a link swapped in after contains() judged the name is refused.
    const fs::path real = withLinksResolved(finalPath);
    if (!contains(real)) return pathError(KERF_TR_NOOP("'{1}' is outside the NC root"), finalPath);
    return openBeneath(m_root, real.lexically_relative(m_root), flags);
}

Expected<std::string> NcRoot::read(const fs::path& finalPath) const {
    auto fd = openResolved(finalPath, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    if (!fd) return fd.error();
    return readOpenFile(fd->get(), finalPath);
}

Expected<std::shared_ptr<const SourceText>> NcRoot::loadProgram(const fs::path& finalPath) const {
    auto bytes = read(finalPath);
    if (!bytes) return bytes.error();
    return SourceText::fromString(std::move(*bytes), finalPath.string());
}

MaybeError NcRoot::admitWrite(const fs::path& finalPath) const {
    if (MaybeError refused = admit(finalPath)) return refused;
    std::error_code ignored;
    const fs::file_status status = fs::symlink_status(finalPath, ignored);
    if (fs::is_symlink(status)) {
        return pathError(KERF_TR_NOOP("'{1}' is a link: Kerf does not write through links"),
                         finalPath);
    }
    if (fs::exists(status) && !fs::is_regular_file(status)) return notRegular(finalPath);
    return std::nullopt;
}

MaybeError NcRoot::replace(const fs::path& finalPath, std::string_view content) const {
    if (MaybeError refused = admitWrite(finalPath)) return refused;
    const fs::path parent = finalPath.has_parent_path() ? finalPath.parent_path() : fs::path(".");
    auto folder = openResolved(parent, O_RDONLY | O_DIRECTORY);
    if (!folder) return folder.error();
    return writeFileAtomicallyAt(folder->get(), finalPath.filename().string(), finalPath, content);
}

Expected<fs::path> NcRoot::resolve(std::string_view name, const fs::path& callerFolder) const {
    std::string text(name);
    // Trim blanks and quotes that some programs put around names.
    auto notTrim = [](char c) { return c != ' ' && c != '\t' && c != '"' && c != '\''; };
    text.erase(text.begin(), std::find_if(text.begin(), text.end(), notTrim));
    text.erase(std::find_if(text.rbegin(), text.rend(), notTrim).base(), text.end());
    std::replace(text.begin(), text.end(), '\\', '/');
    fs::path base = callerFolder.empty() ? m_root : callerFolder;
    if (startsWithNoCase(text, "TNC:")) {
        text.erase(0, 4);
        base = m_root;
    }
    if (!text.empty() && text.front() == '/') base = m_root;
    while (!text.empty() && text.front() == '/')
        text.erase(0, 1);
    if (text.empty()) {
        return Diagnostic::make(Severity::Error, "path", "", 0, 0, KERF_TR_NOOP("empty file name"));
    }
    fs::path resolved = (base / text).lexically_normal();
    if (!contains(resolved)) {
        return Diagnostic::make(Severity::Error, "path", "", 0, 0,
                                KERF_TR_NOOP("'{1}' is outside the NC root"), std::string(name));
    }
    return resolved;
}

}  // namespace kerf::program
