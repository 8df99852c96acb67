#include "ui/editor/recovery_store.h"

#include <QCryptographicHash>
#include <system_error>

#include "core/base/atomic_file.h"

namespace kerf::ui {

namespace {

constexpr std::string_view kMagic = "KERF-RECOVERY ";

}  // namespace

RecoveryStore::RecoveryStore(std::filesystem::path folder) : m_folder(std::move(folder)) {}

std::filesystem::path RecoveryStore::recoveryFile(const std::filesystem::path& program) const {
    const QByteArray key =
        QByteArray::fromStdString(std::filesystem::absolute(program).lexically_normal().string());
    const QByteArray hash =
        QCryptographicHash::hash(key, QCryptographicHash::Sha1).toHex().left(16);
    return m_folder / (program.filename().string() + "." + hash.toStdString() + ".autosave");
}

MaybeError RecoveryStore::store(const std::filesystem::path& program, const QString& text) const {
    std::error_code error;
    std::filesystem::create_directories(m_folder, error);
    std::string content(kMagic);
    content += std::filesystem::absolute(program).lexically_normal().string();
    content += '\n';
    content += text.toStdString();
    return writeFileAtomically(recoveryFile(program), content);
}

std::optional<QString> RecoveryStore::recover(const std::filesystem::path& program) const {
    const auto content = readWholeFile(recoveryFile(program));
    if (!content) return std::nullopt;
    const std::string_view view = *content;
    const size_t newline = view.find('\n');
    if (view.substr(0, kMagic.size()) != kMagic || newline == std::string_view::npos)
        return std::nullopt;
    const std::string_view owner = view.substr(kMagic.size(), newline - kMagic.size());
    if (owner != std::filesystem::absolute(program).lexically_normal().string())
        return std::nullopt;
    const std::string_view text = view.substr(newline + 1);
    return QString::fromUtf8(text.data(), static_cast<int>(text.size()));
}

void RecoveryStore::discard(const std::filesystem::path& program) const {
    std::error_code error;
    std::filesystem::remove(recoveryFile(program), error);
}

}  // namespace kerf::ui
