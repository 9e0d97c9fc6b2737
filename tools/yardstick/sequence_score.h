// Scores of one image sequence against a scene's reference (truth, raw input, flow,
// disocclusion): the means the yardstick's table shows.
#pragma once

#include <limits>
#include <vector>

#include "util/image.h"
#include "yardstick/metrics.h"

namespace taa::yardstick {

// One frame of a scene's reference. `truth` and `raw` are tonemapped (metrics.h: tonemap).
struct ReferenceFrame {
  int frame = 0;
  int shot = 0;  // frames of a new shot restart the warm-up and the history of the metrics
  Image truth, raw;
  Image flow;          // exact motion, previous - current, px, y down
  Image disocclusion;  // 0 where the surface was visible at pos + flow in the previous frame
  // Optional, 2 channels: 1 where the scene's moving object is (channel 0) and where its
  // shadow falls (channel 1): the parts a window resolve may smear or see through.
  Image regions;
};

struct ScoreOptions {
  int warmup = 4;       // frames at the start of each shot left out of every mean
  int ghostFrames = 4;  // "recently disoccluded": within this many frames, this one included
};

// The reference prepared once per scene: which frames count, ghost regions, and the truth's
// and raw input's own figures that the ratios divide by.
struct Reference {
  std::vector<ReferenceFrame> frames;  // consecutive frames, in order
  std::vector<bool> measured;          // frame index -> counts in the means
  std::vector<Image> ghostRegion;      // 1 where disoccluded within ghostFrames
  MeanAccumulator truthFlicker;        // motion-compensated change of the truth
  MeanAccumulator rawGhostError;       // raw input's error in the ghost regions
  int measuredFrames = 0;
};

Reference prepareReference(std::vector<ReferenceFrame> frames, const ScoreOptions& options);

struct Scores {
  double psnr = 0.0;      // dB, mean over measured frames
  double ssim = 0.0;      // mean over measured frames
  double temporal = 0.0;  // pooled temporal error (metrics.h: temporalError; 0 = the truth's)
  double flicker = 0.0;   // pooled motion-compensated change / the truth's (1 = as stable)
  double ghosting = 0.0;  // pooled error in recently disoccluded pixels / the raw input's;
                          // NaN when no measured frame has any
  // PSNR (dB) pooled over the measured frames' pixels inside the moving object and inside its
  // shadow (ReferenceFrame::regions); NaN where the scene has none.
  double movingPsnr = std::numeric_limits<double>::quiet_NaN();
  double shadowPsnr = std::numeric_limits<double>::quiet_NaN();
};

// `output`: the tonemapped sequence, one image per reference frame.
Scores score(const Reference& reference, const std::vector<Image>& output);

}  // namespace taa::yardstick
