#include "resolve/camera.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/vec4.hpp>

#include <cmath>

namespace taa {

glm::dmat4 ndcFromRaster(const RasterWindow& window, NdcConvention convention) {
  const double w = window.displayWidth, h = window.displayHeight;
  glm::dmat4 m(1.0);  // column-major: m[column][row]
  if (convention == NdcConvention::ZeroOneYDown) {
    m[0][0] = 1.0 / w;
    m[1][1] = 1.0 / h;
    m[3][0] = window.dataX / w;
    m[3][1] = window.dataY / h;
  } else {
    m[0][0] = 2.0 / w;
    m[1][1] = -2.0 / h;
    m[3][0] = 2.0 * window.dataX / w - 1.0;
    m[3][1] = 1.0 - 2.0 * window.dataY / h;
  }
  return m;
}

ReprojectionMatrices reprojectionMatrices(const FrameCamera& current, const FrameCamera& previous,
                                          const RasterWindow& window, NdcConvention convention) {
  const glm::dmat4 ndcFromRasterM = ndcFromRaster(window, convention);
  const glm::dmat4 cameraToWorld = glm::inverse(current.worldToCamera);
  const glm::dmat4 cameraToNdc = current.worldToNdc * cameraToWorld;
  ReprojectionMatrices m;
  m.rasterToCamera = glm::mat4(glm::inverse(cameraToNdc) * ndcFromRasterM);
  m.cameraToPreviousRaster =
      glm::mat4(glm::inverse(ndcFromRasterM) * previous.worldToNdc * cameraToWorld);
  m.cameraToPreviousCamera = glm::mat4(previous.worldToCamera * cameraToWorld);
  return m;
}

glm::dvec2 cameraMotion(const FrameCamera& current, const FrameCamera& previous,
                        const RasterWindow& window, NdcConvention convention, glm::dvec2 position,
                        double depth) {
  const glm::dmat4 ndcFromRasterM = ndcFromRaster(window, convention);
  const glm::dmat4 cameraToWorld = glm::inverse(current.worldToCamera);
  const glm::dmat4 rasterToCamera =
      glm::inverse(current.worldToNdc * cameraToWorld) * ndcFromRasterM;
  const glm::dvec4 a = rasterToCamera * glm::dvec4(position, 0.25, 1.0);
  const glm::dvec4 b = rasterToCamera * glm::dvec4(position, 0.75, 1.0);
  const glm::dvec3 nearPoint = glm::dvec3(a) / a.w, farPoint = glm::dvec3(b) / b.w;
  const glm::dvec3 along = farPoint - nearPoint;
  // At infinite depth (no hit) only the ray's direction matters: a point at infinity, w = 0.
  const glm::dvec4 point =
      std::isinf(depth) ? glm::dvec4(along * (along.z < 0.0 ? -1.0 : 1.0), 0.0)
                        : glm::dvec4(nearPoint + along * ((depth - nearPoint.z) / along.z), 1.0);
  const glm::dvec4 previousRaster =
      glm::inverse(ndcFromRasterM) * previous.worldToNdc * cameraToWorld * point;
  return glm::dvec2(previousRaster) / previousRaster.w - position;
}

}  // namespace taa
