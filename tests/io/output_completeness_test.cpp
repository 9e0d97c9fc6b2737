// Whether an output frame on disk is complete (issue 17, defect 7: the farm step counted a file
// cut short after it was written as complete because its header opened).
#include "io/output_completeness.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "io/exr_writer.h"
#include "test_files.h"

namespace taa::io {
namespace {

namespace fs = std::filesystem;

using taa::test::contains;
using taa::test::makeSpec;
using taa::test::scratchFolder;
using taa::test::writeImage;

// A frame as the sequence job writes it: taa:version and taa:options in the header, noisy
// pixels so that compression leaves many blocks to cut.
std::string writeTaaFrame(const std::string& folder, const std::string& options = "blend=0.04") {
  const std::string path = folder + "/r.0001.exr";
  Image rgba(64, 64, 4);
  for (std::size_t i = 0; i < rgba.pixels.size(); ++i) rgba.pixels[i] = float(i % 97) / 13.0f;
  OIIO::ImageSpec spec = makeSpec(64, 64, {"R", "G", "B", "A"});
  spec.attribute("taa:version", "0.1.0");
  spec.attribute("taa:options", options);
  writeExrAtomic(path, rgba, spec, WriteOptions(PixelType::Half, "zip"));
  return path;
}

TEST(OutputCompleteness, AWholeFrameIsComplete) {
  const std::string path = writeTaaFrame(scratchFolder());
  const OutputCheck check = checkOutputComplete(path);
  EXPECT_TRUE(check.complete) << check.reason;
  EXPECT_TRUE(checkOutputComplete(path, "blend=0.04").complete);
}

TEST(OutputCompleteness, AFrameCutShortIsNotEvenThoughItsHeaderOpens) {
  const std::string path = writeTaaFrame(scratchFolder());
  fs::resize_file(path, fs::file_size(path) * 2 / 3);
  ASSERT_TRUE(OIIO::ImageInput::open(path));  // what the farm script checked
  const OutputCheck check = checkOutputComplete(path);
  EXPECT_FALSE(check.complete);
  EXPECT_TRUE(contains(check.reason, "truncated or corrupt")) << check.reason;
}

TEST(OutputCompleteness, MissingForeignAndOtherOptionsAreNotThisJobsOutput) {
  const std::string folder = scratchFolder();
  EXPECT_EQ(checkOutputComplete(folder + "/none.exr").reason, "missing");
  writeImage(folder + "/plain.exr", makeSpec(4, 3, {"R", "G", "B", "A"}),
             std::vector<float>(48, 0.5f));
  EXPECT_TRUE(contains(checkOutputComplete(folder + "/plain.exr").reason, "taa:version"));
  const std::string path = writeTaaFrame(folder, "blend=0.1");
  EXPECT_TRUE(contains(checkOutputComplete(path, "blend=0.04").reason, "other options"));
  taa::test::writeTextFile(folder + "/text.exr", "not an image");
  EXPECT_FALSE(checkOutputComplete(folder + "/text.exr").complete);
}

}  // namespace
}  // namespace taa::io
