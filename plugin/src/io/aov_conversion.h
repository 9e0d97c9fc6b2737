// Conversions of depth and motion values from a renderer's conventions (io/aov_layout.h) to
// taa's internal ones (DESIGN.md section 3). Pure functions on images, used by io::readFrame.
#pragma once

#include <glm/vec3.hpp>

#include <functional>

#include "io/aov_layout.h"
#include "resolve/camera.h"
#include "util/image.h"

namespace taa::io {

// Motion (2 channels) in place: per MotionConvention; NaN/Inf results become 0. Returns how many
// values were set to 0 so (the sequence job reports them). `window` gives the display size that
// Ndc and Uv units refer to.
int convertMotion(Image& motion, const MotionConvention& convention, const RasterWindow& window);

// Depth (1 channel) in place, for every kind except Radial (which needs the pixel rays: see
// radialToPlanar): to planar distance, +inf where nothing was hit.
void convertDepth(Image& depth, const DepthConvention& convention);

// The direction, in a +z-forward camera space, of the ray through raster position (x, y) of the
// data window (pixel centres at +0.5); any length.
using PixelRay = std::function<glm::dvec3(double x, double y)>;

// Radial distances (1 channel) in place to planar ones: planar = radial * cos(angle of the
// pixel's ray to the view axis). Non-finite values and values at or above noHitAbove become
// +inf first.
void radialToPlanar(Image& depth, const PixelRay& ray, float noHitAbove);

// Pixel rays from the frame's camera matrices.
PixelRay cameraPixelRay(const FrameCamera& camera, const RasterWindow& window,
                        NdcConvention convention);

// Pixel rays of a centred pinhole camera whose horizontal field of view spans the display
// window (square pixels).
PixelRay pinholePixelRay(double horizontalFovDegrees, const RasterWindow& window);

}  // namespace taa::io
