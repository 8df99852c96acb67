#include "core/program/nc_root.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>
#include <sys/stat.h>

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

TEST_F(NcRootTest, AdmitsTheFinalNameOnlyInside) {
    NcRoot nc(root / "parts");
    const fs::path outside = root / "secret.H";
    std::ofstream(outside) << "secret";
    std::ofstream(root / "parts" / "inside.H") << "inside";
    fs::create_symlink("../secret.H", root / "parts" / "noext.H");
    fs::create_symlink("inside.H", root / "parts" / "alias.H");
    // The name a program wrote is inside; the one opened after adding ".H" leads out.
    EXPECT_TRUE(nc.resolve("noext", root / "parts").ok());
    EXPECT_TRUE(nc.admit(root / "parts" / "noext.H").has_value());
    EXPECT_FALSE(nc.read(root / "parts" / "noext.H").ok());
    EXPECT_FALSE(nc.admit(root / "parts" / "alias.H").has_value());
    auto text = nc.read(root / "parts" / "alias.H");
    ASSERT_TRUE(text.ok());
    EXPECT_EQ(*text, "inside");
}

TEST_F(NcRootTest, ADanglingLinkIsJudgedByItsTarget) {
    NcRoot nc(root / "parts");
    // Writing to this link would create root/created.txt, outside.
    fs::create_symlink("../created.txt", root / "parts" / "P000779.PIM");
    EXPECT_FALSE(nc.contains(root / "parts" / "P000779.PIM"));
    EXPECT_TRUE(nc.replace(root / "parts" / "P000779.PIM", "x").has_value());
    EXPECT_FALSE(fs::exists(root / "created.txt"));
    // A dangling link to a name inside is inside, but still not written through.
    fs::create_symlink("later.H", root / "parts" / "link.H");
    EXPECT_TRUE(nc.contains(root / "parts" / "link.H"));
    EXPECT_TRUE(nc.replace(root / "parts" / "link.H", "x").has_value());
    EXPECT_FALSE(fs::exists(root / "parts" / "later.H"));
}

TEST_F(NcRootTest, ReplacesRegularFilesAndRefusesOthers) {
    NcRoot nc(root / "parts");
    const fs::path file = root / "parts" / "OUT.TXT";
    EXPECT_FALSE(nc.replace(file, "one\n").has_value());
    EXPECT_FALSE(nc.replace(file, "two\n").has_value());
    EXPECT_EQ(*nc.read(file), "two\n");
    const fs::path fifo = root / "parts" / "fifo.H";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto read = nc.read(fifo);  // returns at once: nothing waits for a writer
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message().find("not a regular file"), std::string::npos);
    EXPECT_TRUE(nc.replace(fifo, "x").has_value());
    EXPECT_FALSE(nc.loadProgram(fifo).ok());
    EXPECT_TRUE(nc.replace(root / "parts" / "a", "x").has_value());  // a folder
}

TEST_F(NcRootTest, LoadedProgramSurvivesTheFileBeingTruncated) {
    NcRoot nc(root);
    const fs::path file = root / "P.H";
    std::ofstream(file) << "0 BEGIN PGM P MM\n1 END PGM P MM\n";
    auto program = nc.loadProgram(file);
    ASSERT_TRUE(program.ok());
    fs::resize_file(file, 0);
    EXPECT_EQ((*program)->text(), "0 BEGIN PGM P MM\n1 END PGM P MM\n");
}

TEST_F(NcRootTest, ALinkSwappedInAfterTheCheckIsNotFollowed) {
    // Another process swaps a folder of the root with a link to the outside, again and again,
    // while programs are read: a read either gets the file inside or is refused, never the
    // file outside (the check and the open are one step, not two).
    fs::create_directories(root / "outside");
    std::ofstream(root / "outside" / "P.H") << "secret";
    NcRoot nc(root / "parts");
    std::ofstream(root / "parts" / "a" / "P.H") << "inside";
    fs::create_directory_symlink(root / "outside", root / "parts" / "b");
    std::atomic<bool> stop{false};
    std::thread swapper([&] {
        const fs::path a = root / "parts" / "a";
        const fs::path b = root / "parts" / "b";
        const fs::path parked = root / "parts" / "parked";
        while (!stop) {
            std::rename(a.c_str(), parked.c_str());
            std::rename(b.c_str(), a.c_str());
            std::rename(parked.c_str(), b.c_str());
        }
    });
    int inside = 0;
    int leaked = 0;
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(1500);
    while (std::chrono::steady_clock::now() < end) {
        auto text = nc.read(root / "parts" / "a" / "P.H");
        if (text && *text == "secret") ++leaked;
        if (text && *text == "inside") ++inside;
    }
    stop = true;
    swapper.join();
    EXPECT_EQ(leaked, 0);
    EXPECT_GT(inside, 0);
}

}  // namespace
}  // namespace kerf::program
