#include "yardstick/cycles_reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "taa/error.h"

namespace taa::yardstick {
namespace {

constexpr float kNoHitDepth = 1e9f;  // Cycles writes 1e10 where nothing is hit

// The XY pair (toPrevious) or the ZW pair negated (to the next frame), in y-down pixels.
Image flowOf(const CyclesCentres& frame, const FrameCamera& otherCamera, bool toPrevious) {
  const int w = frame.vectors.width, h = frame.vectors.height;
  if (frame.vectors.channels != 4 || frame.depth.width != w || frame.depth.height != h) {
    throw Error("Cycles reference: vectors need 4 channels and the depth's size");
  }
  const RasterWindow window{0, 0, w, h};
  Image flow(w, h, 2);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float* v = frame.vectors.at(x, y);
      float* out = flow.at(x, y);
      if (frame.depth.at(x, y)[0] >= kNoHitDepth) {
        const glm::dvec2 m = cameraMotion(frame.camera, otherCamera, window,
                                          NdcConvention::MinusOneOneYUp, {x + 0.5, y + 0.5},
                                          std::numeric_limits<double>::infinity());
        out[0] = float(m.x);
        out[1] = float(m.y);
      } else if (toPrevious) {
        out[0] = v[0];   // previous - current, y up -> y down
        out[1] = -v[1];
      } else {
        out[0] = -v[2];  // current - next -> next - current, y up -> y down
        out[1] = v[3];
      }
    }
  }
  return flow;
}

}  // namespace

Image flowToPrevious(const CyclesCentres& frame, const FrameCamera& previousCamera) {
  return flowOf(frame, previousCamera, true);
}

Image flowToNext(const CyclesCentres& frame, const FrameCamera& nextCamera) {
  return flowOf(frame, nextCamera, false);
}

Image disocclusionFromFlows(const Image& flowToPrevious, const Image& previousFlowToNext) {
  const int w = flowToPrevious.width, h = flowToPrevious.height;
  if (previousFlowToNext.width != w || previousFlowToNext.height != h) {
    throw Error("Cycles reference: flows of different sizes");
  }
  Image mask(w, h, 1);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const glm::dvec2 back(flowToPrevious.at(x, y)[0], flowToPrevious.at(x, y)[1]);
      const glm::dvec2 previous = glm::dvec2(x + 0.5, y + 0.5) + back;
      bool visible = false;
      if (previous.x >= 0.0 && previous.y >= 0.0 && previous.x < w && previous.y < h) {
        const double tolerance = 0.5 + 0.05 * glm::length(back);
        const int x0 = int(std::floor(previous.x - 0.5)), y0 = int(std::floor(previous.y - 0.5));
        for (int dy = 0; dy <= 1 && !visible; ++dy) {
          for (int dx = 0; dx <= 1 && !visible; ++dx) {
            const int px = std::clamp(x0 + dx, 0, w - 1), py = std::clamp(y0 + dy, 0, h - 1);
            // Only centres with a bilinear weight: not the far one when the position sits
            // on a centre's row or column.
            if (std::fabs(px + 0.5 - previous.x) >= 1.0 ||
                std::fabs(py + 0.5 - previous.y) >= 1.0) {
              continue;
            }
            const glm::dvec2 forward(previousFlowToNext.at(px, py)[0],
                                     previousFlowToNext.at(px, py)[1]);
            // Where that pixel's surface lands now, against where this pixel is.
            const glm::dvec2 landing = glm::dvec2(px + 0.5, py + 0.5) + forward;
            const glm::dvec2 expected = glm::dvec2(x + 0.5, y + 0.5) +
                                        (glm::dvec2(px + 0.5, py + 0.5) - previous);
            visible = glm::length(landing - expected) <= tolerance;
          }
        }
      }
      mask.at(x, y)[0] = visible ? 0.0f : 1.0f;
    }
  }
  return mask;
}

}  // namespace taa::yardstick
