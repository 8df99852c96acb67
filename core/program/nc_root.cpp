#include "core/program/nc_root.h"

#include <algorithm>
#include <string>

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

}  // namespace

NcRoot::NcRoot(fs::path root) : m_root(canonicalOrNormal(root)) {}

bool NcRoot::contains(const fs::path& path) const {
    fs::path real = canonicalOrNormal(path);
    auto rootIt = m_root.begin();
    auto it = real.begin();
    for (; rootIt != m_root.end(); ++rootIt, ++it) {
        if (rootIt->empty()) continue;  // trailing separator
        if (it == real.end() || *it != *rootIt) return false;
    }
    return true;
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
