// Options that would change nothing are errors: "--layer RL" without --preset cycles was
// silently ignored, and a user who gave it believes it was used (issue 24).
#pragma once

#include <set>
#include <string>

#include "resolve/sequence_job.h"

namespace taa::cli {

// Throws taa::Error naming the option and what it needs when an option in `given` (as typed:
// "--layer") has no effect on `job` as parsed with `preset` ("" for none): --layer without
// --preset cycles; a motion convention without a motion AOV, a depth convention without a
// depth AOV; --motion-max without centred encoding; --depth-near/far without ndc or
// reversed-z depth, --depth-fov without radial; --jitter-offset, --jitter-period and
// --jitter-scale when the jitter is not Halton's.
void requireOptionsTakeEffect(const std::set<std::string>& given, const std::string& preset,
                              const SequenceJob& job);

}  // namespace taa::cli
