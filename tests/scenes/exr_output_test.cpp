// Both output layouts read back through OIIO with the names and conventions taa expects.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "scene_test_util.h"
#include "scenegen/exr_output.h"
#include "taa/error.h"

namespace taa::scenes::test {
namespace {

constexpr int kWidth = 64, kHeight = 36, kFrame = 7;

SceneFrame renderSmallFrame() {
  const auto scene = makeLayeredScene("moving_object", kWidth, kHeight);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 2;
  return scene->render(kFrame, settings);
}

// Checks that `plane` holds channel c of `image`, each value passed through `expected`.
template <typename Map>
void expectPlane(const ExrPlanes& file, const std::string& name, const Image& image, int c,
                 Map expected) {
  const auto found = file.planes.find(name);
  ASSERT_NE(found, file.planes.end()) << "no channel " << name;
  ASSERT_EQ(file.width, image.width);
  ASSERT_EQ(file.height, image.height);
  for (int j = 0; j < image.height; ++j) {
    for (int i = 0; i < image.width; ++i) {
      ASSERT_EQ(found->second[std::size_t(j) * image.width + i], expected(image.at(i, j)[c]))
          << name << " at " << i << "," << j;
    }
  }
}

float same(float v) { return v; }

std::vector<std::string> channelNames(const ExrPlanes& file) {
  std::vector<std::string> names;
  for (const auto& entry : file.planes) names.push_back(entry.first);
  return names;
}

TEST(SceneExrOutput, FramePathsArePadded) {
  EXPECT_EQ(framePath("out", "beauty", 7), "out/beauty.0007.exr");
  EXPECT_EQ(framePath("out", "depth", 12345), "out/depth.12345.exr");
}

TEST(SceneExrOutput, SeparateLayoutReadsBack) {
  const SceneFrame frame = renderSmallFrame();
  const std::string dir = freshTempDir("separate");
  writeFrame(frame, "moving_object", OutputLayout::Separate, dir);

  const ExrPlanes beauty = readExr(framePath(dir, "beauty", kFrame));
  EXPECT_EQ(channelNames(beauty), (std::vector<std::string>{"A", "B", "G", "R"}));
  EXPECT_EQ(beauty.compression, "zip");
  const char* rgba[] = {"R", "G", "B", "A"};
  const ExrPlanes truth = readExr(framePath(dir, "truth", kFrame));
  for (int c = 0; c < 4; ++c) {
    expectPlane(beauty, rgba[c], frame.color, c, same);
    expectPlane(truth, rgba[c], frame.truth, c, same);
  }
  const ExrPlanes depth = readExr(framePath(dir, "depth", kFrame));
  EXPECT_EQ(channelNames(depth), (std::vector<std::string>{"Z"}));
  expectPlane(depth, "Z", frame.depth, 0, same);
  const ExrPlanes motion = readExr(framePath(dir, "motion", kFrame));
  EXPECT_EQ(channelNames(motion), (std::vector<std::string>{"X", "Y"}));
  expectPlane(motion, "X", frame.motion, 0, same);
  expectPlane(motion, "Y", frame.motion, 1, same);
  EXPECT_FALSE(std::filesystem::exists(framePath(dir, "render", kFrame)));
}

TEST(SceneExrOutput, HeaderCarriesJitter) {
  const SceneFrame frame = renderSmallFrame();
  const std::string dir = freshTempDir("header");
  writeFrame(frame, "moving_object", OutputLayout::Separate, dir);
  auto input = OIIO::ImageInput::open(framePath(dir, "beauty", kFrame));
  ASSERT_TRUE(input);
  const OIIO::ParamValue* jitter = input->spec().find_attribute("taa:jitter");
  ASSERT_NE(jitter, nullptr);
  ASSERT_EQ(jitter->type(), OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::VEC2));
  const float* values = static_cast<const float*>(jitter->data());
  EXPECT_EQ(values[0], frame.jitter.x);
  EXPECT_EQ(values[1], frame.jitter.y);
}

TEST(SceneExrOutput, CyclesLayoutReadsBack) {
  const SceneFrame frame = renderSmallFrame();
  const std::string dir = freshTempDir("cycles");
  writeFrame(frame, "moving_object", OutputLayout::Cycles, dir);

  const ExrPlanes render = readExr(framePath(dir, "render", kFrame));
  EXPECT_EQ(channelNames(render),
            (std::vector<std::string>{
                "ViewLayer.Combined.A", "ViewLayer.Combined.B", "ViewLayer.Combined.G",
                "ViewLayer.Combined.R", "ViewLayer.Depth.Z", "ViewLayer.Vector.W",
                "ViewLayer.Vector.X", "ViewLayer.Vector.Y", "ViewLayer.Vector.Z"}));
  const char* rgba[] = {"R", "G", "B", "A"};
  const ExrPlanes truth = readExr(framePath(dir, "truth", kFrame));
  for (int c = 0; c < 4; ++c) {
    expectPlane(render, std::string("ViewLayer.Combined.") + rgba[c], frame.color, c, same);
    expectPlane(truth, rgba[c], frame.truth, c, same);
  }
  expectPlane(render, "ViewLayer.Depth.Z", frame.depth, 0, same);
  // Cycles vectors are y up: (X, Y) = previous - current, (Z, W) = current - next.
  auto negate = [](float v) { return -v; };
  expectPlane(render, "ViewLayer.Vector.X", frame.motion, 0, same);
  expectPlane(render, "ViewLayer.Vector.Y", frame.motion, 1, negate);
  expectPlane(render, "ViewLayer.Vector.Z", frame.nextMotion, 0, negate);
  expectPlane(render, "ViewLayer.Vector.W", frame.nextMotion, 1, same);
  // The object moves right and down (y down), so its previous position is left and up (y up).
  const std::size_t centre = std::size_t(kHeight / 2) * kWidth + kWidth / 2;
  EXPECT_LT(render.planes.at("ViewLayer.Vector.X")[centre], 0.0f);
  EXPECT_GT(render.planes.at("ViewLayer.Vector.Y")[centre], 0.0f);
  EXPECT_FALSE(std::filesystem::exists(framePath(dir, "beauty", kFrame)));
}

TEST(SceneExrOutput, CyclesWritesNoHitAs1e10) {
  SceneFrame frame = renderSmallFrame();
  frame.depth.at(3, 2)[0] = std::numeric_limits<float>::infinity();
  const std::string dir = freshTempDir("cycles_nohit");
  writeFrame(frame, "moving_object", OutputLayout::Cycles, dir);
  writeFrame(frame, "moving_object", OutputLayout::Separate, dir);
  const ExrPlanes render = readExr(framePath(dir, "render", kFrame));
  EXPECT_EQ(render.planes.at("ViewLayer.Depth.Z")[2 * kWidth + 3], 1e10f);
  const ExrPlanes depth = readExr(framePath(dir, "depth", kFrame));
  EXPECT_TRUE(std::isinf(depth.planes.at("Z")[2 * kWidth + 3]));
}

TEST(SceneExrOutput, UnwritableFolderThrows) {
  const SceneFrame frame = renderSmallFrame();
  const std::string dir = freshTempDir("blocked");
  const std::string file = dir + "/not_a_folder";
  { std::ofstream(file) << "x"; }
  EXPECT_THROW(writeFrame(frame, "moving_object", OutputLayout::Separate, file + "/out"),
               taa::Error);
}

}  // namespace
}  // namespace taa::scenes::test
