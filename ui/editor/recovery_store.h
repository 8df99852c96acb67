#pragma once

#include <QString>
#include <filesystem>
#include <optional>

#include "core/base/expected.h"

namespace kerf::ui {

// Autosave copies of programs being edited, kept in a folder of their own so that a crash or a
// power cut loses at most the last few seconds of typing. One file per program, named after a
// hash of the program's path; its first line names the program, the rest is the unsaved text.
class RecoveryStore {
public:
    explicit RecoveryStore(std::filesystem::path folder);

    const std::filesystem::path& folder() const { return m_folder; }
    std::filesystem::path recoveryFile(const std::filesystem::path& program) const;

    // Written atomically: a crash while autosaving keeps the previous copy.
    MaybeError store(const std::filesystem::path& program, const QString& text) const;
    // The unsaved text of `program`, if a copy exists and belongs to it.
    std::optional<QString> recover(const std::filesystem::path& program) const;
    // After a save or when the operator discards the copy.
    void discard(const std::filesystem::path& program) const;

private:
    std::filesystem::path m_folder;
};

}  // namespace kerf::ui
