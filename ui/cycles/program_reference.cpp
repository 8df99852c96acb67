#include "ui/cycles/program_reference.h"

#include "core/base/atomic_file.h"
#include "core/base/translate.h"
#include "core/program/nc_root.h"
#include "ui/common/diagnostic_text.h"

namespace kerf::ui {

namespace fs = std::filesystem;

namespace {

// `path` below `base` ("SUB/PART.H"), or empty when it is not below it.
fs::path below(const fs::path& path, const fs::path& base) {
    const fs::path relative = path.lexically_relative(base);
    if (relative.empty() || *relative.begin() == "..") return {};
    return relative;
}

QString withBackslashes(const fs::path& relative) {
    return QString::fromStdString(relative.generic_string())
        .replace(QLatin1Char('/'), QLatin1Char('\\'));
}

ProgramReference refused(const Diagnostic& why) {
    return {{}, translatedMessage(why)};
}

}  // namespace

ProgramReference programReference(const fs::path& chosen, const ProgramPlace& place) {
    const fs::path root = fs::absolute(place.ncRoot).lexically_normal();
    const fs::path file = fs::absolute(chosen).lexically_normal();
    const fs::path inRoot = below(file, root);
    // The name must lie in the root (it is written relative to it), and so must the file its
    // links lead to (the interpreter would refuse it).
    if (inRoot.empty())
        return refused(Diagnostic::make(Severity::Error, "path", file.string(), 0, 0,
                                        KERF_TR_NOOP("'{1}' is outside the NC root"),
                                        file.string()));
    if (const MaybeError outside = program::NcRoot(root).admit(file)) return refused(*outside);
    std::error_code error;
    if (!fs::is_regular_file(file, error)) return refused(notRegular(file));
    const fs::path folder =
        place.folder.empty() ? root : fs::absolute(place.folder).lexically_normal();
    if (const fs::path relative = below(file, folder); !relative.empty())
        return {withBackslashes(relative), {}};
    return {QStringLiteral("TNC:\\") + withBackslashes(inRoot), {}};
}

}  // namespace kerf::ui
