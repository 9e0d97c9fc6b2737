#include "cli/option_effects.h"

#include "taa/error.h"

namespace taa::cli {

void requireOptionsTakeEffect(const std::set<std::string>& given, const std::string& preset,
                              const SequenceJob& job) {
  const io::AovLayout& layout = job.layout;
  auto check = [&](const char* option, bool effective, const std::string& needs) {
    if (given.count(option) && !effective) {
      throw Error(std::string(option) + " has no effect " + needs);
    }
  };
  check("--layer", preset == "cycles",
        "without --preset cycles: it names the Blender view layer whose passes the preset reads");
  for (const char* option : {"--motion-y", "--motion-to", "--motion-scale", "--motion-units",
                             "--motion-encoding", "--motion-max"}) {
    check(option, layout.motion.has_value(),
          "without motion vectors: give them with --motion FILES or --motion-ch X,Y (or a "
          "--preset)");
  }
  for (const char* option :
       {"--depth-kind", "--depth-near", "--depth-far", "--depth-fov", "--depth-nohit"}) {
    check(option, layout.depth.has_value(),
          "without depth: give it with --depth FILES or --depth-ch Z (or a --preset)");
  }
  check("--motion-max", layout.motionConvention.encoding == io::MotionEncoding::Centred,
        "without --motion-encoding centred");
  const io::DepthKind kind = layout.depthConvention.kind;
  for (const char* option : {"--depth-near", "--depth-far"}) {
    check(option, kind == io::DepthKind::Ndc || kind == io::DepthKind::ReversedZ,
          "without --depth-kind ndc or reversed-z");
  }
  check("--depth-fov", kind == io::DepthKind::Radial, "without --depth-kind radial");
  const bool halton = job.resolve.jitter.source == JitterSource::Halton &&
                      (job.jitterSource == JobJitterSource::Auto ||
                       job.jitterSource == JobJitterSource::Options);
  for (const char* option : {"--jitter-offset", "--jitter-period", "--jitter-scale"}) {
    check(option, halton, "when the jitter is not Halton's (--jitter halton, the default): it "
                          "shapes the Halton sequence");
  }
}

}  // namespace taa::cli
