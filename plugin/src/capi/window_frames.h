// The window mode of a C ABI node (taa.h, "Window mode"): frames pushed into the window
// resolver's ring, resolved on request. Each window is planned as taatool's job plans it
// (planWindows over the frames ever pushed and the shot starts), so a result is taatool's frame
// whatever order frames came in; a frame that left the ring is remembered with the reason, so a
// window that needs it fails with a message that says what to push again.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "gl/context.h"
#include "io/channel_kinds.h"
#include "resolve/pass_plan.h"
#include "resolve/window_budget.h"
#include "resolve/window_resolver.h"
#include "taa/options.h"
#include "util/image.h"

namespace taa::capi {

// The camera matrices a frame was pushed with (16 floats, row-major, as the host gave them).
struct FrameMatrices {
  std::optional<std::array<float, 16>> worldToCamera, worldToNdc;
};

// A frame's passes as the host gave them (taa_passes): values as float, the host buffer's type,
// and the rules their kinds come from (the node's "aov" parameter).
struct FramePasses {
  std::vector<std::string> names;
  std::vector<OIIO::TypeDesc> types;  // per channel: its host buffer's, half or float
  Image values;
  std::vector<io::ChannelKindRule> rules;
};

class WindowFrames {
 public:
  // The context must be current for every call, destructor included. Throws taa::Error when
  // the options are unusable (e.g. a bracket the OCIO config lacks). `ringBudget`: the bytes
  // the rings of frames with passes may take (resolve/window_budget; tests give less).
  WindowFrames(gl::Context& context, const ResolveOptions& options,
               double ringBudget = kWindowRingBudget);
  ~WindowFrames();
  WindowFrames(const WindowFrames&) = delete;
  WindowFrames& operator=(const WindowFrames&) = delete;

  // Other options make a new, empty ring (frames are stored in the working space the options
  // choose); the frames known as pushed and the shot starts stay. Throws taa::Error, keeping
  // the old ring, when the new options are unusable.
  void setOptions(const ResolveOptions& options);

  // Puts `frame` into the ring: a frame of the same number is replaced; in a full ring the
  // frame farthest from it (the earlier of two as far) is evicted. `startsShot` marks it as
  // the first frame of a shot; a frame of another size than the ring's must be one, and then
  // empties the ring. Throws StatusError (a size conflict leaves the ring as it was).
  // With `passes`: the frame's passes, resolved with the beauty's weights (issue 21). Every
  // frame in the ring carries the same pass channels (names, kinds, types) or none: a push
  // with others first removes the frames held.
  void push(int frame, const ResolveInput& input, bool startsShot,
            const FrameMatrices& matrices, const FramePasses* passes = nullptr);
  // Takes `frame` out of the ring; it stays known as pushed. Nothing when it is not held.
  void drop(int frame);

  // Resolves `frame` from its window. Throws StatusError(TAA_ERROR_MISSING_FRAME) naming the
  // frame of the window that is not in the ring and why.
  TypedImage resolve(int frame, SampleType outputType);
  // The passes of the frame resolve() resolved last, the channels in the order pushed (empty
  // when it had none); moved out.
  Image takeResolvedPasses() { return std::move(resolvedPasses_); }
  // The names of the channels the ring's frames carry (none: empty).
  std::vector<std::string> passNames() const {
    return passPlan_ ? passPlan_->names : std::vector<std::string>();
  }
  // The matrices `frame` was pushed with; it must be in the ring.
  const FrameMatrices& matrices(int frame) const;

 private:
  // Takes `frame` out of the ring, remembering `why` (for a later window that needs it).
  void remove(int frame, const std::string& why);
  int farthestFrom(int frame) const;
  // Makes the ring's frames carry `plan`'s passes (none: nullopt), removing the frames held
  // when that changes; `pushed` names the push that asks, for their reason.
  void usePasses(std::optional<PassPlan> plan, const std::string& pushed);
  std::string missingMessage(int missing, int frame, int first, int last) const;
  // K under `options` for frames of `width` x `height` with the ring's passes: taatool's rule
  // (resolve/window_budget), so a node's frame is still taatool's.
  int radiusFor(const ResolveOptions& options, int width, int height) const;
  // A resolver of `options` with K `radius`, set up for the ring's passes.
  std::unique_ptr<WindowResolver> makeResolver(const ResolveOptions& options, int radius) const;
  // Gives the ring the K its frames' passes and size allow, emptying it when that changes;
  // `pushed` names the push that asks, for their reason.
  void fitRing(int width, int height, const std::string& pushed);

  gl::Context& context_;
  ResolveOptions options_;
  std::string optionsText_;  // every option's value: equal texts are equal options
  double ringBudget_;
  int radius_;  // K in use: options_' K, shortened where the passes' rings would not fit
  std::unique_ptr<WindowResolver> resolver_;
  std::set<int> ring_;                    // frames the resolver holds
  std::map<int, FrameMatrices> matrices_; // of the frames in the ring
  std::optional<std::pair<int, int>> size_;  // width, height of the ring's frames
  std::set<int> known_;                   // every frame number ever pushed
  std::set<int> shotStarts_;
  std::map<int, std::string> removed_;    // known frames not in the ring: why they left
  std::optional<PassPlan> passPlan_;      // the passes every frame in the ring carries
  std::map<int, Image> keptPasses_;       // per frame in the ring: its channels not summed
  Image resolvedPasses_;
};

}  // namespace taa::capi
