// libFuzzer target: one frame read through io::readFrame from an EXR file holding colour, depth
// and motion (in one file, as Cycles writes them), with the AOV conversions the first bytes
// choose (depth kind and range, motion units, direction, encoding, scale). Any file gives a
// frame in internal conventions or a taa::Error naming it; a frame read has no NaN/Inf colour
// and no NaN/Inf motion.
#include <fuzzer/FuzzedDataProvider.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_scratch_file.h"
#include "io/frame_reader.h"
#include "taa/error.h"

namespace {

taa::io::AovLayout layoutFrom(FuzzedDataProvider& input, const std::string& pattern) {
  using namespace taa::io;
  AovLayout layout;
  layout.color = {pattern, {"R", "G", "B", "A"}, ""};
  layout.depth = AovSource{"", {"Z"}, ""};
  layout.motion = AovSource{"", {"X", "Y"}, ""};
  DepthConvention& depth = layout.depthConvention;
  depth.kind = input.PickValueInArray({DepthKind::Planar, DepthKind::Radial, DepthKind::Ndc,
                                       DepthKind::ReversedZ, DepthKind::Inverse});
  depth.nearPlane = input.ConsumeFloatingPointInRange(1e-4, 10.0);
  depth.farPlane = input.ConsumeBool() ? INFINITY : input.ConsumeFloatingPointInRange(10.0, 1e6);
  depth.noHitAbove = input.ConsumeFloatingPointInRange(1.0f, 1e10f);
  if (input.ConsumeBool()) depth.horizontalFovDegrees = input.ConsumeFloatingPointInRange(1.0, 179.0);
  MotionConvention& motion = layout.motionConvention;
  motion.units = input.PickValueInArray({MotionUnits::Pixels, MotionUnits::Ndc, MotionUnits::Uv});
  motion.yUp = input.ConsumeBool();
  motion.toPrevious = input.ConsumeBool();
  motion.scale = input.ConsumeFloatingPointInRange(-100.0f, 100.0f);
  motion.encoding = input.ConsumeBool() ? MotionEncoding::Centred : MotionEncoding::Signed;
  motion.centredMax = input.ConsumeFloatingPointInRange(0.01f, 100.0f);
  return layout;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  OIIO::attribute("threads", 1);  // deterministic, and no pool to keep between inputs
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const FuzzScratchFile scratch("frame.exr");
  const std::string& path = scratch.path();
  FuzzedDataProvider input(data, size);
  const taa::io::AovLayout layout = layoutFrom(input, path);
  std::string file = input.ConsumeRemainingBytesAsString();
  // Kept an EXR file: mutations of the magic number only reach the "not an OpenEXR file"
  // refusal, which tests/io/frame_reader_test.cpp covers.
  static const char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
  file.replace(0, std::min<std::size_t>(file.size(), 4), kMagic, 4);
  scratch.write(file.data(), file.size());
  try {
    const taa::io::FrameData frame = taa::io::readFrame(layout, 1);
    const taa::Image color = frame.color.toFloat();
    for (float v : color.pixels) {
      if (!std::isfinite(v)) __builtin_trap();
    }
    for (float v : frame.motion.pixels) {
      if (!std::isfinite(v)) __builtin_trap();
    }
  } catch (const taa::Error& e) {
    if (e.context().file != path) __builtin_trap();
  }
  return 0;
}
