// Each renderer preset read from a hand-made file whose values are known: the file holds the
// preset's channel names with values written in that renderer's convention (worked out by hand
// below, not by the code under test), and readFrame must give taa's internal values.
#include "io/renderer_presets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>

#include "io/frame_reader.h"
#include "taa/error.h"
#include "test_files.h"

namespace taa::io {
namespace {

using taa::test::makeSpec;
using taa::test::scratchFolder;
using taa::test::writeImage;

// Internal truth for every pixel of the 8x4 test image: motion (3, -2) px (previous = pos +
// mv, y down), planar depth 5; the last pixel hit nothing.
constexpr float kMotionX = 3.0f, kMotionY = -2.0f, kDepth = 5.0f;
constexpr int kWidth = 8, kHeight = 4;

struct PresetCase {
  std::string preset;
  float motionU, motionV;  // the file's motion values for the truth above
  float depth;             // the file's depth value for the truth above
  float noHitDepth;        // what the renderer writes where nothing was hit
};

// Hand-worked file values per preset (see README "Renderer presets"):
//   to previous, y up: (3, 2); to previous, y down: (3, -2); forward, y up: (-3, -2);
//   unreal: forward, y down, UV units, 0.5-centred with max 1: 0.5 - 3 / (2 * 8) = 0.3125,
//   0.5 - (-2) / (2 * 4) = 0.75.
const std::vector<PresetCase>& cases() {
  static const std::vector<PresetCase> all = {
      {"cycles", 3.0f, 2.0f, 5.0f, 1e10f},
      {"nuke", 3.0f, 2.0f, 0.2f, 0.0f},
      {"arnold", -3.0f, -2.0f, 5.0f, 1e30f},
      {"renderman", 3.0f, -2.0f, 5.0f, 1e30f},
      {"vray", -3.0f, -2.0f, 5.0f, 1e30f},
      {"karma", -3.0f, -2.0f, 5.0f, 1e30f},
      {"redshift", -3.0f, -2.0f, 5.0f, 1e30f},
      {"unreal", 0.3125f, 0.75f, 5.0f, 1e30f},
  };
  return all;
}

// Writes `channels` -> per-pixel value into one float EXR.
void writeFile(const std::string& path, const std::vector<std::string>& names,
               const std::function<float(int pixel, const std::string& name)>& value) {
  std::vector<float> pixels;
  for (int p = 0; p < kWidth * kHeight; ++p) {
    for (const std::string& name : names) pixels.push_back(value(p, name));
  }
  writeImage(path, makeSpec(kWidth, kHeight, names), pixels);
}

// Writes the preset's files for frame 1 and returns the layout reading them.
AovLayout writePresetFiles(const PresetCase& c, const std::string& folder) {
  AovLayout layout = presetLayout(c.preset, folder + "/beauty.####.exr");
  const int lastPixel = kWidth * kHeight - 1;
  auto colorValue = [&](int p, const std::string& name) {
    const auto& color = layout.color.channels;
    for (std::size_t i = 0; i < color.size(); ++i) {
      if (color[i] == name) return 0.25f * float(i) + 0.01f * float(p);
    }
    return -1.0f;
  };
  auto aovValue = [&](int p, const std::string& name) {
    if (name == layout.depth->channels[0]) return p == lastPixel ? c.noHitDepth : c.depth;
    if (name == layout.motion->channels[0]) return c.motionU;
    if (name == layout.motion->channels[1]) return c.motionV;
    return colorValue(p, name);
  };
  if (c.preset == "unreal") {
    // Movie Render Queue writes one file per pass.
    layout.depth->pattern = folder + "/depth.####.exr";
    layout.motion->pattern = folder + "/motion.####.exr";
    writeFile(folder + "/beauty.0001.exr", layout.color.channels, colorValue);
    // The pass files share channel names (R, G), so each gets its own values.
    writeFile(folder + "/depth.0001.exr", layout.depth->channels,
              [&](int p, const std::string&) { return p == lastPixel ? c.noHitDepth : c.depth; });
    writeFile(folder + "/motion.0001.exr", layout.motion->channels,
              [&](int, const std::string& name) { return name == "R" ? c.motionU : c.motionV; });
    return layout;
  }
  std::vector<std::string> names = layout.color.channels;
  names.push_back(layout.depth->channels[0]);
  names.insert(names.end(), layout.motion->channels.begin(), layout.motion->channels.end());
  names.push_back("unrelated.X");
  writeFile(folder + "/beauty.0001.exr", names, aovValue);
  return layout;
}

TEST(RendererPresets, EveryPresetConvertsKnownValuesToInternalConventions) {
  ASSERT_EQ(rendererPresets().size(), cases().size());
  for (const PresetCase& c : cases()) {
    SCOPED_TRACE(c.preset);
    const std::string folder = scratchFolder() + "/" + c.preset;
    std::filesystem::create_directories(folder);
    const AovLayout layout = writePresetFiles(c, folder);
    const FrameData data = readFrame(layout, 1);
    ASSERT_EQ(data.motion.channels, 2);
    for (int p = 0; p < kWidth * kHeight; ++p) {
      EXPECT_NEAR(data.motion.pixels[2 * p], kMotionX, 1e-5f) << p;
      EXPECT_NEAR(data.motion.pixels[2 * p + 1], kMotionY, 1e-5f) << p;
    }
    for (int p = 0; p + 1 < kWidth * kHeight; ++p) {
      EXPECT_NEAR(data.depth.pixels[p], kDepth, 1e-5f) << p;
    }
    EXPECT_TRUE(std::isinf(data.depth.pixels.back())) << "no-hit value " << c.noHitDepth;
    // Color channels come in the preset's R, G, B, A order.
    EXPECT_FLOAT_EQ(data.color.toFloat().pixels[0], 0.0f);
    EXPECT_FLOAT_EQ(data.color.toFloat().pixels[1], 0.25f);
    EXPECT_FLOAT_EQ(data.color.toFloat().pixels[2], 0.5f);
    EXPECT_FLOAT_EQ(data.color.toFloat().pixels[3], 0.75f);
  }
}

TEST(RendererPresets, ChannelNamesPerRenderer) {
  using Names = std::vector<std::string>;
  EXPECT_EQ(presetLayout("nuke", "x").motion->channels, Names({"backward.u", "backward.v"}));
  EXPECT_EQ(presetLayout("nuke", "x").depth->channels, Names({"depth.Z"}));
  EXPECT_EQ(presetLayout("karma", "x").color.channels, Names({"C.R", "C.G", "C.B", "C.A"}));
  EXPECT_EQ(presetLayout("renderman", "x").motion->channels[0], "motionBack.r");
  EXPECT_EQ(presetLayout("vray", "x").motion->channels[0], "VRayVelocity.R");
  EXPECT_EQ(presetLayout("cycles", "x", "Hero").depth->channels, Names({"Hero.Depth.Z"}));
  EXPECT_EQ(presetLayout("cycles", "x", "").depth->channels, Names({"Depth.Z"}));
  EXPECT_EQ(presetLayout("cycles", "x").color.pattern, "x");
}

TEST(RendererPresets, UnknownNameListsTheKnownOnes) {
  try {
    presetLayout("mantra", "x");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("mantra"), std::string::npos) << what;
    for (const RendererPreset& p : rendererPresets()) {
      EXPECT_NE(what.find(p.name), std::string::npos) << what;
    }
  }
}

TEST(RendererPresets, MissingPresetChannelsAreListedWithTheAvailableOnes) {
  const std::string folder = scratchFolder();
  // A Nuke-style file without the backward vectors (only forward ones).
  writeFile(folder + "/beauty.0001.exr", {"R", "G", "B", "A", "depth.Z", "forward.u", "forward.v"},
            [](int, const std::string&) { return 1.0f; });
  try {
    readFrame(presetLayout("nuke", folder + "/beauty.####.exr"), 1);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("backward.u, backward.v"), std::string::npos) << what;
    EXPECT_NE(what.find("forward.u"), std::string::npos) << what;  // listed as available
    EXPECT_NE(what.find("beauty.0001.exr"), std::string::npos) << what;
    EXPECT_NE(what.find("frame 1"), std::string::npos) << what;
    EXPECT_EQ(e.context().channel, "backward.u, backward.v");
  }
}

}  // namespace
}  // namespace taa::io
