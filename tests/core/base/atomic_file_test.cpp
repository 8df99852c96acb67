#include "core/base/atomic_file.h"

#include <filesystem>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace kerf
