// The scene interface of the quality yardstick (DESIGN.md section 7): a scene renders, per
// frame, a jittered one-sample-per-pixel colour, exact depth and motion, and a supersampled
// box-filtered truth, all in taa's internal conventions (DESIGN.md section 3).
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "resolve/jitter.h"
#include "util/image.h"

namespace taa::scenes {

struct RenderSettings {
  JitterOptions jitter;          // the jitter of each frame is frameJitter(frame, jitter)
  int truthSamplesPerAxis = 16;  // truth = mean of N x N stratified samples per pixel, N >= 1
  int threads = 0;               // worker threads; 0 = one per hardware thread
  std::uint32_t truthSeed = 0;   // picks the truth's jittered sample pattern (3D scenes); any
                                 // value gives a converged truth, different ones other samples
};

// Camera matrices of a frame as a renderer writes them (samples/README.md): column-vector GLM
// matrices here, written to EXR headers as row-vector M44f worldToCamera / worldToNDC.
struct CameraMatrices {
  glm::mat4 worldToCamera{1.0f};
  glm::mat4 worldToNDC{1.0f};
};

// Values of SceneFrame::disocclusion.
enum Disocclusion : int {
  kVisibleBefore = 0,    // the surface was visible at pos + flow in the previous frame
  kOccludedBefore = 1,   // it was on screen there but hidden behind something else
  kOutsideBefore = 2,    // pos + flow lies outside the previous frame (or behind its camera)
};

// One rendered frame. Images are width x height, rows top first.
struct SceneFrame {
  int frame = 0;
  glm::vec2 jitter{0.0f};  // offset of the colour sample from the pixel centre, px, y down
  Image color;             // RGBA: one point sample at (i + 0.5 + jx, j + 0.5 + jy); A = coverage
  Image depth;             // 1 channel at the pixel centre: planar distance, +inf where nothing
  Image motion;            // 2 channels at the pixel centre: previous - current, px, y down
  Image nextMotion;        // 2 channels at the pixel centre: next - current, px, y down
  Image truth;             // RGBA: box-filtered pixel average, unjittered
  // For the yardstick's metrics (empty when a scene does not provide them):
  Image flow;              // 2 channels: the exact motion of what the pixel centre sees,
                           // previous - current, px, y down, including the sky at infinity
                           // (where `motion` is zero, as Cycles writes it)
  Image disocclusion;      // 1 channel at the pixel centre: a Disocclusion value
  bool hasCamera = false;  // whether `camera` holds the frame's matrices
  CameraMatrices camera;
  int shot = 0;            // shot number: changes at a hard cut
};

// A frame with every image allocated at width x height (zeros) and the frame's jitter set;
// truth is left empty for scenes that compute it separately.
inline SceneFrame blankFrame(int frame, int width, int height, const RenderSettings& settings,
                             bool withTruth) {
  SceneFrame out;
  out.frame = frame;
  out.jitter = frameJitter(frame, settings.jitter);
  out.color = Image(width, height, 4);
  out.depth = Image(width, height, 1);
  out.motion = Image(width, height, 2);
  out.nextMotion = Image(width, height, 2);
  if (withTruth) out.truth = Image(width, height, 4);
  out.flow = Image(width, height, 2);
  out.disocclusion = Image(width, height, 1);
  return out;
}

// A scene of fixed raster size. Rendering a frame is independent of any other frame, so frames
// can be rendered in any order (farm chunks, tests picking single frames).
class Scene {
 public:
  Scene(std::string name, int width, int height)
      : name_(std::move(name)), width_(width), height_(height) {}
  virtual ~Scene() = default;

  const std::string& name() const { return name_; }
  int width() const { return width_; }
  int height() const { return height_; }

  virtual SceneFrame render(int frame, const RenderSettings& settings) const = 0;

 private:
  std::string name_;
  int width_;
  int height_;
};

}  // namespace taa::scenes
