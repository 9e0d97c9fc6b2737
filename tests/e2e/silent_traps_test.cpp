// End-to-end: inputs checked instead of silently wrong (issue 24). Each trap was measured on a
// new user's first hour; each test here failed before its fix.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <vector>

#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

using test::frameName;
using test::ToolRun;

constexpr int kFrames = 5;

std::vector<float> readPixels(const fs::path& path, OIIO::ImageSpec* header = nullptr) {
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << path;
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  if (header) *header = spec;
  std::vector<float> pixels(spec.image_pixels() * std::size_t(spec.nchannels));
  EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, pixels.data()));
  return pixels;
}

float maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
  EXPECT_EQ(a.size(), b.size());
  float worst = 0.0f;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    worst = std::max(worst, std::abs(a[i] - b[i]));
  }
  return worst;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class SilentTrapsTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::freshTestFolder(); }

  // The 3D scene with a yawing camera: headers hold worldToCamera/worldToNDC and taa:jitter.
  fs::path cameraScene() {
    const fs::path in = dir_ / "in";
    test::writeSeparateFrames(in, 1, kFrames, 48, 32, "rotate_yaw");
    return in;
  }

  ToolRun run(const fs::path& in, const std::string& out, std::vector<std::string> extra) const {
    std::vector<std::string> args = test::separateFileArgs(in, dir_ / out / "r.####.exr");
    args.insert(args.end(), {"-d", "float"});
    args.insert(args.end(), extra.begin(), extra.end());
    return test::runTaatool(args, dir_);
  }
  void runOk(const fs::path& in, const std::string& out, std::vector<std::string> extra) const {
    const ToolRun r = run(in, out, std::move(extra));
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  float difference(const std::string& a, const std::string& b, int frame) const {
    return maxDifference(readPixels(dir_ / a / frameName("r", frame)),
                         readPixels(dir_ / b / frameName("r", frame)));
  }

  // A sidecar with the scene's cameras as OpenGL view and projection (the projection with
  // `jitterInProjection` of each frame's jitter in it: Blender's calc_matrix_camera on a
  // jittered frame gives that), and each frame's `jitter` unless it is empty.
  void writeSidecar(const fs::path& in, const fs::path& path, bool withMatrices,
                    bool jitterInProjection, std::optional<std::array<float, 2>> jitter) {
    std::ofstream json(path);
    json << std::setprecision(9) << "{\"frames\": {";
    for (int f = 1; f <= kFrames; ++f) {
      OIIO::ImageSpec spec;
      readPixels(in / frameName("beauty", f), &spec);
      const auto* toCamera = spec.find_attribute("worldToCamera", OIIO::TypeMatrix44);
      const auto* toNdc = spec.find_attribute("worldToNDC", OIIO::TypeMatrix44);
      ASSERT_TRUE(toCamera && toNdc);
      const float* headerJitter = static_cast<const float*>(spec.find_attribute("taa:jitter")->data());
      const std::array<float, 2> j = jitter.value_or(std::array<float, 2>{headerJitter[0],
                                                                           headerJitter[1]});
      json << (f > 1 ? ", " : "") << "\"" << f << "\": {\"jitter\": [" << j[0] << ", " << j[1]
           << "]";
      if (withMatrices) {
        glm::dmat4 flipZ(1.0), toGlNdc(1.0), shift(1.0);
        flipZ[2][2] = -1.0;
        toGlNdc[0][0] = 2.0;
        toGlNdc[3][0] = -1.0;
        toGlNdc[1][1] = -2.0;
        toGlNdc[3][1] = 1.0;
        if (jitterInProjection) {  // clip-space translation by (2 jx / W, -2 jy / H)
          shift[3][0] = 2.0 * j[0] / spec.full_width;
          shift[3][1] = -2.0 * j[1] / spec.full_height;
        }
        const glm::dmat4 view =
            flipZ * glm::dmat4(glm::make_mat4(static_cast<const float*>(toCamera->data())));
        const glm::dmat4 projection =
            shift * toGlNdc * glm::dmat4(glm::make_mat4(static_cast<const float*>(toNdc->data()))) *
            glm::inverse(view);
        json << ", \"view\": [";
        for (int i = 0; i < 16; ++i) json << (i ? ", " : "") << glm::value_ptr(view)[i];
        json << "], \"projection\": [";
        for (int i = 0; i < 16; ++i) json << (i ? ", " : "") << glm::value_ptr(projection)[i];
        json << "]";
      }
      json << "}";
    }
    json << "}}";
  }

  fs::path dir_;
};

