// How long a window the rings hold when the frames carry passes (resolve/window_budget).
#include "resolve/window_budget.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace taa {
namespace {

// A Cycles render's every pass beside its beauty (Blender 3.4.1 with every pass on, the
// render of scripts/bench-passes.sh): light and colour passes as half, the rest as float.
PassPlan everyCyclesPass() {
  std::vector<std::string> names;
  std::vector<OIIO::TypeDesc> formats;
  const auto add = [&](const std::string& pass, const std::string& channels, OIIO::TypeDesc type) {
    for (char c : channels) {
      names.push_back("ViewLayer." + pass + "." + std::string(1, c));
      formats.push_back(type);
    }
  };
  for (const char* pass : {"DiffDir", "DiffInd", "DiffCol", "GlossDir", "GlossInd", "GlossCol",
                           "TransDir", "TransInd", "TransCol", "Emit", "Env", "AO", "Shadow"}) {
    add(pass, "RGB", OIIO::TypeDesc::HALF);
  }
  add("Depth", "Z", OIIO::TypeDesc::FLOAT);
  add("Mist", "Z", OIIO::TypeDesc::FLOAT);
  add("IndexOB", "X", OIIO::TypeDesc::FLOAT);
  add("Vector", "XYZW", OIIO::TypeDesc::FLOAT);
  add("Normal", "XYZ", OIIO::TypeDesc::FLOAT);
  add("Position", "XYZ", OIIO::TypeDesc::FLOAT);
  add("UV", "UVA", OIIO::TypeDesc::FLOAT);
  for (const char* set : {"CryptoObject00", "CryptoObject01", "CryptoObject02"}) {
    add(set, "rgba", OIIO::TypeDesc::FLOAT);
  }
  return planPasses(names, formats, {});
}

TEST(WindowBudget, AFramesRingBytesAreColourAndEachGroupAndSet) {
  EXPECT_EQ(ringBytesPerPixel(nullptr), 20.0);
  PassPlan plan;
  plan.halfGroups = {true, true, false};
  plan.cryptomatte.resize(2);
  EXPECT_EQ(ringBytesPerPixel(&plan), 20.0 + 2 * 8.0 + 16.0 + 2 * 16.0);
  EXPECT_EQ(windowRingBytes(4, 100.0), 1000.0);  // 2K+2 frames
}

TEST(WindowBudget, EveryPassAt1080pShortensTheDefaultWindowToK4) {
  const PassPlan plan = everyCyclesPass();
  EXPECT_EQ(ringBytesPerPixel(&plan), 156.0);  // taatool -v: 10998 MB for 34 frames at K 16
  const double frameBytes = ringBytesPerPixel(&plan) * 1920.0 * 1080.0;
  EXPECT_EQ(windowRadiusWithinBudget(16, 2, frameBytes, true), 4);
  EXPECT_LE(windowRingBytes(4, frameBytes), kWindowRingBudget);
  EXPECT_GT(windowRingBytes(5, frameBytes), kWindowRingBudget);
}

TEST(WindowBudget, ColourAloneAndWindowsThatFitAreLeftAsAsked) {
  const double colour = ringBytesPerPixel(nullptr) * 3840.0 * 2160.0;
  EXPECT_EQ(windowRadiusWithinBudget(16, 2, colour, false), 16);  // 4K colour: asked is asked
  EXPECT_EQ(windowRadiusWithinBudget(3, 2, 100.0, true), 3);
}

TEST(WindowBudget, TheWindowIsNeverShortenedBelowItsNearFrames) {
  EXPECT_EQ(windowRadiusWithinBudget(16, 2, 1e12, true), 2);
  EXPECT_EQ(windowRadiusWithinBudget(16, 0, 1e12, true), 0);
  EXPECT_EQ(windowRadiusWithinBudget(1, 2, 1e12, true), 1);  // asked below near: as asked
}

// The ring needs 2K+2 layers in one texture array; a driver holding fewer shortens every run.
TEST(WindowBudget, TheWindowFitsTheLargestTextureTheGlMakes) {
  EXPECT_EQ(windowRadiusWithinLayers(16, 48), 16);
  EXPECT_EQ(windowRadiusWithinLayers(24, 48), 23);  // llvmpipe at 1080p
  EXPECT_EQ(windowRadiusWithinLayers(16, 34), 16);
  EXPECT_EQ(windowRadiusWithinLayers(16, 33), 15);
  EXPECT_EQ(windowRadiusWithinLayers(16, 12), 5);
  EXPECT_EQ(windowRadiusWithinLayers(4, 1), 0);  // not even K 0: its error comes on creation
}

}  // namespace
}  // namespace taa
