#include "core/base/open_beneath.h"

#include <filesystem>
#include <fstream>

#include <fcntl.h>
#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "test_paths.h"

namespace kerf {
namespace {

namespace fs = std::filesystem;

class OpenBeneath : public testing::Test {
protected:
    void SetUp() override {
        dir = test::uniqueTempDir("beneath");
        fs::create_directories(dir / "root" / "sub");
        fs::create_directories(dir / "outside");
        std::ofstream(dir / "root" / "sub" / "f") << "inside";
        std::ofstream(dir / "outside" / "f") << "secret";
    }
    void TearDown() override { fs::remove_all(dir); }

    std::string readBelowRoot(const fs::path& relative) {
        auto fd = openBeneath(dir / "root", relative, O_RDONLY | O_NONBLOCK);
        if (!fd) return "refused";
        auto text = readOpenFile(fd->get(), relative);
        return text ? *text : "unreadable";
    }

    fs::path dir;
};

TEST_F(OpenBeneath, OpensAPlainNameBelowTheRoot) {
    EXPECT_EQ(readBelowRoot("sub/f"), "inside");
}

TEST_F(OpenBeneath, RefusesALinkAnywhereInTheName) {
    // The names were resolved earlier; a link that appears later is refused, wherever it points.
    fs::create_directory_symlink(dir / "outside", dir / "root" / "out");
    fs::create_directory_symlink("sub", dir / "root" / "alias");
    fs::create_symlink("sub/f", dir / "root" / "flink");
    EXPECT_EQ(readBelowRoot("out/f"), "refused");
    EXPECT_EQ(readBelowRoot("alias/f"), "refused");
    EXPECT_EQ(readBelowRoot("flink"), "refused");
}

TEST_F(OpenBeneath, RefusesClimbingOutOfTheRoot) {
    EXPECT_EQ(readBelowRoot("../outside/f"), "refused");
    EXPECT_EQ(readBelowRoot(dir / "outside" / "f"), "refused");  // absolute
}

}  // namespace
}  // namespace kerf
