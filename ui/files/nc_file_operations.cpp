#include "ui/files/nc_file_operations.h"

#include <system_error>

#include "core/base/translate.h"

namespace kerf::ui {

namespace fs = std::filesystem;

namespace {

Diagnostic fileError(const fs::path& path, const char* messageTemplate, std::string detail = {}) {
    return Diagnostic::make(Severity::Error, "file", path.string(), 0, 0, messageTemplate,
                            std::move(detail));
}

bool sameFile(const fs::path& a, const fs::path& b) {
    std::error_code error;
    return fs::equivalent(a, b, error);
}

}  // namespace

NcFileOperations::NcFileOperations(fs::path root) : m_root(std::move(root)) {}

MaybeError NcFileOperations::requireInside(const fs::path& path) const {
    if (!m_root.contains(path))
        return fileError(path, KERF_TR_NOOP("the file is outside the NC root"));
    return std::nullopt;
}

MaybeError NcFileOperations::requireChangeable(const fs::path& path) const {
    if (auto error = requireInside(path)) return error;
    std::error_code ignored;
    if (!fs::exists(fs::symlink_status(path, ignored)))
        return fileError(path, KERF_TR_NOOP("the file does not exist"));
    if (sameFile(path, m_root.path()))
        return fileError(path, KERF_TR_NOOP("the NC root itself cannot be changed"));
    if (isProtected(path)) return fileError(path, KERF_TR_NOOP("the file is protected"));
    return std::nullopt;
}

Expected<fs::path> NcFileOperations::destination(const fs::path& source,
                                                 const fs::path& target) const {
    std::error_code ignored;
    const fs::path to = fs::is_directory(target, ignored) ? target / source.filename() : target;
    if (auto error = requireInside(to)) return *error;
    if (fs::exists(to, ignored))
        return fileError(to, KERF_TR_NOOP("a file with this name exists already"));
    return to;
}

Expected<fs::path> NcFileOperations::copy(const fs::path& source, const fs::path& target) const {
    if (auto error = requireInside(source)) return *error;
    auto to = destination(source, target);
    if (!to) return to;
    std::error_code error;
    fs::copy(source, *to, fs::copy_options::recursive, error);
    if (error) return fileError(*to, KERF_TR_NOOP("cannot copy: {1}"), error.message());
    return to;
}

Expected<fs::path> NcFileOperations::move(const fs::path& source, const fs::path& target) const {
    if (auto error = requireChangeable(source)) return *error;
    auto to = destination(source, target);
    if (!to) return to;
    std::error_code error;
    fs::rename(source, *to, error);
    if (error) return fileError(*to, KERF_TR_NOOP("cannot move: {1}"), error.message());
    return to;
}

Expected<fs::path> NcFileOperations::rename(const fs::path& source,
                                            std::string_view newName) const {
    if (newName.empty() || newName == "." || newName == ".." ||
        newName.find_first_of("/\\") != std::string_view::npos) {
        return fileError(source, KERF_TR_NOOP("'{1}' is not a valid file name"),
                         std::string(newName));
    }
    return move(source, source.parent_path() / std::string(newName));
}

MaybeError NcFileOperations::remove(const fs::path& path) const {
    if (auto error = requireChangeable(path)) return error;
    std::error_code error;
    fs::remove_all(path, error);
    if (error) return fileError(path, KERF_TR_NOOP("cannot delete: {1}"), error.message());
    return std::nullopt;
}

Expected<fs::path> NcFileOperations::makeFolder(const fs::path& parent,
                                                std::string_view name) const {
    if (name.empty() || name == "." || name == ".." ||
        name.find_first_of("/\\") != std::string_view::npos) {
        return fileError(parent, KERF_TR_NOOP("'{1}' is not a valid file name"), std::string(name));
    }
    const fs::path folder = parent / std::string(name);
    if (auto error = requireInside(folder)) return *error;
    std::error_code error;
    if (!fs::create_directory(folder, error)) {
        return fileError(folder, KERF_TR_NOOP("cannot create the folder: {1}"),
                         error ? error.message() : std::string("exists"));
    }
    return folder;
}

Expected<fs::path> NcFileOperations::createFile(const fs::path& folder, std::string_view name,
                                                std::string_view content) const {
    if (name.empty() || name == "." || name == ".." ||
        name.find_first_of("/\\") != std::string_view::npos) {
        return fileError(folder, KERF_TR_NOOP("'{1}' is not a valid file name"), std::string(name));
    }
    const fs::path file = folder / std::string(name);
    std::error_code error;
    if (fs::exists(fs::symlink_status(file, error)))
        return fileError(file, KERF_TR_NOOP("a file with this name exists already"));
    if (auto refused = m_root.replace(file, content)) return *refused;
    return file;
}

MaybeError NcFileOperations::setProtected(const fs::path& path, bool on) const {
    if (auto error = requireInside(path)) return error;
    std::error_code error;
    fs::permissions(path, fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                    on ? fs::perm_options::remove : fs::perm_options::add, error);
    if (!on)
        fs::permissions(path, fs::perms::group_write | fs::perms::others_write,
                        fs::perm_options::remove, error);
    if (error)
        return fileError(path, KERF_TR_NOOP("cannot change the protection: {1}"), error.message());
    return std::nullopt;
}

bool NcFileOperations::isProtected(const fs::path& path) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    return !error && (status.permissions() & fs::perms::owner_write) == fs::perms::none;
}

}  // namespace kerf::ui
