// Inputs checked instead of silently wrong (issue 24), the helpers: a single file's frame
// number from its name, a pattern that matches nothing says where it looked and what is near,
// a Blender multilayer file read without its preset gets a hint, a projection that carries the
// jitter is recognised and corrected.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>

#include "io/frame_reader.h"
#include "io/layout_hint.h"
#include "io/nearest_files.h"
#include "io/sequence_scan.h"
#include "resolve/projection_jitter.h"
#include "test_files.h"

namespace taa {
namespace {

namespace fs = std::filesystem;
using test::contains;

TEST(InputChecks, FrameNumberFromASingleFilesName) {
  EXPECT_EQ(io::frameNumberInFileName("/shots/shot.0001.exr"), 1);
  EXPECT_EQ(io::frameNumberInFileName("beauty_1001.exr"), 1001);
  EXPECT_EQ(io::frameNumberInFileName("sh010.comp.-0005.exr"), -5);
  EXPECT_EQ(io::frameNumberInFileName("a/b.12/shot.0042.exr"), 42);
  EXPECT_EQ(io::frameNumberInFileName("shot.exr"), std::nullopt);
  EXPECT_EQ(io::frameNumberInFileName("take2.exr"), std::nullopt);   // part of a word
  EXPECT_EQ(io::frameNumberInFileName("0001.exr"), std::nullopt);    // no separator before
  EXPECT_EQ(io::frameNumberInFileName("shot.0001"), std::nullopt);   // no extension after
  EXPECT_EQ(io::frameNumberInFileName("shot.99999999999.exr"), std::nullopt);  // beyond int
}

TEST(InputChecks, APatternThatMatchesNothingSaysWhereItLookedAndWhatIsNear) {
  const std::string folder = test::scratchFolder();
  for (int f = 1; f <= 24; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "/render_%04d.exr", f);
    test::writeTextFile(folder + name, "");
  }
  test::writeTextFile(folder + "/render.json", "{}");
  test::writeTextFile(folder + "/notes.txt", "");
  const std::string text = io::patternMissText(folder + "/render.####.exr");
  EXPECT_TRUE(contains(text, "looked in " + fs::path(folder).lexically_normal().string() +
                                 " for names like render.0001.exr (#### = the frame number)"))
      << text;
  EXPECT_TRUE(contains(text, "nearest there: render_0001.exr .. render_0024.exr (24 files), "
                             "render.json, notes.txt"))
      << text;

  const std::string single = io::patternMissText(folder + "/render_001.exr");
  EXPECT_TRUE(contains(single, "for render_001.exr; nearest there: render_0001.exr")) << single;

