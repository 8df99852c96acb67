#include "ui/files/file_manager.h"

#include <QSignalSpy>
#include <fstream>

#include <gtest/gtest.h>

#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/common/diagnostic_text.h"

namespace kerf::ui {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& path, const std::string& text = "x\n") {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
}

// A root with a program, a subfolder and, beside the root, a file that must stay out of reach.
struct Tree {
    fs::path base;
    fs::path root;
    explicit Tree(const std::string& name)
        : base(kerf::test::uniqueTempDir(name)), root(base / "root") {
        touch(root / "PART.H");
        touch(root / "sub" / "TOOL.T");
        touch(base / "outside.txt", "secret\n");
    }
};

TEST(NcFileOperations, CopyMoveRenameDeleteInsideTheRoot) {
    Tree tree("hmi_files_ops");
    NcFileOperations files(tree.root);
    auto copied = files.copy(tree.root / "PART.H", tree.root / "sub");
    ASSERT_TRUE(copied) << copied.error().format();
    EXPECT_EQ(*copied, tree.root / "sub" / "PART.H");
    EXPECT_TRUE(fs::exists(tree.root / "PART.H"));
    auto renamed = files.rename(tree.root / "sub" / "PART.H", "COPY.H");
    ASSERT_TRUE(renamed);
    EXPECT_TRUE(fs::exists(tree.root / "sub" / "COPY.H"));
    auto moved = files.move(tree.root / "sub" / "COPY.H", tree.root);
    ASSERT_TRUE(moved);
    EXPECT_TRUE(fs::exists(tree.root / "COPY.H"));
    EXPECT_FALSE(fs::exists(tree.root / "sub" / "COPY.H"));
    EXPECT_FALSE(files.remove(tree.root / "COPY.H").has_value());
    EXPECT_FALSE(fs::exists(tree.root / "COPY.H"));
}

TEST(NcFileOperations, NothingLeavesTheRoot) {
    Tree tree("hmi_files_sandbox");
    NcFileOperations files(tree.root);
    EXPECT_FALSE(files.copy(tree.root / "PART.H", tree.base));
    EXPECT_FALSE(files.copy(tree.root / "PART.H", tree.root / ".." / "PART.H"));
    EXPECT_FALSE(files.copy(tree.base / "outside.txt", tree.root));
    EXPECT_FALSE(files.move(tree.root / "PART.H", tree.base));
    EXPECT_FALSE(files.rename(tree.root / "PART.H", "../PART.H"));
    EXPECT_FALSE(files.rename(tree.root / "PART.H", ".."));
    EXPECT_TRUE(files.remove(tree.base / "outside.txt").has_value());
    EXPECT_TRUE(files.remove(tree.root).has_value());
    // A link inside the root that points out of it does not open a way out.
    fs::create_directory_symlink(tree.base, tree.root / "escape");
    EXPECT_FALSE(files.copy(tree.root / "PART.H", tree.root / "escape"));
    EXPECT_TRUE(fs::exists(tree.base / "outside.txt"));
    EXPECT_TRUE(fs::exists(tree.root / "PART.H"));
    EXPECT_FALSE(fs::exists(tree.base / "PART.H"));
}

TEST(NcFileOperations, ProtectedFilesCannotBeChanged) {
    Tree tree("hmi_files_protect");
    NcFileOperations files(tree.root);
    ASSERT_FALSE(files.setProtected(tree.root / "PART.H", true).has_value());
    EXPECT_TRUE(NcFileOperations::isProtected(tree.root / "PART.H"));
    const auto refused = files.remove(tree.root / "PART.H");
    ASSERT_TRUE(refused.has_value());
    EXPECT_EQ(refused->messageTemplate, "the file is protected");
    EXPECT_FALSE(files.rename(tree.root / "PART.H", "NEW.H"));
    EXPECT_TRUE(files.copy(tree.root / "PART.H", tree.root / "sub"));  // reading is allowed
    ASSERT_FALSE(files.setProtected(tree.root / "PART.H", false).has_value());
    EXPECT_FALSE(files.remove(tree.root / "PART.H").has_value());
}

TEST(FileManager, DeleteAsksFirst) {
    test::testApp();
    Tree tree("hmi_files_widget");
    FileManager manager(tree.root);
    QStringList questions;
    bool answer = false;
    manager.setPrompts({[&](const QString& q) {
                            questions << q;
                            return answer;
                        },
                        nullptr});
    ASSERT_TRUE(manager.selectPath(tree.root / "PART.H"));
    EXPECT_FALSE(manager.deleteSelected());
    EXPECT_TRUE(fs::exists(tree.root / "PART.H"));
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].contains("PART.H"));
    answer = true;
    EXPECT_TRUE(manager.deleteSelected());
    EXPECT_FALSE(fs::exists(tree.root / "PART.H"));
}

TEST(FileManager, RenameFailureIsReportedAndOpenIsRemembered) {
    test::testApp();
    Tree tree("hmi_files_rename");
    FileManager manager(tree.root);
    manager.setPrompts(
        {nullptr, [](const QString&, const QString&) { return std::optional<QString>("a/b.H"); }});
    QSignalSpy messages(&manager, &FileManager::message);
    QSignalSpy opened(&manager, &FileManager::openRequested);
    ASSERT_TRUE(manager.selectPath(tree.root / "PART.H"));
    EXPECT_FALSE(manager.renameSelected());
    ASSERT_EQ(messages.count(), 1);
    EXPECT_EQ(messages.at(0).at(0).value<Severity>(), Severity::Error);
    EXPECT_FALSE(manager.selectPath(tree.base / "outside.txt"));
    ASSERT_TRUE(manager.openSelected());
    ASSERT_EQ(opened.count(), 1);
    EXPECT_EQ(manager.recentFiles(),
              QStringList{QString::fromStdString((tree.root / "PART.H").string())});
}

}  // namespace
}  // namespace kerf::ui
