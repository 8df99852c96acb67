#pragma once

#include <QDialog>
#include <filesystem>
#include <optional>

class QFileSystemModel;
class QLabel;
class QPushButton;
class QTreeView;

namespace kerf::ui {

// The file list of SEL PGM and CALL PGM ("Select file"): the NC root as a tree of folders and
// Klartext or DIN/ISO programs (.H, .I), nothing above the root. OK takes the selected program;
// a folder opens instead. Rows and buttons are touch sized.
class ProgramFileDialog : public QDialog {
    Q_OBJECT

public:
    ProgramFileDialog(const std::filesystem::path& ncRoot, const std::filesystem::path& folder,
                      QWidget* parent = nullptr);

    // Selects `path` when the tree shows it (the tree fills in the background: the folder must
    // have been read, see QFileSystemModel::directoryLoaded).
    bool selectPath(const std::filesystem::path& path);
    std::optional<std::filesystem::path> selectedPath() const;
    QTreeView* view() const { return m_view; }
    QFileSystemModel* model() const { return m_model; }
    QString message() const;

    void accept() override;

private:
    QFileSystemModel* m_model = nullptr;
    QTreeView* m_view = nullptr;
    QLabel* m_message = nullptr;
    QPushButton* m_ok = nullptr;
    QPushButton* m_cancel = nullptr;
};

}  // namespace kerf::ui
