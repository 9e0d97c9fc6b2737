// Depth and motion conversions on values worked out by hand.
#include "io/aov_conversion.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace taa::io {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

Image oneChannel(std::vector<float> values) {
  Image image(int(values.size()), 1, 1);
  image.pixels.assign(values.begin(), values.end());
  return image;
}

Image motionOf(float x, float y) {
  Image image(1, 1, 2);
  image.pixels = {x, y};
  return image;
}

DepthConvention depthKind(DepthKind kind, double nearPlane = 0.1, double farPlane = 1e4) {
  DepthConvention c;
  c.kind = kind;
  c.nearPlane = nearPlane;
  c.farPlane = farPlane;
  return c;
}

TEST(ConvertDepth, PlanarKeepsValuesAndMapsSentinelsToInfinity) {
  Image depth = oneChannel({5.0f, 1e10f, std::nanf(""), -kInf});
  convertDepth(depth, depthKind(DepthKind::Planar));
  EXPECT_EQ(depth.pixels[0], 5.0f);
  for (int i = 1; i < 4; ++i) EXPECT_TRUE(std::isinf(depth.pixels[i]) && depth.pixels[i] > 0);
}

TEST(ConvertDepth, InverseDepth) {
  Image depth = oneChannel({0.2f, 0.0f, -1.0f});
  convertDepth(depth, depthKind(DepthKind::Inverse));
  EXPECT_FLOAT_EQ(depth.pixels[0], 5.0f);
  EXPECT_EQ(depth.pixels[1], kInf);
  EXPECT_EQ(depth.pixels[2], kInf);
}

TEST(ConvertDepth, NdcDepthWithNearAndFar) {
  // n = 1, f = 100: d(z) = f/(f-n) - f n/((f-n) z); d(5) = 80/99, d(100) = 1.
  Image depth = oneChannel({80.0f / 99.0f, 0.0f, 1.0f});
  convertDepth(depth, depthKind(DepthKind::Ndc, 1.0, 100.0));
  EXPECT_NEAR(depth.pixels[0], 5.0f, 1e-4f);
  EXPECT_NEAR(depth.pixels[1], 1.0f, 1e-6f);  // the near plane
  EXPECT_EQ(depth.pixels[2], kInf);           // the far plane / cleared depth buffer
}

TEST(ConvertDepth, ReversedZFiniteAndInfiniteFar) {
  // n = 1, f = 100: d' = 1 - d(5) = 19/99.
  Image finite = oneChannel({19.0f / 99.0f, 1.0f, 0.0f});
  convertDepth(finite, depthKind(DepthKind::ReversedZ, 1.0, 100.0));
  EXPECT_NEAR(finite.pixels[0], 5.0f, 1e-4f);
  EXPECT_NEAR(finite.pixels[1], 1.0f, 1e-6f);
  EXPECT_EQ(finite.pixels[2], kInf);
  // Infinite far plane: d' = n / z.
  Image infinite = oneChannel({0.02f, 0.0f});
  convertDepth(infinite, depthKind(DepthKind::ReversedZ, 0.1, kInf));
  EXPECT_NEAR(infinite.pixels[0], 5.0f, 1e-5f);
  EXPECT_EQ(infinite.pixels[1], kInf);
}

TEST(ConvertDepth, NoHitThresholdAppliesAfterConversion) {
  DepthConvention c = depthKind(DepthKind::Inverse);
  c.noHitAbove = 100.0f;
  Image depth = oneChannel({0.001f, 0.5f});  // 1000 and 2
  convertDepth(depth, c);
  EXPECT_EQ(depth.pixels[0], kInf);
  EXPECT_FLOAT_EQ(depth.pixels[1], 2.0f);
}

TEST(RadialToPlanar, PinholeRaysShortenOffCentreDistances) {
  // 8x4 display, 90 degrees: focal length 4 px, centre (4, 2). Pixel (7, 0)'s ray through
  // (7.5, 0.5) is (3.5/4, -1.5/4, 1): planar = radial / |ray|.
  const RasterWindow window{0, 0, 8, 4};
  const double length = std::sqrt(1.0 + (3.5 / 4) * (3.5 / 4) + (1.5 / 4) * (1.5 / 4));
  Image depth(8, 4, 1);
  for (float& v : depth.pixels) v = 1.0f;
  *depth.at(7, 0) = float(5.0 * length);
  *depth.at(3, 1) = 1e10f;
  radialToPlanar(depth, pinholePixelRay(90.0, window), 1e9f);
  EXPECT_NEAR(*depth.at(7, 0), 5.0f, 1e-5f);
  EXPECT_EQ(*depth.at(3, 1), kInf);
  // Pixel (3, 1) is no hit; (4, 2) is off the centre by half a pixel each way.
  const double centreLength = std::sqrt(1.0 + 2 * (0.5 / 4) * (0.5 / 4));
  EXPECT_NEAR(*depth.at(4, 2), 1.0 / centreLength, 1e-6);
}

