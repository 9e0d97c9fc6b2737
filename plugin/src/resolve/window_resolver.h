// The window resolve (DESIGN.md section 4): frame t rebuilt from the raw jittered samples of
// frames t-K..t+K, each carried to t along its own motion (glsl/window_gather.frag). Frames
// enter a ring of 2K+1 on the GPU once, as they are read, and leave it when no window needs
// them; every output frame depends on its window's frames and the options alone, so any
// chunking of a shot resolves the same frames bit for bit.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "gl/context.h"
#include "resolve/camera.h"
#include "resolve/pass_plan.h"
#include "resolve/resolver.h"
#include "taa/options.h"
#include "util/image.h"

namespace taa {

class PassBandStream;

// Per-pixel diagnostics of the last resolved frame (setDebugOutput): weight gathered (frame
// t's own samples and its reconstruction included), fraction of candidate samples rejected
// (hidden in t, or colour outside t's box), number of candidates.
inline constexpr int kWindowDebugChannels = 3;

class WindowResolver {
 public:
  // The context must be current on the calling thread for every call, destructor included.
  WindowResolver(gl::Context& context, const ResolveOptions& options);
  ~WindowResolver();
  WindowResolver(const WindowResolver&) = delete;
  WindowResolver& operator=(const WindowResolver&) = delete;

  // The most frames the ring holds: 2K+1.
  int capacity() const;

  // Puts `frame` into the ring: colour (converted into the bracket's working space), depth and
  // motion are uploaded once. All frames must have one size. Throws taa::Error on malformed
  // input, a full ring or a GL failure.
  void addFrame(int frame, const ResolveInput& input);
  // Takes a frame out of the ring (a no-op for a frame it does not hold).
  void dropFrame(int frame);
  bool hasFrame(int frame) const;
  // Drops every frame (a new sequence, or a new size).
  void clear();

  // Resolves `frame` from the ring's frames first..last (each added, consecutive, one shot,
  // `frame` among them) and returns RGBA of the frames' size in `outputType`. The result
  // depends on those frames and the options alone: which samples are static is decided within
  // the window (each frame against the one before it there, the first against the one after).
  TypedImage resolve(int frame, int first, int last, SampleType outputType);

  // As resolve, for a writer that takes the passes as they come (resolve/pass_band_stream):
  // `colourReady` gets the colour once the beauty is drawn, before the passes' draws, and the
  // passes' sums go into `bands` band by band instead of being kept for takePassSums. The
  // colour and every pass are the same as resolve's. Only where canStreamPasses().
  void resolveStreaming(int frame, int first, int last, SampleType outputType,
                        const std::function<void(TypedImage)>& colourReady, PassBandStream& bands);
  // Whether the passes set are drawn in one draw band by band (image stores, every group and at
  // most one Cryptomatte set in it), which streaming needs.
  bool canStreamPasses() const;

  // Pass values summed with the beauty's weights (resolve/pass_plan): `halfGroups[g]` says
  // whether group g's ring may hold halves (every channel in it was half); and the number of
  // Cryptomatte sets weighed the same way. Call before the first frame or after clear(); every
  // addFrame then brings that many groups and sets.
  void setPasses(const std::vector<bool>& halfGroups, int cryptomatteSets);
  // The last resolved frame's pass sums (RGBA per group, half where the group's ring is) and
  // Cryptomatte ranks, given away: the writer finishes the passes from them band by band.
  PassSums takePassSums();

  // Keep each frame's diagnostics for lastDebug() (one more read-back per frame).
  void setDebugOutput(bool enabled);
  // kWindowDebugChannels channels of the last resolved frame.
  const Image& lastDebug() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// K for a window asked as `asked` over frames of `width` x `height`: as long as `context`
// (current) can make the rings' texture arrays (resolve/window_budget:
// windowRadiusWithinLayers). Every face shortens the window by it before the first frame enters
// a ring.
int windowRadiusTheGlHolds(gl::Context& context, int asked, int width, int height);

}  // namespace taa
