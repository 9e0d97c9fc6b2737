// Camera carries (resolve/camera): a pinhole camera's carries have offsets that are pure
// translations, exactly, and an orthographic camera's do not; both carry points to where the
// other frame's camera sees them.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "resolve/camera.h"

namespace taa {
namespace {

const RasterWindow kWindow{0, 0, 64, 48};

// A camera at `position`, turned `yaw` radians about y, looking down +z (left-handed camera
// space), with `projection` (camera to NDC 0..1, y down).
FrameCamera cameraWith(const glm::dmat4& projection, glm::dvec3 position, double yaw) {
  FrameCamera c;
  const glm::dmat4 cameraToWorld =
      glm::rotate(glm::translate(glm::dmat4(1.0), position), yaw, glm::dvec3(0.0, 1.0, 0.0));
  c.worldToCamera = glm::inverse(cameraToWorld);
  c.worldToNdc = projection * c.worldToCamera;
  return c;
}

glm::dmat4 perspective() {
  glm::dmat4 p(0.0);  // x = 0.5 + 0.9 X / Z, y = 0.5 + 1.2 Y / Z
  p[0][0] = 0.9;
  p[1][1] = 1.2;
  p[2][0] = 0.5;
  p[2][1] = 0.5;
  p[2][2] = 1.0;
  p[3][2] = -0.1;
  p[2][3] = 1.0;
  return p;
}

glm::dmat4 orthographic() {
  glm::dmat4 p(1.0);  // x = 0.5 + 0.2 X, y = 0.5 + 0.25 Y
  p[0][0] = 0.2;
  p[3][0] = 0.5;
  p[1][1] = 0.25;
  p[3][1] = 0.5;
  p[2][2] = 0.001;
  return p;
}

// Where raster (x, y) of `from` at planar depth `depth` lands in `to`'s raster, by the carry.
glm::dvec2 carried(const FrameCarry& carry, glm::dvec2 raster, double depth) {
  const glm::dvec4 p(raster, 1.0, 0.0);
  const glm::dvec4 h = depth * (glm::dmat4(carry.toRaster.alongDepth) * p) +
                       glm::dmat4(carry.toRaster.offset) * glm::dvec4(raster, 1.0, 1.0);
  return glm::dvec2(h) / h.w;
}

// The same by way of world space.
glm::dvec2 throughWorld(const FrameCamera& from, const FrameCamera& to, glm::dvec2 raster,
                        double depth) {
  const glm::dmat4 ndcFromRasterM = ndcFromRaster(kWindow, NdcConvention::ZeroOneYDown);
  const glm::dmat4 rasterToWorld = glm::inverse(from.worldToNdc) * ndcFromRasterM;
  // Two points of the ray, walked to camera z = depth.
  glm::dvec4 a = rasterToWorld * glm::dvec4(raster, 0.25, 1.0);
  glm::dvec4 b = rasterToWorld * glm::dvec4(raster, 0.75, 1.0);
  a /= a.w;
  b /= b.w;
  const double za = (from.worldToCamera * a).z, zb = (from.worldToCamera * b).z;
  const glm::dvec4 world = a + (b - a) * ((depth - za) / (zb - za));
  const glm::dvec4 ndc = to.worldToNdc * world;
  const glm::dvec4 rasterTo = glm::inverse(ndcFromRasterM) * (ndc / ndc.w);
  return glm::dvec2(rasterTo);
}

TEST(CameraTest, APinholeCarrysOffsetIsATranslationExactly) {
  const FrameCamera from = cameraWith(perspective(), {0.3, -0.2, 1.0}, 0.05);
  const FrameCamera to = cameraWith(perspective(), {0.45, -0.1, 1.3}, 0.08);
  EXPECT_TRUE(isPinhole(from, kWindow, NdcConvention::ZeroOneYDown));
  const FrameCarry carry = frameCarry(from, to, kWindow, NdcConvention::ZeroOneYDown);
  for (const CarryMatrices& m : {carry.toRaster, carry.toCamera}) {
    for (int column = 0; column < 3; ++column) {
      for (int row = 0; row < 4; ++row) EXPECT_EQ(m.offset[column][row], 0.0f) << column;
    }
  }
  for (const glm::dvec2 raster : {glm::dvec2(3.5, 7.25), glm::dvec2(60.0, 40.5)}) {
    const glm::dvec2 expected = throughWorld(from, to, raster, 4.0);
    const glm::dvec2 got = carried(carry, raster, 4.0);
    EXPECT_NEAR(got.x, expected.x, 1e-3);
    EXPECT_NEAR(got.y, expected.y, 1e-3);
  }
}

TEST(CameraTest, AnOrthographicCameraIsNoPinholeAndItsCarryKeepsItsOffset) {
  const FrameCamera from = cameraWith(orthographic(), {0.3, -0.2, 1.0}, 0.05);
  const FrameCamera to = cameraWith(orthographic(), {0.45, -0.1, 1.3}, 0.08);
  EXPECT_FALSE(isPinhole(from, kWindow, NdcConvention::ZeroOneYDown));
  const FrameCarry carry = frameCarry(from, to, kWindow, NdcConvention::ZeroOneYDown);
  EXPECT_NE(carry.toRaster.offset[0][0], 0.0f);
  for (const glm::dvec2 raster : {glm::dvec2(3.5, 7.25), glm::dvec2(60.0, 40.5)}) {
    for (const double depth : {2.0, 9.0}) {
      const glm::dvec2 expected = throughWorld(from, to, raster, depth);
      const glm::dvec2 got = carried(carry, raster, depth);
      EXPECT_NEAR(got.x, expected.x, 1e-3) << depth;
      EXPECT_NEAR(got.y, expected.y, 1e-3) << depth;
    }
  }
}

}  // namespace
}  // namespace taa