  const std::string gone = io::patternMissText(folder + "/no/such/render.####.exr");
  EXPECT_TRUE(contains(gone, "the folder " + folder + "/no/such does not exist (the nearest "
                             "folder above it that does: " + folder + ")"))
      << gone;
  fs::create_directories(folder + "/empty");
  EXPECT_TRUE(contains(io::patternMissText(folder + "/empty/r.#.exr"), "holds no files"));
}

OIIO::ImageSpec blenderHeader(const std::vector<std::string>& channels) {
  OIIO::ImageSpec spec = test::makeSpec(4, 4, channels);
  spec.attribute("BlenderMultiChannel", "Blender V2.55.1 and newer");
  return spec;
}

TEST(InputChecks, ABlenderFileWithoutItsPresetGetsAHint) {
  const std::vector<std::string> channels = {"RL.Combined.R", "RL.Combined.G", "RL.Combined.B",
                                             "RL.Combined.A", "RL.Depth.Z", "RL.Vector.X"};
  std::string hint = io::layoutHint(blenderHeader(channels), {"R", "G", "B"});
  EXPECT_TRUE(contains(hint, "the header says Blender wrote it (BlenderMultiChannel): --preset "
                             "cycles reads its Combined, Depth and Vector passes (view layer RL; "
                             "add --layer RL)"))
      << hint;
  hint = io::layoutHint(blenderHeader(channels), {"ViewLayer.Combined.R"});
  EXPECT_TRUE(contains(hint, "the file's view layer RL: --layer RL names it")) << hint;
  // Not Blender's, or Blender's with the layer right: nothing to add.
  EXPECT_EQ(io::layoutHint(test::makeSpec(4, 4, channels), {"R"}), "");
  EXPECT_EQ(io::layoutHint(blenderHeader(channels), {"RL.Vector.Y"}), "");

  // readFrame puts the hint into its missing-channel error.
  const std::string path = test::scratchFolder() + "/render.exr";
  test::writeImage(path, blenderHeader(channels), std::vector<float>(4 * 4 * channels.size()));
  io::AovLayout layout;
  layout.color = {path, {"R", "G", "B", "A"}, ""};
  const Error error = test::errorOf([&] { io::readFrame(layout, 1); });
  EXPECT_TRUE(contains(error.what(), "lacks channels R, G, B; the header says Blender wrote it"))
      << error.what();
}

// A camera 5 units from the origin looking at it, as the sidecar and note hold it after
// conversion (+z forward, OpenGL NDC), with `shift` pixels of principal point offset.
FrameCamera glCamera(const RasterWindow& window, glm::dvec2 shift) {
  glm::dmat4 projection =
      glm::perspective(glm::radians(40.0), double(window.displayWidth) / window.displayHeight,
                       0.1, 100.0);
  glm::dmat4 jitter(1.0);
  jitter[3][0] = 2.0 * shift.x / window.displayWidth;
  jitter[3][1] = -2.0 * shift.y / window.displayHeight;
  glm::dmat4 view = glm::lookAt(glm::dvec3(1, 2, 5), glm::dvec3(0), glm::dvec3(0, 1, 0));
  glm::dmat4 flipZ(1.0);
  flipZ[2][2] = -1.0;
  return {flipZ * view, jitter * projection * view};
}

TEST(InputChecks, AProjectionCarryingTheJitterIsRecognisedAndCorrected) {
  const RasterWindow window{3, 2, 64, 36};  // a data window inside the display window
  const glm::vec2 jitter(0.3125f, -0.2f);
  const FrameCamera clean = glCamera(window, {0, 0});
  const FrameCamera jittered = glCamera(window, glm::dvec2(jitter));
  const glm::dvec2 offset =
      principalPointOffset(jittered, window, NdcConvention::MinusOneOneYUp);
  EXPECT_NEAR(offset.x, jitter.x, 1e-9);
  EXPECT_NEAR(offset.y, jitter.y, 1e-9);

  const auto corrected =
      withoutJitterInProjection(jittered, jitter, window, NdcConvention::MinusOneOneYUp);
  ASSERT_TRUE(corrected);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(corrected->worldToNdc[c][r], clean.worldToNdc[c][r], 1e-12) << c << r;
    }
  }
  // A clean projection, another frame's jitter, a zero jitter: left alone.
  EXPECT_FALSE(withoutJitterInProjection(clean, jitter, window, NdcConvention::MinusOneOneYUp));
  EXPECT_FALSE(withoutJitterInProjection(jittered, glm::vec2(0.1f, 0.4f), window,
                                         NdcConvention::MinusOneOneYUp));
  EXPECT_FALSE(withoutJitterInProjection(clean, glm::vec2(0.0f), window,
                                         NdcConvention::MinusOneOneYUp));

  // The same camera in EXR's NDC convention ([0, 1], y down).
  glm::dmat4 toZeroOne(1.0);
  toZeroOne[0][0] = 0.5;
  toZeroOne[3][0] = 0.5;
  toZeroOne[1][1] = -0.5;
  toZeroOne[3][1] = 0.5;
  FrameCamera exr = jittered;
  exr.worldToNdc = toZeroOne * jittered.worldToNdc;
  const glm::dvec2 exrOffset = principalPointOffset(exr, window, NdcConvention::ZeroOneYDown);
  EXPECT_NEAR(exrOffset.x, jitter.x, 1e-9);
  EXPECT_NEAR(exrOffset.y, jitter.y, 1e-9);
  EXPECT_TRUE(withoutJitterInProjection(exr, jitter, window, NdcConvention::ZeroOneYDown));
}

}  // namespace
}  // namespace taa
