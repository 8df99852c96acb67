#pragma once

#include <QString>
#include <QStringList>
#include <QWidget>
#include <filesystem>
#include <functional>
#include <optional>

#include "core/base/diagnostic.h"
#include "ui/files/nc_file_operations.h"

class QComboBox;
class QFileSystemModel;
class QLabel;
class QListWidget;
class QTreeView;

namespace kerf::ui {

// The file manager page: the NC root as a tree with type filters, recent files, and copy,
// move, rename, delete (after confirmation) and protection through NcFileOperations, so no
// operation leaves the root. The questions it asks go through replaceable prompts so that tests
// and touch dialogs can answer them.
class FileManager : public QWidget {
    Q_OBJECT

public:
    struct Prompts {
        std::function<bool(const QString& question)> confirm;
        std::function<std::optional<QString>(const QString& question, const QString& initial)>
            askText;
    };

    enum class Filter { All, Programs, Tables };

    explicit FileManager(std::filesystem::path root, QWidget* parent = nullptr);

    void setPrompts(Prompts prompts) { m_prompts = std::move(prompts); }
    void setFilter(Filter filter);

    bool selectPath(const std::filesystem::path& path);
    std::optional<std::filesystem::path> selectedPath() const;

    // Each works on the selected entry; false if nothing happened (refused, cancelled, failed:
    // failures are reported through message()).
    bool openSelected();
    bool copySelected();    // asks for the new name (or a folder inside the root)
    bool moveSelected();    // asks for the target folder, relative to the root
    bool renameSelected();  // asks for the new name
    bool deleteSelected();  // asks for confirmation
    bool toggleProtection();
    bool newFolder();
    // Where new files go: the selected folder, the folder of the selected file, or the root.
    std::filesystem::path currentFolder()
        const;  // asks for the name; created in the selected folder (or the root)

    QStringList recentFiles() const { return m_recent; }
    void addRecent(const std::filesystem::path& path);
    QTreeView* view() const { return m_view; }

protected:
    void changeEvent(QEvent* event) override;

signals:
    void openRequested(const std::filesystem::path& path);
    void message(kerf::Severity severity, const QString& text);

private:
    void retranslate();
    bool report(const MaybeError& error);
    std::optional<QString> ask(const QString& question, const QString& initial) const;
    std::filesystem::path resolveAnswer(const QString& answer,
                                        const std::filesystem::path& folder) const;

    NcFileOperations m_operations;
    Prompts m_prompts;
    QFileSystemModel* m_model = nullptr;
    QTreeView* m_view = nullptr;
    QComboBox* m_filter = nullptr;
    QListWidget* m_recentList = nullptr;
    QLabel* m_rootLabel = nullptr;
    QLabel* m_recentLabel = nullptr;
    QStringList m_recent;
};

}  // namespace kerf::ui

Q_DECLARE_METATYPE(std::filesystem::path)
