// Tool length touch-off on the mill: the new L makes the display show the known surface.
#include "core/task/tool_length_touch_off.h"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/base/atomic_file.h"
#include "core/tables/tool_table.h"

namespace kerf::task {
namespace {

namespace fs = std::filesystem;

class ToolLengthTouchOffTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_touch_off_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path dir;
};

TEST_F(ToolLengthTouchOffTest, TheToolIsLongerByWhatTheDisplayShowsAboveTheSurface) {
    writeFileAtomically(dir / "TOOL.T",
                        "BEGIN TOOL.T MM\nT    NAME   L         R         DL\n"
                        "1    MILL   +50       +5        +0.02\n[END]\n");
    // The tip rests on the workpiece top (Z 0) while the display, with L + DL = 50.02, shows
    // Z +0.3: the real tool is 0.3 longer; L becomes 50.3, the wear DL stays.
    const auto length = touchOffToolLength(dir, {1, 0.3, 0.0});
    ASSERT_TRUE(length) << length.error().format();
    EXPECT_NEAR(*length, 50.3, 1e-9);
    const auto tools = tables::ToolTable::load(dir / "TOOL.T");
    ASSERT_TRUE(tools);
    EXPECT_NEAR(tools->byNumber(1)->length, 50.3, 1e-9);
    EXPECT_NEAR(tools->byNumber(1)->deltaLength, 0.02, 1e-9);
    // On a gauge block 25 high the display shows 24.9: 0.1 shorter.
    ASSERT_TRUE(touchOffToolLength(dir, {1, 24.9, 25.0}));
    EXPECT_NEAR(tables::ToolTable::load(dir / "TOOL.T")->byNumber(1)->length, 50.2, 1e-9);
}

TEST_F(ToolLengthTouchOffTest, NoToolNoTableOrAnUnknownToolIsAnError) {
    EXPECT_FALSE(touchOffToolLength(dir, {-1, 0.0, 0.0}));
    EXPECT_FALSE(touchOffToolLength(dir, {1, 0.0, 0.0}));  // no TOOL.T
    writeFileAtomically(dir / "TOOL.T", "BEGIN TOOL.T MM\nT    NAME   L\n1    A   +50\n[END]\n");
    const auto missing = touchOffToolLength(dir, {7, 0.0, 0.0});
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().format().find("tool 7"), std::string::npos)
        << missing.error().format();
}

}  // namespace
}  // namespace kerf::task
