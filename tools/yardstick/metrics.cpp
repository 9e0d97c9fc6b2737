#include "yardstick/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "taa/error.h"

namespace taa::yardstick {
namespace {

constexpr double kSsimSigma = 1.5;
constexpr int kSsimRadius = 5;
constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;
constexpr float kNeverDisoccluded = 1e9f;

void requireSameSize(const Image& a, const Image& b, const char* what) {
  if (a.width != b.width || a.height != b.height || a.channels < 3 || b.channels < 3) {
    throw Error(std::string(what) + ": images differ in size or have fewer than 3 channels");
  }
}

// Gaussian-weighted local mean of a single-channel plane, the window truncated at the border
// with its weights renormalised. Separable.
std::vector<double> localMean(const std::vector<double>& plane, int w, int h) {
  double kernel[2 * kSsimRadius + 1];
  for (int k = -kSsimRadius; k <= kSsimRadius; ++k) {
    kernel[k + kSsimRadius] = std::exp(-0.5 * k * k / (kSsimSigma * kSsimSigma));
  }
  auto pass = [&](const std::vector<double>& in, bool horizontal) {
    std::vector<double> out(in.size());
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        double sum = 0.0, weight = 0.0;
        for (int k = -kSsimRadius; k <= kSsimRadius; ++k) {
          const int sx = horizontal ? x + k : x, sy = horizontal ? y : y + k;
          if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
          sum += kernel[k + kSsimRadius] * in[std::size_t(sy) * w + sx];
          weight += kernel[k + kSsimRadius];
        }
        out[std::size_t(y) * w + x] = sum / weight;
      }
    }
    return out;
  };
  return pass(pass(plane, true), false);
}

}  // namespace

double MeanAccumulator::mean() const {
  return count > 0 ? sum / double(count) : std::numeric_limits<double>::quiet_NaN();
}

Image tonemap(const Image& linear) {
  Image out(linear.width, linear.height, 3);
  for (int y = 0; y < linear.height; ++y) {
    for (int x = 0; x < linear.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const float v = std::max(0.0f, linear.at(x, y)[c]);
        out.at(x, y)[c] = std::isinf(v) ? 1.0f : v / (1.0f + v);
      }
    }
  }
  return out;
}

double psnr(const Image& a, const Image& b) {
  requireSameSize(a, b, "psnr");
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const double d = double(a.at(x, y)[c]) - b.at(x, y)[c];
        sum += d * d;
      }
    }
  }
  const double mse = sum / (3.0 * a.width * a.height);
  return mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
}

Image ssimMap(const Image& a, const Image& b) {
  requireSameSize(a, b, "ssim");
  const int w = a.width, h = a.height;
  const std::size_t n = std::size_t(w) * h;
  Image map(w, h, 1);
  for (int c = 0; c < 3; ++c) {
    std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
    for (std::size_t k = 0; k < n; ++k) {
      x[k] = a.pixels[k * a.channels + c];
      y[k] = b.pixels[k * b.channels + c];
      xx[k] = x[k] * x[k];
      yy[k] = y[k] * y[k];
      xy[k] = x[k] * y[k];
    }
    const auto mx = localMean(x, w, h), my = localMean(y, w, h);
    const auto mxx = localMean(xx, w, h), myy = localMean(yy, w, h), mxy = localMean(xy, w, h);
    for (std::size_t k = 0; k < n; ++k) {
      const double vx = mxx[k] - mx[k] * mx[k], vy = myy[k] - my[k] * my[k];
      const double cov = mxy[k] - mx[k] * my[k];
      const double value = (2.0 * mx[k] * my[k] + kC1) * (2.0 * cov + kC2) /
                           ((mx[k] * mx[k] + my[k] * my[k] + kC1) * (vx + vy + kC2));
      map.pixels[k] += float(value / 3.0);
    }
  }
  return map;
}

double ssim(const Image& a, const Image& b) {
  const Image map = ssimMap(a, b);
  double sum = 0.0;
  for (float v : map.pixels) sum += v;
  return sum / double(map.pixels.size());
}

float bilinear(const Image& image, double x, double y, int c) {
  const double fx = std::clamp(x - 0.5, 0.0, double(image.width - 1));
  const double fy = std::clamp(y - 0.5, 0.0, double(image.height - 1));
  const int x0 = int(fx), y0 = int(fy);
  const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  const double tx = fx - x0, ty = fy - y0;
  const double top = image.at(x0, y0)[c] * (1.0 - tx) + image.at(x1, y0)[c] * tx;
  const double bottom = image.at(x0, y1)[c] * (1.0 - tx) + image.at(x1, y1)[c] * tx;
  return float(top * (1.0 - ty) + bottom * ty);
}

