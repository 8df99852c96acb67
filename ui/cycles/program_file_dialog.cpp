#include "ui/cycles/program_file_dialog.h"

#include <QFileSystemModel>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeView>
#include <QVBoxLayout>

#include "ui/cycles/dialog_parts.h"

namespace kerf::ui {

namespace fs = std::filesystem;

namespace {

QString pathText(const fs::path& path) {
    return QString::fromStdString(fs::absolute(path).lexically_normal().string());
}

}  // namespace

ProgramFileDialog::ProgramFileDialog(const fs::path& ncRoot, const fs::path& folder,
                                     QWidget* parent)
    : QDialog(parent) {
    setObjectName("programFileDialog");
    setWindowTitle(tr("Select file"));
    m_model = new QFileSystemModel(this);
    m_model->setReadOnly(true);
    m_model->setFilter(QDir::AllDirs | QDir::Files | QDir::NoDotAndDotDot);
    // Case-insensitive: "*.h" also lists "PART.H"; hidden, not greyed: only programs are offered.
    m_model->setNameFilters({QStringLiteral("*.h"), QStringLiteral("*.i")});
    m_model->setNameFilterDisables(false);
    const QString root = pathText(ncRoot);
    m_model->setRootPath(root);

    m_view = new QTreeView(this);
    m_view->setObjectName("programFileTree");
    m_view->setModel(m_model);
    m_view->setRootIndex(m_model->index(root));  // the tree does not go above the NC root
    for (int column = 1; column < m_model->columnCount(); ++column)
        m_view->setColumnHidden(column, column != 3);  // name and date, as the TNC lists them
    m_view->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_view->setUniformRowHeights(true);
    m_view->setStyleSheet(
        QStringLiteral("QTreeView::item { min-height: %1px; }").arg(kTouchHeight));
    m_view->setMinimumSize(560, 360);
    connect(m_view, &QTreeView::activated, this, [this](const QModelIndex& index) {
        if (!m_model->isDir(index)) accept();
    });
    if (!folder.empty()) {
        const QModelIndex start = m_model->index(pathText(folder));
        if (start.isValid()) {
            m_view->setCurrentIndex(start);
            m_view->expand(start);
        }
    }

    auto* layout = new QVBoxLayout(this);
    auto* rootLabel = new QLabel(tr("NC root: %1").arg(root), this);
    layout->addWidget(rootLabel);
    layout->addWidget(m_view, 1);
    m_message = addRefusalLine(*this, *layout, "programFileMessage");
    addOkCancel(*this, *layout, m_ok, m_cancel);
    m_ok->setText(tr("OK"));
    m_cancel->setText(tr("Cancel"));
}

bool ProgramFileDialog::selectPath(const fs::path& path) {
    const QModelIndex index = m_model->index(pathText(path));
    if (!index.isValid()) return false;
    m_view->setCurrentIndex(index);
    return true;
}

std::optional<fs::path> ProgramFileDialog::selectedPath() const {
    const QModelIndex index = m_view->currentIndex();
    if (!index.isValid()) return std::nullopt;
    return fs::path(m_model->filePath(index).toStdString());
}

QString ProgramFileDialog::message() const {
    return m_message->text();
}

void ProgramFileDialog::accept() {
    const QModelIndex index = m_view->currentIndex();
    if (!index.isValid() || m_model->isDir(index)) {
        m_message->setText(tr("Choose a program (.H or .I)"));
        if (index.isValid()) m_view->expand(index);
        return;
    }
    QDialog::accept();
}

}  // namespace kerf::ui
