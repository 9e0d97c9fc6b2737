#include "resolve/projection_jitter.h"

#include <glm/glm.hpp>

namespace taa {

glm::dvec2 principalPointOffset(const FrameCamera& camera, const RasterWindow& window,
                                NdcConvention convention) {
  // A point on the view axis (camera space +z forward): for a pinhole camera every depth lands
  // on the same pixel, for an orthographic one too.
  const glm::dvec4 world = glm::inverse(camera.worldToCamera) * glm::dvec4(0.0, 0.0, 1.0, 1.0);
  const glm::dvec4 ndc = camera.worldToNdc * world;
  const glm::dvec4 raster =
      glm::inverse(ndcFromRaster(window, convention)) * glm::dvec4(glm::dvec2(ndc) / ndc.w, 0, 1);
  const glm::dvec2 centre(0.5 * window.displayWidth - window.dataX,
                          0.5 * window.displayHeight - window.dataY);
  return glm::dvec2(raster) - centre;
}

std::optional<FrameCamera> withoutJitterInProjection(const FrameCamera& camera, glm::vec2 jitter,
                                                     const RasterWindow& window,
                                                     NdcConvention convention) {
  const glm::dvec2 offset = principalPointOffset(camera, window, convention);
  const glm::dvec2 expected(jitter);
  if (glm::length(expected) < kProjectionJitterTolerance ||
      glm::length(offset - expected) > kProjectionJitterTolerance) {
    return std::nullopt;
  }
  // NDC moved by the offset's NDC size: x' = x - d w after the projection, so x'/w = x/w - d.
  const glm::dmat4 fromRaster = ndcFromRaster(window, convention);
  const glm::dvec2 delta(fromRaster[0][0] * offset.x, fromRaster[1][1] * offset.y);
  glm::dmat4 shift(1.0);
  shift[3][0] = -delta.x;
  shift[3][1] = -delta.y;
  FrameCamera corrected = camera;
  corrected.worldToNdc = shift * camera.worldToNdc;
  return corrected;
}

}  // namespace taa
