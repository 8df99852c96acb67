#include "ui/files/file_manager.h"

#include <QComboBox>
#include <QEvent>
#include <QFileSystemModel>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QTreeView>
#include <QVBoxLayout>

#include "ui/common/diagnostic_text.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxRecent = 10;

QString pathText(const fs::path& path) {
    return QString::fromStdString(path.string());
}

}  // namespace

FileManager::FileManager(fs::path root, QWidget* parent)
    : QWidget(parent), m_operations(std::move(root)) {
    setObjectName("fileManager");
    registerDiagnosticMetaTypes();
    qRegisterMetaType<std::filesystem::path>();
    m_model = new QFileSystemModel(this);
    m_model->setReadOnly(true);  // every change goes through NcFileOperations
    m_model->setNameFilterDisables(false);
    m_model->setFilter(QDir::AllDirs | QDir::Files | QDir::NoDotAndDotDot);
    const QString rootPath = pathText(m_operations.root().path());
    m_model->setRootPath(rootPath);

    m_view = new QTreeView(this);
    m_view->setObjectName("fileTree");
    m_view->setModel(m_model);
    m_view->setRootIndex(m_model->index(rootPath));
    m_view->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_view->setUniformRowHeights(true);
    makeTouchSizedRows(*m_view);
    connect(m_view, &QTreeView::activated, this, [this] { openSelected(); });

    m_filter = new QComboBox(this);
    m_filter->setObjectName("fileFilter");
    m_filter->setMinimumHeight(kTouchHeight);
    m_filter->addItems({QString(), QString(), QString()});
    makeTouchSizedRows(*m_filter);
    connect(m_filter, qOverload<int>(&QComboBox::currentIndexChanged), this,
            [this](int index) { setFilter(static_cast<Filter>(index)); });

    m_recentList = new QListWidget(this);
    m_recentList->setObjectName("recentFiles");
    m_recentList->setMaximumWidth(320);
    makeTouchSizedRows(*m_recentList);
    connect(m_recentList, &QListWidget::itemActivated, this, [this](QListWidgetItem* item) {
        emit openRequested(fs::path(item->data(Qt::UserRole).toString().toStdString()));
    });

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* top = new QHBoxLayout();
    m_rootLabel = new QLabel(this);
    top->addWidget(m_rootLabel, 1);
    top->addWidget(m_filter);
    layout->addLayout(top);
    auto* body = new QHBoxLayout();
    body->addWidget(m_view, 1);
    auto* side = new QVBoxLayout();
    m_recentLabel = new QLabel(this);
    side->addWidget(m_recentLabel);
    side->addWidget(m_recentList, 1);
    body->addLayout(side);
    layout->addLayout(body, 1);
    retranslate();
}

void FileManager::retranslate() {
    m_filter->setItemText(0, tr("All files"));
    m_filter->setItemText(1, tr("Programs (.H .I .PIT)"));
    m_filter->setItemText(2, tr("Tables (.T .TCH .PR .D .PNT .TP .TAB)"));
    m_rootLabel->setText(tr("NC root: %1").arg(pathText(m_operations.root().path())));
    m_recentLabel->setText(tr("Recent files"));
}

void FileManager::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

void FileManager::setFilter(Filter filter) {
    QStringList patterns;
    if (filter == Filter::Programs) patterns = QStringList{"*.h", "*.i", "*.pit"};
    if (filter == Filter::Tables)
        patterns = QStringList{"*.t", "*.tch", "*.pr", "*.d", "*.pnt", "*.tp", "*.tab"};
    // QFileSystemModel matches name filters case-insensitively: "*.h" also finds "PART.H".
    m_model->setNameFilters(patterns);
    if (m_filter->currentIndex() != static_cast<int>(filter))
        m_filter->setCurrentIndex(static_cast<int>(filter));
}

bool FileManager::selectPath(const fs::path& path) {
    if (!m_operations.root().contains(path)) return false;
    const QModelIndex index = m_model->index(pathText(path));
    if (!index.isValid()) return false;
    m_view->setCurrentIndex(index);
    return true;
}

std::optional<fs::path> FileManager::selectedPath() const {
    const QModelIndex index = m_view->currentIndex();
    if (!index.isValid()) return std::nullopt;
    return fs::path(m_model->filePath(index).toStdString());
}