MeanAccumulator warpedChange(const Image& now, const Image& before, const Image& flow,
                             const Image& disocclusion) {
  requireSameSize(now, before, "flicker");
  MeanAccumulator result;
  for (int y = 0; y < now.height; ++y) {
    for (int x = 0; x < now.width; ++x) {
      if (disocclusion.at(x, y)[0] != 0.0f) continue;
      const double px = x + 0.5 + flow.at(x, y)[0], py = y + 0.5 + flow.at(x, y)[1];
      if (px < 0.0 || py < 0.0 || px >= now.width || py >= now.height) continue;
      double change = 0.0;
      for (int c = 0; c < 3; ++c) {
        change += std::fabs(now.at(x, y)[c] - bilinear(before, px, py, c));
      }
      result.add(change / 3.0);
    }
  }
  return result;
}

MeanAccumulator temporalError(const Image& now, const Image& before, const Image& truthNow,
                              const Image& truthBefore, const Image& flow,
                              const Image& disocclusion) {
  requireSameSize(now, before, "temporal error");
  requireSameSize(now, truthNow, "temporal error");
  requireSameSize(now, truthBefore, "temporal error");
  MeanAccumulator result;
  for (int y = 0; y < now.height; ++y) {
    for (int x = 0; x < now.width; ++x) {
      if (disocclusion.at(x, y)[0] != 0.0f) continue;
      const double px = x + 0.5 + flow.at(x, y)[0], py = y + 0.5 + flow.at(x, y)[1];
      if (px < 0.0 || py < 0.0 || px >= now.width || py >= now.height) continue;
      double error = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double change = double(now.at(x, y)[c]) - bilinear(before, px, py, c);
        const double truthChange = double(truthNow.at(x, y)[c]) - bilinear(truthBefore, px, py, c);
        error += std::fabs(change - truthChange);
      }
      result.add(error / 3.0);
    }
  }
  return result;
}

MeanAccumulator maskedAbsError(const Image& a, const Image& b, const Image& mask) {
  requireSameSize(a, b, "error");
  MeanAccumulator result;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      if (!mask.empty() && !(mask.at(x, y)[0] > 0.0f)) continue;
      double error = 0.0;
      for (int c = 0; c < 3; ++c) error += std::fabs(double(a.at(x, y)[c]) - b.at(x, y)[c]);
      result.add(error / 3.0);
    }
  }
  return result;
}

MeanAccumulator maskedSquaredError(const Image& a, const Image& b, const Image& mask, int c) {
  requireSameSize(a, b, "error");
  MeanAccumulator result;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      if (!(mask.at(x, y)[c] > 0.5f)) continue;
      for (int k = 0; k < 3; ++k) {
        const double d = double(a.at(x, y)[k]) - b.at(x, y)[k];
        result.add(d * d);
      }
    }
  }
  return result;
}

void DisocclusionAge::advance(const Image& disocclusion, const Image& flow, bool restart) {
  const int w = disocclusion.width, h = disocclusion.height;
  Image next(w, h, 1);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      float age = kNeverDisoccluded;
      if (disocclusion.at(x, y)[0] != 0.0f) {
        age = 0.0f;
      } else if (!restart && !age_.empty() && age_.width == w && age_.height == h) {
        // Follow the surface to where it was (nearest pixel) and carry its age on.
        const int px = int(std::floor(x + 0.5 + flow.at(x, y)[0]));
        const int py = int(std::floor(y + 0.5 + flow.at(x, y)[1]));
        if (px >= 0 && py >= 0 && px < w && py < h) age = age_.at(px, py)[0] + 1.0f;
      }
      next.at(x, y)[0] = std::min(age, kNeverDisoccluded);
    }
  }
  age_ = std::move(next);
}

Image DisocclusionAge::recent(int frames) const {
  Image mask(age_.width, age_.height, 1);
  for (std::size_t k = 0; k < mask.pixels.size(); ++k) {
    mask.pixels[k] = age_.pixels[k] < float(frames) ? 1.0f : 0.0f;
  }
  return mask;
}

}  // namespace taa::yardstick
