// The real renders' flow and disocclusion (yardstick/cycles_reference) on hand-made Cycles
// vectors: a square moving right over a still backdrop, and an empty sky under a turning
// camera.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include <gtest/gtest.h>

#include "yardstick/contact_sheet.h"
#include "yardstick/cycles_reference.h"

namespace taa::yardstick {
namespace {

constexpr int kW = 16, kH = 8;

// A camera at the origin looking down -z (OpenGL), turned by `yaw` radians, as the sidecar
// gives it: camera space +z forward, worldToNdc = projection * view.
FrameCamera cameraTurnedBy(double yaw) {
  const glm::dmat4 view = glm::rotate(glm::dmat4(1.0), yaw, glm::dvec3(0, 1, 0));
  const glm::dmat4 projection = glm::perspective(glm::radians(40.0), double(kW) / kH, 0.1, 100.0);
  FrameCamera camera;
  camera.worldToCamera = glm::scale(glm::dmat4(1.0), glm::dvec3(1, 1, -1)) * view;
  camera.worldToNdc = projection * view;
  return camera;
}

// A 4x4 square at x = left..left+3 (depth 2) moving 3 px right a frame over a backdrop
// (depth 10), static camera. Cycles' vectors: XY = previous - current, ZW = current - next,
// y up (here y motion is zero).
CyclesCentres squareFrame(int left, const FrameCamera& camera) {
  CyclesCentres frame{Image(kW, kH, 1), Image(kW, kH, 4), camera};
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const bool square = x >= left && x < left + 4 && y >= 2 && y < 6;
      frame.depth.at(x, y)[0] = square ? 2.0f : 10.0f;
      frame.vectors.at(x, y)[0] = square ? -3.0f : 0.0f;  // came from 3 px to the left
      frame.vectors.at(x, y)[2] = square ? -3.0f : 0.0f;  // goes 3 px to the right
    }
  }
  return frame;
}

TEST(CyclesReference, FlowsFollowTheSquareAndTheRevealedStripIsDisoccluded) {
  const FrameCamera still = cameraTurnedBy(0.0);
  const CyclesCentres before = squareFrame(4, still), now = squareFrame(7, still);
  const Image back = flowToPrevious(now, still);
  EXPECT_FLOAT_EQ(back.at(8, 3)[0], -3.0f);
  EXPECT_FLOAT_EQ(back.at(2, 3)[0], 0.0f);
  const Image forward = flowToNext(before, still);
  EXPECT_FLOAT_EQ(forward.at(5, 3)[0], 3.0f);
  const Image mask = disocclusionFromFlows(back, forward);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      // The square covered x = 4..7 before; x = 4..6 of the backdrop is seen again now.
      const bool revealed = x >= 4 && x < 7 && y >= 2 && y < 6;
      EXPECT_EQ(mask.at(x, y)[0], revealed ? 1.0f : 0.0f) << x << "," << y;
    }
  }
}

TEST(CyclesReference, EmptySkyTakesTheCamerasTurn) {
  CyclesCentres sky{Image(kW, kH, 1), Image(kW, kH, 4), cameraTurnedBy(0.02)};
  for (float& d : sky.depth.pixels) d = 1e10f;  // nothing hit: Cycles' vectors stay zero
  const Image back = flowToPrevious(sky, cameraTurnedBy(0.0));
  const Image forward = flowToNext(sky, cameraTurnedBy(0.04));
  // A turn of 0.02 rad moves the sky the same way at every pixel near the centre, and the
  // next turn by as much again: the two flows are opposite.
  EXPECT_GT(std::fabs(back.at(8, 4)[0]), 0.1f);
  EXPECT_NEAR(back.at(8, 4)[0], -forward.at(8, 4)[0], 0.05f);
  EXPECT_NEAR(back.at(8, 4)[1], 0.0f, 1e-3f);
}

TEST(ContactSheet, WorstWindowFindsTheError) {
  Image a(64, 32, 3), b(64, 32, 3);
  for (int y = 20; y < 28; ++y) {
    for (int x = 40; x < 52; ++x) a.at(x, y)[1] = 0.5f;
  }
  const Crop crop = worstWindow(a, b, 16, 12);
  EXPECT_EQ(crop.width, 16);
  EXPECT_EQ(crop.height, 12);
  EXPECT_LE(crop.x, 40);
  EXPECT_GE(crop.x + crop.width, 52);
  EXPECT_LE(crop.y, 20);
  EXPECT_GE(crop.y + crop.height, 28);
}

}  // namespace
}  // namespace taa::yardstick
