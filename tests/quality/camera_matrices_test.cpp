// The 3D scenes' files agree with themselves: pixel centres of static geometry, unprojected by
// their depth and the frame's header matrices and projected by the previous frame's, land
// where the motion vectors say. The matrices are read back from the written EXR headers, so
// this checks the file convention (samples/README.md) as well as the generator.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include <OpenImageIO/imageio.h>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>
#include <gtest/gtest.h>

#include "scenegen/exr_output.h"
#include "scenegen/scenes_3d.h"
#include "yardstick/exr_files.h"

namespace taa::scenes {
namespace {

constexpr int kWidth = 96, kHeight = 54;

std::string freshDir(const std::string& name) {
  const std::string dir = std::string(TAA_TEST_TMPDIR) + "/" + name;
  std::filesystem::remove_all(dir);
  return dir;
}

// Writes frames first..last of a scene (truth barely sampled: only the AOVs matter here).
void writeScene(const std::string& name, int first, int last, const std::string& dir) {
  const auto scene = makeScene3d(name, kWidth, kHeight);
  ASSERT_TRUE(scene);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 1;
  for (int f = first; f <= last; ++f) {
    writeFrame(scene->render(f, settings), name, OutputLayout::Separate, dir);
  }
}

// A header matrix as written (row-vector M44f, 16 floats row by row), turned into the
// column-vector GLM matrix: the same 16 numbers in GLM's column-by-column memory order.
glm::dmat4 headerMatrix(const std::string& path, const char* name) {
  auto input = OIIO::ImageInput::open(path);
  EXPECT_TRUE(input) << path;
  if (!input) return glm::dmat4(1.0);
  const OIIO::ParamValue* value = input->spec().find_attribute(name);
  EXPECT_TRUE(value) << name << " missing in " << path;
  if (!value) return glm::dmat4(1.0);
  EXPECT_EQ(value->type(), OIIO::TypeMatrix44) << name;
  float rowMajor[16];
  std::memcpy(rowMajor, value->data(), sizeof rowMajor);
  glm::mat4 m;
  std::memcpy(&m[0][0], rowMajor, sizeof rowMajor);
  return glm::dmat4(m);
}

struct FrameMatrices {
  glm::dmat4 worldToCamera, worldToNDC;
};

FrameMatrices matricesOf(const std::string& dir, int frame) {
  const std::string path = framePath(dir, "depth", frame);
  return {headerMatrix(path, "worldToCamera"), headerMatrix(path, "worldToNDC")};
}

// The world point seen at raster position p with planar depth z: the camera-space point
// (x, y, z) whose NDC is p / size, solved from the two linear equations X - u W = 0 and
// Y - v W = 0 of the camera-to-NDC matrix.
glm::dvec3 unproject(const FrameMatrices& m, glm::dvec2 raster, double z) {
  const glm::dmat4 cameraToNDC = m.worldToNDC * glm::inverse(m.worldToCamera);
  const double u = raster.x / kWidth, v = raster.y / kHeight;
  auto row = [&](int r) {
    return glm::dvec4(cameraToNDC[0][r], cameraToNDC[1][r], cameraToNDC[2][r], cameraToNDC[3][r]);
  };
  const glm::dvec4 ex = row(0) - u * row(3), ey = row(1) - v * row(3);
  // ex.x x + ex.y y = -(ex.z z + ex.w), likewise ey.
  const double rx = -(ex.z * z + ex.w), ry = -(ey.z * z + ey.w);
  const double det = ex.x * ey.y - ex.y * ey.x;
  const glm::dvec4 camera((rx * ey.y - ex.y * ry) / det, (ex.x * ry - rx * ey.x) / det, z, 1.0);
  return glm::dvec3(glm::inverse(m.worldToCamera) * camera);
}

glm::dvec2 project(const FrameMatrices& m, glm::dvec3 world) {
  const glm::dvec4 h = m.worldToNDC * glm::dvec4(world, 1.0);
  return {h.x / h.w * kWidth, h.y / h.w * kHeight};
}

void expectReprojectionMatchesMotion(const std::string& scene) {
  const std::string dir = freshDir(scene);
  writeScene(scene, 4, 5, dir);
  const FrameMatrices before = matricesOf(dir, 4), now = matricesOf(dir, 5);
  const Image depth = yardstick::readExr(framePath(dir, "depth", 5)).image;
  const Image motion = yardstick::readExr(framePath(dir, "motion", 5)).image;
  int checked = 0;
  double worst = 0.0;
  for (int j = 0; j < kHeight; ++j) {
    for (int i = 0; i < kWidth; ++i) {
      const double z = depth.at(i, j)[0];
      if (std::isinf(z)) continue;
      const glm::dvec2 centre(i + 0.5, j + 0.5);
      const glm::dvec3 world = unproject(now, centre, z);
      // Depth is planar: camera-space z of the unprojected point.
      ASSERT_NEAR((now.worldToCamera * glm::dvec4(world, 1.0)).z, z, 1e-4 * z);
      const glm::dvec2 expected = project(before, world) - centre;
      const double error = std::hypot(expected.x - motion.at(i, j)[0],
                                      expected.y - motion.at(i, j)[1]);
      worst = std::max(worst, error);
      ++checked;
    }
  }
  std::printf("%s: %d pixels, worst reprojection error %.2e px\n", scene.c_str(), checked, worst);
  EXPECT_GT(checked, kWidth * kHeight / 3) << scene;
  EXPECT_LT(worst, 0.01) << scene << ": worst reprojection error in px";
}

// Scenes whose geometry is all static (only the camera moves).
TEST(SceneCamera3d, ReprojectionByDepthAndHeaderMatricesMatchesMotion) {
  for (const char* scene : {"wires", "checker_dolly"}) {
    SCOPED_TRACE(scene);
    expectReprojectionMatchesMotion(scene);
  }
}

TEST(SceneCamera3d, HeaderMatricesProjectPixelCentres) {
  // NDC (0, 0) is the display window's top-left corner, (1, 1) its bottom-right: the view
  // axis lands on the image centre.
  const std::string dir = freshDir("centre");
  writeScene("checker_dolly", 3, 3, dir);
  const FrameMatrices m = matricesOf(dir, 3);
  const glm::dmat4 toWorld = glm::inverse(m.worldToCamera);
  const glm::dvec3 ahead(toWorld * glm::dvec4(0.0, 0.0, 5.0, 1.0));
  const glm::dvec2 p = project(m, ahead);
  EXPECT_NEAR(p.x, kWidth / 2.0, 1e-3);
  EXPECT_NEAR(p.y, kHeight / 2.0, 1e-3);
  // Camera-space +y is up: a point above the axis has a smaller raster y.
  const glm::dvec3 above(toWorld * glm::dvec4(0.0, 1.0, 5.0, 1.0));
  EXPECT_LT(project(m, above).y, kHeight / 2.0);
  const glm::dvec3 right(toWorld * glm::dvec4(1.0, 0.0, 5.0, 1.0));
  EXPECT_GT(project(m, right).x, kWidth / 2.0);
}

// Sky as Cycles writes it: no hit, depth +inf, zero vectors although the camera turns; the
// exact flow (for the metrics) is not zero.
TEST(SceneCamera3d, SkyHasZeroMotionButNonZeroFlow) {
  const auto scene = makeScene3d("sky_pan", 48, 27);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 1;
  const SceneFrame frame = scene->render(6, settings);
  for (int j = 0; j < 27; ++j) {
    for (int i = 0; i < 48; ++i) {
      ASSERT_TRUE(std::isinf(frame.depth.at(i, j)[0]));
      ASSERT_EQ(frame.motion.at(i, j)[0], 0.0f);
      ASSERT_EQ(frame.motion.at(i, j)[1], 0.0f);
    }
  }
  // 0.4 degrees of yaw per frame toward +x, focal length 13.5 / tan(20 deg) = 37.1 px,
  // pitch 12 degrees: the centre's sky was about 37.1 * 0.00698 * cos(12 deg) = 0.25 px to
  // the right in the previous frame.
  EXPECT_NEAR(frame.flow.at(24, 13)[0], 0.25, 0.03);
  EXPECT_NEAR(frame.flow.at(24, 13)[1], 0.0, 0.06);
}

// The cut: a new shot number from kCutFrame on, and the first frame of the new shot sees
// nothing it saw before.
TEST(SceneCamera3d, CutStartsANewShotWithEverythingDisoccluded) {
  const auto scene = makeScene3d("cut", 48, 27);
  RenderSettings settings;
  settings.truthSamplesPerAxis = 1;
  const SceneFrame before = scene->render(kCutFrame - 1, settings);
  const SceneFrame after = scene->render(kCutFrame, settings);
  EXPECT_NE(before.shot, after.shot);
  int visibleBefore = 0;
  for (float d : after.disocclusion.pixels) visibleBefore += d == float(kVisibleBefore);
  EXPECT_EQ(visibleBefore, 0);
  int stillVisible = 0;
  for (float d : before.disocclusion.pixels) stillVisible += d == float(kVisibleBefore);
  EXPECT_GT(stillVisible, 48 * 27 * 9 / 10);
}

}  // namespace
}  // namespace taa::scenes
