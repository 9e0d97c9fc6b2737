// A projection that carries the frame's jitter. The resolve takes the jitter from its own
// source and wants the projection without it; a jittered projection (what Blender's
// calc_matrix_camera returns on a frame rendered with a lens-shift jitter, or a renderer's
// jittered matrix written as is) counts the jitter twice and costs quality without a word
// (0.4 dB on a Cycles shot, issue 24). It is recognised by its principal point: the view axis
// meets the image off the display window's centre by exactly the frame's jitter.
#pragma once

#include <glm/vec2.hpp>

#include <optional>

#include "resolve/camera.h"

namespace taa {

// Where the camera's view axis meets the image, in pixels from the display window's centre,
// x right, y down (0 for a centred projection; a lens shift or a jitter moves it).
glm::dvec2 principalPointOffset(const FrameCamera& camera, const RasterWindow& window,
                                NdcConvention convention);

// Within this many pixels the principal point "equals" the jitter: float32 matrices of a 4K
// frame hold it to about 1e-4 px; a genuine lens shift equal to a Halton offset to 1e-3 px is
// not a coincidence to expect.
inline constexpr double kProjectionJitterTolerance = 1e-3;

// `camera` with the jitter taken out of its projection when its principal point equals
// `jitter` (and the jitter is not 0): the image shifted back by the jitter, a translation of
// NDC after the projection. Nothing when the projection does not carry it.
std::optional<FrameCamera> withoutJitterInProjection(const FrameCamera& camera, glm::vec2 jitter,
                                                     const RasterWindow& window,
                                                     NdcConvention convention);

}  // namespace taa
