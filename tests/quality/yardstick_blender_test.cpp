// taa-yardstick end to end on a reduced real render: Blender renders a small cycles_ball (then
// reuses it), taatool resolves it with --preset cycles, and the tables carry the SSAA rows,
// the equivalent spp and the temporal error; the contact sheet is written.
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "../blender/blender_tmpdir.h"
#include "yardstick_runner.h"

namespace {

using namespace taa::yardstick::test;

TEST(YardstickBlender, ReducedRealSceneEndToEnd) {
  const std::string work = std::string(TAA_TEST_TMPDIR) + "/real";
  std::filesystem::remove_all(work);
  taa::test::keepBlendersTemporaryFilesInTheTestFolder();
  const std::string arguments =
      "--scenes cycles_ball --size 64x36 --frames 1-6 --warmup 2 --blender-samples 16 "
      "--ssaa 2,4 --configs classic,default --render-cache " + work + "/cache --work " + work +
      " --doc " + work + "/QUALITY.md --command 'real yardstick under test'";
  const ToolRun first = runYardstick(arguments);
  ASSERT_EQ(first.exitCode, 0) << first.output;
  EXPECT_TRUE(contains(first.output, "cycles_ball: rendered")) << first.output;
  for (const char* row : {"| cycles_ball | raw |", "| cycles_ball | ssaa-2 |",
                          "| cycles_ball | ssaa-4 |", "| cycles_ball | classic |",
                          "| cycles_ball | default |"}) {
    EXPECT_TRUE(contains(first.output, row)) << row << "\n" << first.output;
  }
  // The SSAA rows are the rungs the equivalent spp is read on; the raw input is one sample.
  EXPECT_TRUE(contains(lineStartingWith(first.output, "| cycles_ball | raw |"), "| 1.0 |"))
      << first.output;
  EXPECT_TRUE(contains(lineStartingWith(first.output, "| cycles_ball | ssaa-4 |"), "| 4.0 |"))
      << first.output;
  EXPECT_TRUE(contains(first.output, "spp equivalent")) << first.output;

  const std::string page = readFile(work + "/QUALITY.md");
  EXPECT_TRUE(contains(page, "## Real renders (Blender Cycles)")) << page;
  EXPECT_TRUE(contains(page, "`real yardstick under test`")) << page;
  // The input rendered through the add-on: camera and jitter in each header, no sidecar.
  EXPECT_TRUE(contains(page, "read by taatool with `--preset cycles` and no other flag")) << page;
  const std::string sheet = work + "/quality/cycles_ball.png";
  auto png = OIIO::ImageInput::open(sheet);
  ASSERT_TRUE(png) << sheet;
  // Six tiles a row (32x18 crops of the 64x36 frame, labels above): raw, two SSAA rows, two
  // configurations, the truth and the error map make seven tiles, two rows.
  EXPECT_EQ(png->spec().width, 6 * (32 + 2));
  EXPECT_EQ(png->spec().height, 2 * (18 + 14 + 2));

  // A second run renders nothing.
  const ToolRun second = runYardstick(arguments);
  ASSERT_EQ(second.exitCode, 0) << second.output;
  EXPECT_TRUE(contains(second.output, "cycles_ball: cached")) << second.output;
}

}  // namespace
