#include "io/aov_conversion.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <limits>

namespace taa::io {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Pixels per motion unit along x and y.
glm::dvec2 pixelsPerUnit(MotionUnits units, const RasterWindow& window) {
  const glm::dvec2 display(window.displayWidth, window.displayHeight);
  switch (units) {
    case MotionUnits::Ndc: return display * 0.5;
    case MotionUnits::Uv: return display;
    case MotionUnits::Pixels: break;
  }
  return glm::dvec2(1.0);
}

// One depth value of a non-radial kind to planar distance; +inf for the kind's "no hit".
double toPlanar(double value, const DepthConvention& c) {
  if (!std::isfinite(value)) return kInfinity;
  const double n = c.nearPlane, f = c.farPlane;
  switch (c.kind) {
    case DepthKind::Planar:
    case DepthKind::Radial:
      return value;
    case DepthKind::Inverse:
      return value > 0.0 ? 1.0 / value : kInfinity;
    case DepthKind::Ndc:
      // Perspective depth d = f / (f - n) - f n / ((f - n) z), solved for z.
      return value < 1.0 ? n * f / (f - value * (f - n)) : kInfinity;
    case DepthKind::ReversedZ:
      // d' = 1 - d: z = n f / (n + d' (f - n)); with f = inf, z = n / d'.
      if (value <= 0.0) return kInfinity;
      return std::isinf(f) ? n / value : n * f / (n + value * (f - n));
  }
  return value;
}

}  // namespace

int convertMotion(Image& motion, const MotionConvention& convention, const RasterWindow& window) {
  const glm::dvec2 units = pixelsPerUnit(convention.units, window);
  const double sign = convention.scale * (convention.toPrevious ? 1.0 : -1.0);
  const double xFactor = units.x * sign;
  const double yFactor = units.y * sign * (convention.yUp ? -1.0 : 1.0);
  const bool centred = convention.encoding == MotionEncoding::Centred;
  const double centredScale = 2.0 * convention.centredMax;
  auto decode = [&](float value) {
    return centred ? (double(value) - 0.5) * centredScale : double(value);
  };
  int zeroed = 0;
  // Checked in double: converting a double beyond float's range to float is undefined.
  auto toPixels = [&](double value) {
    if (std::abs(value) <= double(std::numeric_limits<float>::max())) return float(value);
    ++zeroed;  // NaN, Inf, or beyond float after scaling
    return 0.0f;
  };
  for (std::size_t i = 0; i + 1 < motion.pixels.size(); i += 2) {
    const float x = toPixels(decode(motion.pixels[i]) * xFactor);
    const float y = toPixels(decode(motion.pixels[i + 1]) * yFactor);
    motion.pixels[i] = x;
    motion.pixels[i + 1] = y;
  }
  return zeroed;
}

void convertDepth(Image& depth, const DepthConvention& convention) {
  for (float& value : depth.pixels) {
    // NaN and -inf carry no distance either: treat them as "no hit" too. Compared in double:
    // a double beyond float's range converted to float would be undefined.
    const double planar = toPlanar(value, convention);
    const bool hit = std::isfinite(planar) && planar < double(convention.noHitAbove) &&
                     std::abs(planar) <= double(std::numeric_limits<float>::max());
    value = hit ? float(planar) : kInfinity;
  }
}

void radialToPlanar(Image& depth, const PixelRay& ray, float noHitAbove) {
  for (int y = 0; y < depth.height; ++y) {
    for (int x = 0; x < depth.width; ++x) {
      float& value = *depth.at(x, y);
      if (!std::isfinite(value) || value >= noHitAbove) {
        value = kInfinity;
        continue;
      }
      const glm::dvec3 direction = ray(x + 0.5, y + 0.5);
      value = float(value * std::abs(direction.z) / glm::length(direction));
    }
  }
}

PixelRay cameraPixelRay(const FrameCamera& camera, const RasterWindow& window,
                        NdcConvention convention) {
  const glm::dmat4 cameraToWorld = glm::inverse(camera.worldToCamera);
  const glm::dmat4 rasterToCamera =
      glm::inverse(camera.worldToNdc * cameraToWorld) * ndcFromRaster(window, convention);
  // Two points of the ray (any two NDC depths), as resolve/camera.cpp's cameraMotion does.
  return [rasterToCamera](double x, double y) {
    const glm::dvec4 a = rasterToCamera * glm::dvec4(x, y, 0.25, 1.0);
    const glm::dvec4 b = rasterToCamera * glm::dvec4(x, y, 0.75, 1.0);
    return glm::dvec3(b) / b.w - glm::dvec3(a) / a.w;
  };
}

PixelRay pinholePixelRay(double horizontalFovDegrees, const RasterWindow& window) {
  const double pi = 3.14159265358979323846;
  const double focalPixels =
      0.5 * window.displayWidth / std::tan(0.5 * horizontalFovDegrees * pi / 180.0);
  const double centreX = 0.5 * window.displayWidth - window.dataX;
  const double centreY = 0.5 * window.displayHeight - window.dataY;
  return [=](double x, double y) {
    return glm::dvec3((x - centreX) / focalPixels, (y - centreY) / focalPixels, 1.0);
  };
}

}  // namespace taa::io
