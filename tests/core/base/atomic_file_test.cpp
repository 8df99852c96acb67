#include "core/base/atomic_file.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "test_paths.h"

namespace kerf {
namespace {

namespace fs = std::filesystem;

TEST(AtomicFile, ReplacesContentAndLeavesNoTemporary) {
    fs::path dir = test::uniqueTempDir("atomic");
    fs::path file = dir / "table.T";
    ASSERT_FALSE(writeFileAtomically(file, "first").has_value());
    ASSERT_FALSE(writeFileAtomically(file, "second\n").has_value());
    auto content = readWholeFile(file);
    ASSERT_TRUE(content.ok());
    EXPECT_EQ(*content, "second\n");
    int entries = 0;
    for ([[maybe_unused]] auto& entry : fs::directory_iterator(dir))
        ++entries;
    EXPECT_EQ(entries, 1);
    fs::remove_all(dir);
}

TEST(AtomicFile, ReportsMissingFolder) {
    auto error = writeFileAtomically("/nonexistent-kerf-dir/x.T", "x");
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(error->code, "io");
}

TEST(AtomicFile, RefusesFifosWithoutBlocking) {
    fs::path dir = test::uniqueTempDir("atomic_fifo");
    fs::path fifo = dir / "fifo.T";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto read = readWholeFile(fifo);  // a blocking open would wait here for a writer forever
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().message(), "'" + fifo.string() + "' is not a regular file");
    EXPECT_TRUE(writeFileAtomically(fifo, "x").has_value());
    EXPECT_FALSE(readWholeFile(dir).ok());
    fs::remove_all(dir);
}

TEST(AtomicFile, SameFileSeesThroughSpellingsAndLinks) {
    fs::path dir = test::uniqueTempDir("atomic_same");
    fs::create_directories(dir / "fr");
    ASSERT_FALSE(writeFileAtomically(dir / "fr" / "P.PIM", "x").has_value());
    ASSERT_FALSE(writeFileAtomically(dir / "fr" / "Q.PIM", "x").has_value());
    fs::create_symlink("P.PIM", dir / "fr" / "link.PIM");
    EXPECT_TRUE(sameFile(dir / "fr" / ".." / "fr" / "P.PIM", dir / "fr" / "P.PIM"));
    EXPECT_TRUE(sameFile(dir / "fr" / "link.PIM", dir / "fr" / "P.PIM"));
    EXPECT_FALSE(sameFile(dir / "fr" / "Q.PIM", dir / "fr" / "P.PIM"));
    EXPECT_FALSE(sameFile(dir / "fr" / "missing", dir / "fr" / "missing"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace kerf
