// How long a window the rings can hold: a window resolve with passes keeps every pass of its
// ring's 2K+1 frames on the GPU; the rule counts one frame more, the one on its way in. At 1080p
// with every Cycles pass and K 16 that would be 11 GB. Every face (taatool, taa-farm, the C ABI, Python, OpenFX)
// shortens such a window by the same rule, so a node's frame is still taatool's.
#pragma once

#include "resolve/pass_plan.h"

namespace taa {

// The most the rings of one run may take, colour and passes of every view (bytes). The colour
// ring alone takes 20 bytes a pixel a frame (1.4 GB at 1080p and K 16); a Cycles render's every
// pass adds 136 (3.2 GB at 1080p and K 4, which keeps issue 21's peak of 4 GiB;
// docs/PERFORMANCE.md).
constexpr double kWindowRingBudget = 3.25 * 1024 * 1024 * 1024;

// Bytes one frame's pixel takes in a view's rings: 20 for colour, depth and motion, 8 (half) or
// 16 (float) per pass group, 16 per Cryptomatte set. `passes`: none when null.
double ringBytesPerPixel(const PassPlan* passes);

// The rings of window K over frames of `frameBytes` (every view's ringBytesPerPixel times the
// pixels): 2K+2 frames.
double windowRingBytes(int radius, double frameBytes);

// K for a window asked as `asked` with frames of `frameBytes`: `asked` where its rings fit
// `budget`, else the longest that fits, never shorter than `nearRadius` (the frames the tile
// test always counts). Only runs with passes are shortened (`withPasses`): colour alone at K 16
// is 1.4 GB at 1080p and the window is what the user asked for.
int windowRadiusWithinBudget(int asked, int nearRadius, double frameBytes, bool withPasses,
                             double budget = kWindowRingBudget);

// K for a window asked as `asked` whose rings (2K+2 layers of a texture array each) may have at
// most `largestLayers` layers (gl::largestTextureArrayLayers): the driver's largest texture,
// about 1.6 GB on llvmpipe, holds 48 frames of the ring at 1080p (K 23) and 12 at 4K (K 5).
// Every run is shortened by it, colour alone too: a longer ring cannot be made at all.
int windowRadiusWithinLayers(int asked, int largestLayers);

}  // namespace taa