bool FileManager::report(const MaybeError& error) {
    if (!error) return true;
    emit message(Severity::Error, QStringLiteral("%1: %2").arg(QString::fromStdString(error->file),
                                                               translatedMessage(*error)));
    return false;
}

std::optional<QString> FileManager::ask(const QString& question, const QString& initial) const {
    if (m_prompts.askText) return m_prompts.askText(question, initial);
    return askTextTouch(const_cast<FileManager*>(this), tr("File manager"), question, initial);
}

fs::path FileManager::resolveAnswer(const QString& answer, const fs::path& folder) const {
    // "/sub/NAME" is relative to the root, "NAME" to the folder of the selected file.
    const std::string text = answer.trimmed().toStdString();
    if (!text.empty() && (text.front() == '/' || text.front() == '\\')) {
        return (m_operations.root().path() / text.substr(1)).lexically_normal();
    }
    return (folder / text).lexically_normal();
}

bool FileManager::openSelected() {
    const auto path = selectedPath();
    if (!path || fs::is_directory(*path)) return false;
    addRecent(*path);
    emit openRequested(*path);
    return true;
}

bool FileManager::copySelected() {
    const auto path = selectedPath();
    if (!path) return false;
    const auto answer =
        ask(tr("Copy %1 to:").arg(pathText(path->filename())), pathText(path->filename()));
    if (!answer) return false;
    auto copied = m_operations.copy(*path, resolveAnswer(*answer, path->parent_path()));
    if (!copied) return report(copied.error());
    emit message(Severity::Note, tr("Copied to %1").arg(pathText(*copied)));
    return true;
}

bool FileManager::moveSelected() {
    const auto path = selectedPath();
    if (!path) return false;
    const auto answer =
        ask(tr("Move %1 to folder:").arg(pathText(path->filename())), QStringLiteral("/"));
    if (!answer) return false;
    auto moved = m_operations.move(*path, resolveAnswer(*answer, path->parent_path()));
    if (!moved) return report(moved.error());
    return true;
}

bool FileManager::renameSelected() {
    const auto path = selectedPath();
    if (!path) return false;
    const auto answer =
        ask(tr("New name for %1:").arg(pathText(path->filename())), pathText(path->filename()));
    if (!answer) return false;
    auto renamed = m_operations.rename(*path, answer->trimmed().toStdString());
    if (!renamed) return report(renamed.error());
    return true;
}

bool FileManager::deleteSelected() {
    const auto path = selectedPath();
    if (!path) return false;
    const QString question = tr("Delete %1?").arg(pathText(path->filename()));
    const bool confirmed = m_prompts.confirm ? m_prompts.confirm(question)
                                             : confirmTouch(this, tr("File manager"), question);
    if (!confirmed) return false;
    return report(m_operations.remove(*path));
}

bool FileManager::toggleProtection() {
    const auto path = selectedPath();
    if (!path) return false;
    return report(m_operations.setProtected(*path, !NcFileOperations::isProtected(*path)));
}

fs::path FileManager::currentFolder() const {
    auto folder = selectedPath().value_or(m_operations.root().path());
    if (!fs::is_directory(folder)) folder = folder.parent_path();
    return folder;
}

bool FileManager::newFolder() {
    const fs::path folder = currentFolder();
    const auto answer = ask(tr("Name of the new folder:"), QString());
    if (!answer) return false;
    auto made = m_operations.makeFolder(folder, answer->trimmed().toStdString());
    if (!made) return report(made.error());
    return true;
}

void FileManager::addRecent(const fs::path& path) {
    const QString text = pathText(path);
    m_recent.removeAll(text);
    m_recent.prepend(text);
    while (m_recent.size() > kMaxRecent)
        m_recent.removeLast();
    m_recentList->clear();
    for (const QString& file : m_recent) {
        // Shown relative to the root, which is where the operator thinks the files are.
        const fs::path relative =
            fs::path(file.toStdString()).lexically_relative(m_operations.root().path());
        auto* item = new QListWidgetItem(
            QString::fromStdString(relative.empty() ? file.toStdString() : relative.string()));
        item->setData(Qt::UserRole, file);
        m_recentList->addItem(item);
    }
}

}  // namespace kerf::ui
