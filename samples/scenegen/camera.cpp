#include "scenegen/camera.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace taa::scenes {

Camera::Camera(const CameraPose& pose, int width, int height)
    : position_(pose.position), width_(width), height_(height) {
  const double yaw = glm::radians(pose.yawDegrees), pitch = glm::radians(pose.pitchDegrees);
  forward_ = glm::dvec3(std::sin(yaw) * std::cos(pitch), std::sin(pitch),
                        -std::cos(yaw) * std::cos(pitch));
  right_ = glm::dvec3(std::cos(yaw), 0.0, std::sin(yaw));
  up_ = glm::cross(right_, forward_);
  focalPixels_ = 0.5 * height / std::tan(0.5 * glm::radians(pose.verticalFovDegrees));
}

Ray Camera::ray(glm::dvec2 raster) const {
  const double x = (raster.x - 0.5 * width_) / focalPixels_;
  const double y = (0.5 * height_ - raster.y) / focalPixels_;
  return {position_, forward_ + x * right_ + y * up_};
}

glm::dvec2 Camera::project(glm::dvec3 world, double* depth) const {
  const glm::dvec3 d = world - position_;
  const double z = glm::dot(d, forward_);
  if (depth) *depth = z;
  return {0.5 * width_ + focalPixels_ * glm::dot(d, right_) / z,
          0.5 * height_ - focalPixels_ * glm::dot(d, up_) / z};
}

bool Camera::projectDirection(glm::dvec3 direction, glm::dvec2* raster) const {
  const double z = glm::dot(direction, forward_);
  if (!(z > 0.0)) return false;
  *raster = {0.5 * width_ + focalPixels_ * glm::dot(direction, right_) / z,
             0.5 * height_ - focalPixels_ * glm::dot(direction, up_) / z};
  return true;
}

glm::dmat4 Camera::worldToCamera() const {
  glm::dmat4 m(1.0);  // m[column][row]
  for (int k = 0; k < 3; ++k) {
    m[k][0] = right_[k];
    m[k][1] = up_[k];
    m[k][2] = forward_[k];
  }
  m[3][0] = -glm::dot(right_, position_);
  m[3][1] = -glm::dot(up_, position_);
  m[3][2] = -glm::dot(forward_, position_);
  return m;
}

glm::dmat4 Camera::worldToNDC() const {
  // Camera (x, y, z) -> X = x f / w + z / 2, Y = -y f / h + z / 2, Z = 1, W = z.
  glm::dmat4 p(0.0);
  p[0][0] = focalPixels_ / width_;
  p[1][1] = -focalPixels_ / height_;
  p[2][0] = 0.5;
  p[2][1] = 0.5;
  p[2][3] = 1.0;
  p[3][2] = 1.0;
  return p * worldToCamera();
}

}  // namespace taa::scenes
