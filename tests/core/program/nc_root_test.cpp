#include "core/program/nc_root.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "test_paths.h"

namespace kerf::program {
namespace {

namespace fs = std::filesystem;

class NcRootTest : public testing::Test {
protected:
    void SetUp() override {
        root = test::uniqueTempDir("ncroot");
        fs::create_directories(root / "parts" / "a");
    }
    void TearDown() override { fs::remove_all(root); }
    fs::path root;
};

TEST_F(NcRootTest, ResolvesTncAndRelativeNames) {
    NcRoot nc(root);
    auto a = nc.resolve("TNC:\\parts\\a\\P.H", root / "x");
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(*a, nc.path() / "parts" / "a" / "P.H");
    auto b = nc.resolve("SUB.H", root / "parts");
    ASSERT_TRUE(b.ok());
    EXPECT_EQ(*b, nc.path() / "parts" / "SUB.H");
    auto c = nc.resolve("..\\B.H", root / "parts" / "a");
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(*c, nc.path() / "parts" / "B.H");
    auto d = nc.resolve("\\TOP.H", root / "parts");
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(*d, nc.path() / "TOP.H");
}

TEST_F(NcRootTest, RefusesEverythingOutside) {
    NcRoot nc(root);
    EXPECT_FALSE(nc.resolve("../../etc/passwd", root / "parts").ok());
    EXPECT_FALSE(nc.resolve("TNC:\\..\\x.H", root).ok());
    EXPECT_FALSE(nc.resolve("", root).ok());
    // A symbolic link that points outside the root does not help either.
    fs::create_directory_symlink("/tmp", root / "escape");
    EXPECT_FALSE(nc.resolve("escape/x.H", root).ok());
}

}  // namespace
}  // namespace kerf::program
