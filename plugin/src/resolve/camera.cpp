#include "resolve/camera.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/geometric.hpp>
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

namespace {

// The camera-space point `rasterToCamera` sees at raster (x, y) at planar depth `depth`.
glm::dvec3 cameraPointAt(const glm::dmat4& rasterToCamera, glm::dvec2 position, double depth) {
  const glm::dvec4 a = rasterToCamera * glm::dvec4(position, 0.25, 1.0);
  const glm::dvec4 b = rasterToCamera * glm::dvec4(position, 0.75, 1.0);
  const glm::dvec3 nearPoint = glm::dvec3(a) / a.w, farPoint = glm::dvec3(b) / b.w;
  const glm::dvec3 along = farPoint - nearPoint;
  return nearPoint + along * ((depth - nearPoint.z) / along.z);
}

// P(x, y, d) = d A (x, y, 1) + G (x, y, 1), the camera-space point raster (x, y) sees at
// planar depth d, at three raster positions: A's and G's columns there, from the points at
// depths 1 and 2 (exact, P being affine in x, y and in d for projective cameras).
struct RasterRays {
  glm::dvec3 along[3], offset[3];
};
RasterRays rasterRays(const glm::dmat4& rasterToCamera) {
  RasterRays rays;
  const glm::dvec2 corners[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 one = cameraPointAt(rasterToCamera, corners[i], 1.0);
    const glm::dvec3 two = cameraPointAt(rasterToCamera, corners[i], 2.0);
    rays.along[i] = two - one;
    rays.offset[i] = one - rays.along[i];
  }
  return rays;
}

// (raster x, raster y, ndc z, 1) to `camera`'s homogeneous camera space.
glm::dmat4 rasterToCameraOf(const FrameCamera& camera, const glm::dmat4& ndcFromRasterM) {
  return glm::inverse(camera.worldToNdc * glm::inverse(camera.worldToCamera)) * ndcFromRasterM;
}

// The rays start at the origin: G's columns are rounding noise against A's.
bool raysMeetAtOrigin(const RasterRays& rays) {
  for (int i = 0; i < 3; ++i) {
    if (glm::length(rays.offset[i]) > 1e-9 * glm::length(rays.along[i])) return false;
  }
  return true;
}

}  // namespace

bool isPinhole(const FrameCamera& camera, const RasterWindow& window, NdcConvention convention) {
  return raysMeetAtOrigin(
      rasterRays(rasterToCameraOf(camera, ndcFromRaster(window, convention))));
}

FrameCarry frameCarry(const FrameCamera& from, const FrameCamera& to, const RasterWindow& window,
                      NdcConvention convention) {
  const glm::dmat4 ndcFromRasterM = ndcFromRaster(window, convention);
  const glm::dmat4 cameraToWorld = glm::inverse(from.worldToCamera);
  RasterRays rays = rasterRays(rasterToCameraOf(from, ndcFromRasterM));
  if (raysMeetAtOrigin(rays)) {
    for (glm::dvec3& offset : rays.offset) offset = glm::dvec3(0.0);
  }
  const glm::dvec3* along = rays.along;
  const glm::dvec3* offset = rays.offset;
  glm::dmat4 a(0.0), g(0.0);  // upper-left 3x3 used; g[3][3] = 1 carries the homogeneous 1
  // Columns: d(x), d(y), constant.
  a[0] = glm::dvec4(along[1] - along[0], 0.0);
  a[1] = glm::dvec4(along[2] - along[0], 0.0);
  a[2] = glm::dvec4(along[0], 0.0);
  g[0] = glm::dvec4(offset[1] - offset[0], 0.0);
  g[1] = glm::dvec4(offset[2] - offset[0], 0.0);
  g[2] = glm::dvec4(offset[0], 0.0);
  g[3] = glm::dvec4(0.0, 0.0, 0.0, 1.0);
  const glm::dmat4 toRaster = glm::inverse(ndcFromRasterM) * to.worldToNdc * cameraToWorld;
  const glm::dmat4 toCamera = to.worldToCamera * cameraToWorld;
  FrameCarry carry;
  carry.toRaster = {glm::mat4(toRaster * a), glm::mat4(toRaster * g)};
  carry.toCamera = {glm::mat4(toCamera * a), glm::mat4(toCamera * g)};
  return carry;
}

glm::dvec2 cameraMotion(const FrameCamera& current, const FrameCamera& previous,
                        const RasterWindow& window, NdcConvention convention, glm::dvec2 position,
                        double depth) {
  const glm::dmat4 ndcFromRasterM = ndcFromRaster(window, convention);
  const glm::dmat4 cameraToWorld = glm::inverse(current.worldToCamera);
  const glm::dmat4 rasterToCamera = rasterToCameraOf(current, ndcFromRasterM);
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
