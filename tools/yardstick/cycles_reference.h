// Exact motion and disocclusion for the yardstick's Blender Cycles renders. They come from the
// "aux" frames: an unjittered 1-spp render, whose only sample sits at the pixel centre (Cycles'
// sample 0), so its depth and vectors are the surface's at the centre, with nothing averaged.
#pragma once

#include "resolve/camera.h"
#include "util/image.h"

namespace taa::yardstick {

// One aux frame and its camera.
struct CyclesCentres {
  Image depth;    // 1 channel: planar depth, 1e10 where nothing is hit (Cycles)
  Image vectors;  // 4 channels: Cycles' Vector pass, pixels, y up: XY = previous - current,
                  // ZW = current - next
  FrameCamera camera;  // from the camera sidecar (NDC [-1, 1], y up)
};

// Motion to the previous frame (pixels, y down, previous - current: the yardstick's flow).
// Cycles writes zero vectors where nothing is hit even when the camera turns; there the
// camera's motion of a point at infinity is used instead.
Image flowToPrevious(const CyclesCentres& frame, const FrameCamera& previousCamera);

// Motion to the next frame (pixels, y down, next - current), the sky filled alike.
Image flowToNext(const CyclesCentres& frame, const FrameCamera& nextCamera);

// 1 where the surface at a pixel was not visible in the previous frame: none of the four pixel
// centres around its previous position (pixel + flowToPrevious) carries the surface back to
// the pixel along its own motion to the next frame (within 0.5 px plus 5% of the motion), or
// the previous position is off screen. A forward-backward consistency test: it needs no
// depth, so it holds for moving objects as well as for the static world.
Image disocclusionFromFlows(const Image& flowToPrevious, const Image& previousFlowToNext);

}  // namespace taa::yardstick