TEST(RadialToPlanar, CameraMatricesGiveThePinholeRays) {
  // worldToNDC of a pinhole with focal f px on an 8x4 display, NDC (0, 0) top left, y down:
  // X = (f/W) x + 0.5 z, Y = -(f/H) y + 0.5 z, W = z (column-vector, m[column][row]).
  const double f = 4.0, w = 8.0, h = 4.0;
  FrameCamera camera;
  camera.worldToNdc = glm::dmat4(0.0);
  camera.worldToNdc[0][0] = f / w;
  camera.worldToNdc[2][0] = 0.5;
  camera.worldToNdc[1][1] = -f / h;
  camera.worldToNdc[2][1] = 0.5;
  camera.worldToNdc[3][2] = 1.0;
  camera.worldToNdc[2][3] = 1.0;
  const RasterWindow window{-2, -1, 8, 4};  // overscan: data window starts outside the display
  const PixelRay fromCamera = cameraPixelRay(camera, window, NdcConvention::ZeroOneYDown);
  const PixelRay fromFov = pinholePixelRay(90.0, window);
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0.5, 0.5}, {11.5, 5.5}}) {
    // Camera space is y up, the pinhole's rays y down: only the rays' angles to the view
    // axis matter for depth, so compare the lengths of the rays scaled to z = 1.
    const glm::dvec3 a = fromCamera(x, y), b = fromFov(x, y);
    EXPECT_NEAR(glm::length(a / a.z), glm::length(b / b.z), 1e-9) << x << "," << y;
    EXPECT_NEAR(std::abs(a.x / a.z), std::abs(b.x / b.z), 1e-9) << x << "," << y;
  }
}

TEST(ConvertMotion, UnitsReferToTheDisplayWindow) {
  // Display 8x4 inside a larger overscan data window: NDC and UV units are display-relative.
  const RasterWindow window{-4, -2, 8, 4};
  MotionConvention ndc;
  ndc.units = MotionUnits::Ndc;
  Image m = motionOf(0.75f, -1.0f);
  convertMotion(m, ndc, window);
  EXPECT_FLOAT_EQ(m.pixels[0], 3.0f);
  EXPECT_FLOAT_EQ(m.pixels[1], -2.0f);

  MotionConvention uv;
  uv.units = MotionUnits::Uv;
  m = motionOf(0.375f, -0.5f);
  convertMotion(m, uv, window);
  EXPECT_FLOAT_EQ(m.pixels[0], 3.0f);
  EXPECT_FLOAT_EQ(m.pixels[1], -2.0f);
}

TEST(ConvertMotion, CentredEncodingWithMaximum) {
  // 0.5 = no motion; 1 = +max; 0 = -max (pixels).
  MotionConvention c;
  c.encoding = MotionEncoding::Centred;
  c.centredMax = 16.0f;
  Image m = motionOf(0.59375f, 0.4375f);  // 0.5 + 3/32, 0.5 - 2/32
  convertMotion(m, c, {0, 0, 8, 4});
  EXPECT_FLOAT_EQ(m.pixels[0], 3.0f);
  EXPECT_FLOAT_EQ(m.pixels[1], -2.0f);
  m = motionOf(0.5f, 0.5f);
  convertMotion(m, c, {0, 0, 8, 4});
  EXPECT_EQ(m.pixels[0], 0.0f);
  EXPECT_EQ(m.pixels[1], 0.0f);
}

TEST(ConvertMotion, DirectionYAndScale) {
  MotionConvention c;
  c.toPrevious = false;
  c.yUp = true;
  c.scale = 0.5f;
  Image m = motionOf(6.0f, 4.0f);
  convertMotion(m, c, {0, 0, 8, 4});
  EXPECT_FLOAT_EQ(m.pixels[0], -3.0f);
  EXPECT_FLOAT_EQ(m.pixels[1], 2.0f);
  m = motionOf(std::nanf(""), kInf);
  convertMotion(m, c, {0, 0, 8, 4});
  EXPECT_EQ(m.pixels[0], 0.0f);
  EXPECT_EQ(m.pixels[1], 0.0f);
}

}  // namespace
}  // namespace taa::io
