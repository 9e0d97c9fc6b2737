// A pinhole camera for the 3D scenes, and the matrices a renderer writes for it into EXR
// headers (DESIGN.md section 3; the exact convention is in samples/README.md).
//
// Camera space is left-handed as in OpenEXR and RenderMan: x right, y up, z forward (the view
// direction), so planar depth is camera-space z. Raster follows taa: pixel (i, j) covers
// [i, i+1) x [j, j+1), y down, pixel centres at +0.5.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace taa::scenes {

// Where a camera is and where it looks. Yaw turns left-right about the world's +y (up) axis,
// 0 looks down world -z, positive turns toward +x; pitch tilts up (positive) or down.
struct CameraPose {
  glm::dvec3 position{0.0};
  double yawDegrees = 0.0;
  double pitchDegrees = 0.0;
  double verticalFovDegrees = 40.0;
};

struct Ray {
  glm::dvec3 origin;
  glm::dvec3 direction;  // scaled so that its camera-space z is 1: the hit's t is planar depth
};

// A camera pose placed on a raster of width x height pixels (square pixels).
class Camera {
 public:
  Camera(const CameraPose& pose, int width, int height);

  // The ray through a continuous raster position.
  Ray ray(glm::dvec2 raster) const;
  // The raster position of a world point, and its planar depth (<= 0: behind the camera, and
  // the position is meaningless).
  glm::dvec2 project(glm::dvec3 world, double* depth = nullptr) const;
  // The raster position of a direction at infinity (sky); false when it points behind.
  bool projectDirection(glm::dvec3 direction, glm::dvec2* raster) const;
  glm::dvec3 position() const { return position_; }
  // Unit view direction in world space.
  glm::dvec3 forward() const { return forward_; }

  // Column-vector matrices (GLM): camera = worldToCamera * world. worldToNDC maps a world point
  // to homogeneous (X, Y, Z, W) with EXR NDC = (X / W, Y / W): (0, 0) the top-left corner of
  // the display window, (1, 1) the bottom-right, y down. W is the planar depth, Z is 1 (so
  // Z / W = 1 / depth and the matrix is invertible). No jitter is included.
  glm::dmat4 worldToCamera() const;
  glm::dmat4 worldToNDC() const;

 private:
  glm::dvec3 position_, right_, up_, forward_;
  double focalPixels_;  // distance of the image plane in pixels
  double width_, height_;
};

}  // namespace taa::scenes
