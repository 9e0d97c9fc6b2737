// Image metrics of the quality yardstick (DESIGN.md section 7), on Reinhard-tonemapped RGB.
// Images are taa::Image (rows top first); only the first three channels are compared.
#pragma once

#include "util/image.h"

namespace taa::yardstick {

// x / (1 + x) per RGB channel, negatives clamped to 0: 3 channels out, values in [0, 1).
Image tonemap(const Image& linear);

// PSNR in dB with peak 1.0 over every pixel and RGB channel; +inf for identical images.
double psnr(const Image& a, const Image& b);

// SSIM (Wang et al. 2004) per pixel: Gaussian window sigma 1.5 truncated at radius 5 (11 x 11)
// and at the image border (weights renormalised over the taps inside), C1 = 0.01^2,
// C2 = 0.03^2 for dynamic range 1; computed per R, G, B channel and averaged. One channel out.
Image ssimMap(const Image& a, const Image& b);

// Mean of ssimMap over the image.
double ssim(const Image& a, const Image& b);

// Bilinear sample of channel c at continuous raster position p (pixel centres at +0.5), the
// position clamped to the outermost pixel centres.
float bilinear(const Image& image, double x, double y, int c);

// A sum and a count, so that means can be pooled over frames.
struct MeanAccumulator {
  double sum = 0.0;
  long long count = 0;
  void add(double value) {
    sum += value;
    ++count;
  }
  void add(const MeanAccumulator& other) {
    sum += other.sum;
    count += other.count;
  }
  double mean() const;  // NaN when empty
};

// Motion-compensated change from `before` to `now`: per pixel whose disocclusion value is 0
// (the surface was visible there in the previous frame, so also on screen), the RGB mean of
// |now(p) - before(p + flow(p))|, `before` sampled bilinearly.
MeanAccumulator warpedChange(const Image& now, const Image& before, const Image& flow,
                             const Image& disocclusion);

// Temporal error: how far the output's motion-compensated frame-to-frame change is from the
// truth's. Per pixel whose surface was visible in both frames (disocclusion 0, previous
// position on screen), the RGB mean of |(now(p) - before(p + flow)) - (truthNow(p) -
// truthBefore(p + flow))|, the previous frames sampled bilinearly. Zero for the truth itself
// whatever the scene does, so it stays meaningful on static shots where the truth's own change
// (the flicker ratio's divisor) is near zero.
MeanAccumulator temporalError(const Image& now, const Image& before, const Image& truthNow,
                              const Image& truthBefore, const Image& flow,
                              const Image& disocclusion);

// RGB mean of |a - b| over the pixels where mask > 0 (every pixel when mask is empty).
MeanAccumulator maskedAbsError(const Image& a, const Image& b, const Image& mask);

// (a - b)^2 of every RGB value of the pixels where channel `c` of `mask` is > 0.5, pooled.
MeanAccumulator maskedSquaredError(const Image& a, const Image& b, const Image& mask, int c);

// Tracks how many frames ago each pixel's surface was disoccluded, following it along the
// flow, so that "disoccluded within the last k frames" can be asked of the current frame.
class DisocclusionAge {
 public:
  // Advances to a frame; `restart`: first frame of a shot (all history forgotten).
  void advance(const Image& disocclusion, const Image& flow, bool restart);
  // 1 where the surface became visible within the last `frames` frames (this one included),
  // else 0. One channel.
  Image recent(int frames) const;

 private:
  Image age_;  // frames since disocclusion; large = never seen disoccluded
};

}  // namespace taa::yardstick
