#include "yardstick/sequence_score.h"

#include <cmath>
#include <limits>

#include "taa/error.h"

namespace taa::yardstick {
namespace {

// Pooled motion-compensated change of a sequence over the measured frames.
MeanAccumulator flickerOf(const Reference& reference, const std::vector<Image>& sequence) {
  MeanAccumulator total;
  for (std::size_t k = 1; k < reference.frames.size(); ++k) {
    if (!reference.measured[k]) continue;
    const ReferenceFrame& frame = reference.frames[k];
    total.add(warpedChange(sequence[k], sequence[k - 1], frame.flow, frame.disocclusion));
  }
  return total;
}

// Pooled temporal error of a sequence against the truth over the measured frames.
MeanAccumulator temporalErrorOf(const Reference& reference, const std::vector<Image>& sequence) {
  MeanAccumulator total;
  for (std::size_t k = 1; k < reference.frames.size(); ++k) {
    if (!reference.measured[k]) continue;
    const ReferenceFrame& frame = reference.frames[k];
    total.add(temporalError(sequence[k], sequence[k - 1], frame.truth,
                            reference.frames[k - 1].truth, frame.flow, frame.disocclusion));
  }
  return total;
}

MeanAccumulator ghostErrorOf(const Reference& reference, const std::vector<Image>& sequence) {
  MeanAccumulator total;
  for (std::size_t k = 0; k < reference.frames.size(); ++k) {
    if (!reference.measured[k]) continue;
    total.add(maskedAbsError(sequence[k], reference.frames[k].truth, reference.ghostRegion[k]));
  }
  return total;
}

// PSNR over the measured frames' pixels where channel `c` of the regions is set.
double regionPsnr(const Reference& reference, const std::vector<Image>& sequence, int c) {
  MeanAccumulator squared;
  for (std::size_t k = 0; k < reference.frames.size(); ++k) {
    const ReferenceFrame& frame = reference.frames[k];
    if (!reference.measured[k] || frame.regions.channels <= c) continue;
    squared.add(maskedSquaredError(sequence[k], frame.truth, frame.regions, c));
  }
  if (squared.count == 0) return std::numeric_limits<double>::quiet_NaN();
  return squared.mean() > 0.0 ? -10.0 * std::log10(squared.mean())
                              : std::numeric_limits<double>::infinity();
}

double ratio(const MeanAccumulator& a, const MeanAccumulator& b) {
  if (a.count == 0 || b.count == 0 || b.mean() == 0.0) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return a.mean() / b.mean();
}

}  // namespace

Reference prepareReference(std::vector<ReferenceFrame> frames, const ScoreOptions& options) {
  Reference reference;
  reference.frames = std::move(frames);
  DisocclusionAge age;
  int shotStart = 0;
  std::vector<Image> truths, raws;
  for (std::size_t k = 0; k < reference.frames.size(); ++k) {
    const ReferenceFrame& frame = reference.frames[k];
    const bool newShot = k == 0 || frame.shot != reference.frames[k - 1].shot ||
                         frame.frame != reference.frames[k - 1].frame + 1;
    if (newShot) shotStart = int(k);
    const bool measured = int(k) - shotStart >= options.warmup && int(k) > shotStart;
    reference.measured.push_back(measured);
    reference.measuredFrames += measured ? 1 : 0;
    age.advance(frame.disocclusion, frame.flow, newShot);
    reference.ghostRegion.push_back(age.recent(options.ghostFrames));
    truths.push_back(frame.truth);
    raws.push_back(frame.raw);
  }
  reference.truthFlicker = flickerOf(reference, truths);
  reference.rawGhostError = ghostErrorOf(reference, raws);
  return reference;
}

Scores score(const Reference& reference, const std::vector<Image>& output) {
  if (output.size() != reference.frames.size()) {
    throw Error("score: " + std::to_string(output.size()) + " output frames for " +
                std::to_string(reference.frames.size()) + " reference frames");
  }
  MeanAccumulator psnrMean, ssimMean;
  for (std::size_t k = 0; k < output.size(); ++k) {
    if (!reference.measured[k]) continue;
    psnrMean.add(psnr(output[k], reference.frames[k].truth));
    ssimMean.add(ssim(output[k], reference.frames[k].truth));
  }
  Scores scores;
  scores.psnr = psnrMean.mean();
  scores.ssim = ssimMean.mean();
  scores.temporal = temporalErrorOf(reference, output).mean();
  scores.flicker = ratio(flickerOf(reference, output), reference.truthFlicker);
  scores.ghosting = ratio(ghostErrorOf(reference, output), reference.rawGhostError);
  scores.movingPsnr = regionPsnr(reference, output, 0);
  scores.shadowPsnr = regionPsnr(reference, output, 1);
  return scores;
}

}  // namespace taa::yardstick