// The sidecar's jitter was ignored unless --jitter sidecar was given too: with a sidecar that
// holds one, it is the jitter, and --jitter only overrides it.
TEST_F(SilentTrapsTest, TheSidecarsJitterIsUsedWheneverItHasOne) {
  const fs::path in = cameraScene();
  const std::string sidecar = (dir_ / "jitter.json").string();
  writeSidecar(in, sidecar, false, false, std::array<float, 2>{0.3f, -0.2f});
  runOk(in, "auto", {"--camera-sidecar", sidecar});
  runOk(in, "explicit", {"--camera-sidecar", sidecar, "--jitter", "sidecar"});
  runOk(in, "halton", {"--camera-sidecar", sidecar, "--jitter", "halton"});
  for (int f = 1; f <= kFrames; ++f) {
    EXPECT_EQ(difference("auto", "explicit", f), 0.0f) << f;
    EXPECT_GT(difference("auto", "halton", f), 1e-3f) << f;  // the jitter matters here
  }
  const ToolRun verbose = run(in, "verbose", {"--camera-sidecar", sidecar, "-v"});
  EXPECT_TRUE(contains(verbose.err, "jitter from the camera sidecar")) << verbose.err;
}

// A projection that carries the frame's jitter counted it twice (0.4 dB on a Cycles shot):
// recognised, taken out with a warning (the result is the clean projection's), refused with
// --strict.
TEST_F(SilentTrapsTest, AProjectionCarryingTheJitterIsCorrectedAndSaid) {
  const fs::path in = cameraScene();
  const std::string clean = (dir_ / "clean.json").string();
  const std::string jittered = (dir_ / "jittered.json").string();
  writeSidecar(in, clean, true, false, std::nullopt);
  writeSidecar(in, jittered, true, true, std::nullopt);
  runOk(in, "clean", {"--camera-sidecar", clean});
  const ToolRun corrected = run(in, "corrected", {"--camera-sidecar", jittered});
  ASSERT_EQ(corrected.exitCode, 0) << corrected.err;
  EXPECT_TRUE(contains(corrected.err, "taatool WARNING: took the jitter out of the camera's "
                                      "projection in 5 frames (first: frame 1, "))
      << corrected.err;
  for (int f = 1; f <= kFrames; ++f) {
    EXPECT_LE(difference("clean", "corrected", f), 2e-4f) << f;
  }
  EXPECT_FALSE(contains(run(in, "clean2", {"--camera-sidecar", clean}).err, "took the jitter"));
  test::expectToolError(run(in, "strict", {"--camera-sidecar", jittered, "--strict"}),
                        {"the camera's projection carries the frame's jitter", "(--strict)",
                         "frame 1"});
}

// Window mode without camera matrices carries samples along vectors only, which costs
// quality; it was said only under -v. Now a warning says it and what it costs.
TEST_F(SilentTrapsTest, MissingCameraInWindowModeIsAWarningWithItsCost) {
  test::writeSeparateFrames(dir_ / "flat", 1, 3);  // the 2D scene: no matrices
  const ToolRun noCamera = run(dir_ / "flat", "out", {});
  ASSERT_EQ(noCamera.exitCode, 0) << noCamera.err;
  EXPECT_TRUE(contains(noCamera.err, "taatool WARNING: no camera matrices (header, camera note or "
                                     "--camera-sidecar) in 3 frames (first: frame 1, "))
      << noCamera.err;
  EXPECT_TRUE(contains(noCamera.err, "23.8 dB against 25.1 with the camera")) << noCamera.err;
  EXPECT_FALSE(contains(run(dir_ / "flat", "q", {"-q"}).err, "WARNING"));
  EXPECT_FALSE(contains(run(dir_ / "flat", "h", {"--mode", "history"}).err, "camera matrices"));
  const fs::path in = cameraScene();
  EXPECT_FALSE(contains(run(in, "cam", {}).err, "camera matrices"));
}

// A single file was resolved as frame 0 (Halton index 0): its name says which frame it is.
TEST_F(SilentTrapsTest, ASingleFilesFrameNumberComesFromItsName) {
  test::writeSeparateFrames(dir_ / "in", 1, 3);
  const fs::path single = dir_ / "single";
  fs::create_directories(single);
  for (const char* stem : {"beauty", "depth", "motion"}) {
    fs::copy_file(dir_ / "in" / frameName(stem, 3), single / ("shot_" + std::string(stem) + ".0003.exr"));
  }
  const ToolRun one = test::runTaatool(
      {(single / "shot_beauty.0003.exr").string(), "--depth",
       (single / "shot_depth.0003.exr").string(), "--motion",
       (single / "shot_motion.0003.exr").string(), "--mode", "history", "-d", "float", "-o",
       (dir_ / "one.exr").string()},
      dir_);
  ASSERT_EQ(one.exitCode, 0) << one.err;
  runOk(dir_ / "in", "seq", {"--mode", "history", "--frames", "3"});
  EXPECT_EQ(maxDifference(readPixels(dir_ / "one.exr"), readPixels(dir_ / "seq" / "r.0003.exr")),
            0.0f);
}

// A Blender multilayer file read without --preset cycles listed its channels and no hint.
TEST_F(SilentTrapsTest, ABlenderFileWithoutThePresetGetsAHint) {
  const std::vector<std::string> names = {"ViewLayer.Combined.R", "ViewLayer.Combined.G",
                                          "ViewLayer.Combined.B", "ViewLayer.Combined.A",
                                          "ViewLayer.Depth.Z",    "ViewLayer.Vector.X",
                                          "ViewLayer.Vector.Y"};
  OIIO::ImageSpec spec(8, 8, int(names.size()), OIIO::TypeFloat);
  spec.channelnames = names;
  spec.attribute("BlenderMultiChannel", "Blender V2.55.1 and newer");
  const std::string path = (dir_ / "render.0001.exr").string();
  auto out = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(out && out->open(path, spec));
  std::vector<float> pixels(8 * 8 * names.size(), 0.5f);
  ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
  ASSERT_TRUE(out->close());
  test::expectToolError(
      test::runTaatool({(dir_ / "render.####.exr").string(), "-o",
                        (dir_ / "out.####.exr").string()},
                       dir_),
      {"lacks channels R, G, B", "Blender wrote it (BlenderMultiChannel): --preset cycles reads",
       "view layer ViewLayer"});
}

// --layer without --preset cycles was silently ignored.
TEST_F(SilentTrapsTest, AnOptionWithoutEffectIsAnError) {
  test::writeSeparateFrames(dir_ / "in", 1, 2);
  test::expectToolError(run(dir_ / "in", "out", {"--layer", "RenderLayer"}),
                        {"--layer has no effect without --preset cycles"});
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// "no frames found for the color pattern" said neither where it looked nor what was there.
TEST_F(SilentTrapsTest, APatternThatMatchesNothingSaysWhatItTriedAndWhatIsNear) {
  test::writeSeparateFrames(dir_ / "in", 1, 3);
  const ToolRun r = test::runTaatool(
      {(dir_ / "in" / "beauty_####.exr").string(), "-o", (dir_ / "out.####.exr").string()},
      dir_);
  test::expectToolError(
      r, {"no frames found for the color pattern: looked in " + (dir_ / "in").string() +
              " for names like beauty_0001.exr (#### = the frame number); nearest there: "
              "beauty.0001.exr .. beauty.0003.exr (3 files)"});
  const ToolRun single = test::runTaatool(
      {(dir_ / "in" / "beauty.001.exr").string(), "-o", (dir_ / "out.exr").string()}, dir_);
  test::expectToolError(single, {"missing input frame", "nearest there: beauty.0001.exr"});
}

}  // namespace
}  // namespace taa
